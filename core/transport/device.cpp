// SPDX-License-Identifier: GPL-3.0-or-later
#include "transport/device.hpp"

#include <charconv>
#include <cmath>

#include "transport/hid_uart.hpp"
#include "transport/lpt_port.hpp"
#include "transport/serial_port.hpp"
#include "transport/tty_port.hpp"
#include "common/try.hpp"

namespace tactus::transport {

std::optional<double> option_number(const std::string& s) {
    double v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    // NaN and infinity are no setting of a line or a simulator.
    if (ec != std::errc{} || p != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

Result<DeviceSpec> parse_device(std::string_view device) {
    const std::string where = "device \"" + std::string(device) + "\"";
    DeviceSpec spec;
    const auto q = device.find('?');
    const std::string_view head = device.substr(0, q);
    const auto colon = head.find(':');
    spec.scheme = std::string(head.substr(0, colon));
    if (colon != std::string_view::npos) spec.path = std::string(head.substr(colon + 1));
    if (spec.scheme != "serial" && spec.scheme != "pty" && spec.scheme != "hid" &&
        spec.scheme != "lpt" && spec.scheme != "sim")
        return fail(ErrorKind::usage, "unknown device type \"" + spec.scheme +
                        "\" (expected serial:, pty:, hid:, lpt: or sim)",
                    where);
    if (spec.scheme != "sim" && spec.path.empty())
        return fail(ErrorKind::usage, "missing the device path after \"" + spec.scheme + ":\"", where);
    if (q != std::string_view::npos) {
        std::string_view rest = device.substr(q + 1);
        while (!rest.empty()) {
            const auto amp = rest.find('&');
            const auto kv = rest.substr(0, amp);
            const auto eq = kv.find('=');
            if (eq == std::string_view::npos || eq == 0)
                return fail(ErrorKind::usage, "option \"" + std::string(kv) + "\" is not key=value", where);
            spec.options[std::string(kv.substr(0, eq))] = std::string(kv.substr(eq + 1));
            if (amp == std::string_view::npos) break;
            rest = rest.substr(amp + 1);
        }
    }
    return spec;
}

std::string format_device(const DeviceSpec& spec) {
    std::string out = spec.scheme;
    if (!spec.path.empty()) out += ":" + spec.path;
    char separator = '?';
    for (const auto& [key, value] : spec.options) {
        out += separator;
        out += key + "=" + value;
        separator = '&';
    }
    return out;
}

Result<void> check_device(std::string_view device) {
    TACTUS_TRY(spec, parse_device(device));
    if (spec.scheme == "sim") {
        TACTUS_TRY_VOID(sim_settings(spec));
        return {};
    }
    if (spec.scheme == "lpt") return {};
    TACTUS_TRY_VOID(uart_settings(spec));
    return {};
}

Result<SimSettings> sim_settings(const DeviceSpec& spec) {
    SimSettings s;
    for (const auto& [k, v] : spec.options) {
        const std::string where = "sim option " + k;
        if (k == "speed" && v == "max") {
            s.speed = 0;
            continue;
        }
        const auto d = option_number(v);
        if (!d || *d < 0) return fail(ErrorKind::usage, "\"" + v + "\" is not a non-negative number", where);
        if (k == "baud") s.baud = *d;
        else if (k == "noise") {
            // The same cap as `sim --noise`: beyond it no frame gets through.
            if (*d > kMaxSimNoise)
                return fail(ErrorKind::usage, "\"" + v + "\" is above the highest noise rate, 0.5 per byte", where);
            s.noise = *d;
        }
        else if (k == "seed") s.seed = static_cast<std::uint64_t>(*d);
        else if (k == "paper-reload") s.paper_reload_s = *d;
        else if (k == "protocol") {
            if (*d != 2 && *d != 3) return fail(ErrorKind::usage, "\"" + v + "\" is not a protocol version (2 or 3)", where);
            s.protocol = static_cast<int>(*d);
        }
        else if (k == "speed") {
            if (*d <= 0) return fail(ErrorKind::usage, "\"" + v + "\" is not a speed above 0 (or max)", where);
            s.speed = *d;
        } else return fail(ErrorKind::usage, "unknown option (baud, noise, seed, paper-reload, speed, protocol)", where);
    }
    if (s.baud < 300) return fail(ErrorKind::usage, "baud rate below 300", "sim option baud");
    return s;
}

Result<UartSettings> uart_settings(const DeviceSpec& spec) {
    UartSettings u;
    for (const auto& [k, v] : spec.options) {
        const std::string where = spec.scheme + " option " + k;
        if (k == "baud") {
            const auto b = option_number(v);
            if (!b || *b < 300 || *b > 1'000'000 || *b != static_cast<int>(*b))
                return fail(ErrorKind::usage, "baud rate \"" + v + "\" is not a whole number from 300 to 1000000", where);
            u.baud = static_cast<int>(*b);
        } else if (k == "parity") {
            if (v != "none" && v != "odd" && v != "even")
                return fail(ErrorKind::usage, "parity must be none, odd or even", where);
            u.parity = v[0];
        } else if (k == "stop") {
            if (v != "1" && v != "2") return fail(ErrorKind::usage, "stop bits must be 1 or 2", where);
            u.stop_bits = v == "2" ? 2 : 1;
        } else if (k == "flow") {
            if (v == "none") u.flow = UartSettings::Flow::none;
            else if (v == "rtscts") u.flow = UartSettings::Flow::rtscts;
            else if (v == "xonxoff") u.flow = UartSettings::Flow::xonxoff;
            else return fail(ErrorKind::usage, "flow must be none, rtscts or xonxoff", where);
        } else if (spec.scheme != "sim") {
            return fail(ErrorKind::usage, "unknown option", where);
        }
    }
    return u;
}

Result<std::unique_ptr<ByteStream>> open_device(std::string_view device) {
    TACTUS_TRY(spec, parse_device(device));
    if (spec.scheme == "hid") return open_hid(spec);
    if (spec.scheme == "lpt") return open_lpt(spec);
    // The simulator belongs to the controller stage: controller::open_device.
    if (spec.scheme == "sim")
        return fail(ErrorKind::internal, "the built-in simulator is not a cable", "device \"" + std::string(device) + "\"");
    TACTUS_TRY(uart, uart_settings(spec));
    if (spec.scheme == "pty") {
        TACTUS_TRY(p, TtyPort::open(spec.path, uart));
        return std::unique_ptr<ByteStream>(std::move(p));
    }
    TACTUS_TRY(p, SerialPort::open(spec.path, uart));
    return std::unique_ptr<ByteStream>(std::move(p));
}

}  // namespace tactus::transport
