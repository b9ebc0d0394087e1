// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Device strings: one line chooses the cable (docs/transports.md).
//   serial:/dev/ttyUSB0?baud=57600&parity=none&flow=rtscts
//   pty:/dev/pts/3?baud=115200
//   hid:10c4:ea80[:serial]?baud=115200
//   lpt:/dev/parport0
//   sim?baud=115200&noise=1e-3&seed=7&paper-reload=5&speed=10&protocol=2
#include <cstdint>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <string_view>

#include "common/result.hpp"
#include "transport/byte_stream.hpp"

namespace tactus::transport {

struct DeviceSpec {
    std::string scheme;  // serial, pty, hid, lpt, sim
    std::string path;    // what follows "scheme:" up to '?'
    std::map<std::string, std::string> options;
};

Result<DeviceSpec> parse_device(std::string_view device);

// The device string of a spec: parse_device's inverse, so that a program that
// changes one option (the app's simulator speed) writes the string a user
// would type. Options come in key order.
std::string format_device(const DeviceSpec& spec);

// An option's value as a number: the whole text, nothing left over.
std::optional<double> option_number(const std::string& value);

// Serial line settings shared by serial, pty and hid.
struct UartSettings {
    int baud = 115200;
    char parity = 'n';  // n, o, e
    int stop_bits = 1;
    enum class Flow { none, rtscts, xonxoff } flow = Flow::none;

    // Line capacity: a start bit, 8 data bits, the parity bit if any, stop bits.
    [[nodiscard]] double bytes_per_second() const {
        const int bits = 1 + 8 + (parity != 'n' ? 1 : 0) + stop_bits;
        return static_cast<double>(baud) / bits;
    }
};
Result<UartSettings> uart_settings(const DeviceSpec& spec);

// The simulator's options (`sim?...`, docs/transports.md), read in one place
// for `tactus-cli` (controller::open_device), the desktop app's built-in
// simulator and the spool's check of a printer's device string.
// The highest per-byte noise rate a simulated line takes (`sim --noise` and
// `sim?noise=`): at 0.5 each of loss, flip and duplicate no frame arrives whole.
inline constexpr double kMaxSimNoise = 0.5;

struct SimSettings {
    double baud = 115200;
    double noise = 0;             // per byte: lost, flipped, doubled
    std::uint64_t seed = 1;       // of the noise
    std::optional<double> paper_reload_s;  // the simulated operator reloads paper after this long
    // How many times faster than the machine simulated time may run: 1 (the
    // default) is the plan's own speed; 0 is `speed=max`, as fast as the
    // computer can.
    double speed = 1;
    // The protocol the simulated controller speaks: 0 (the default) is 3, as
    // the reference firmware built from the profile speaks it, when the
    // profile can be made into its ramp tables, else 2; `protocol=2` or
    // `protocol=3` insists on one.
    int protocol = 0;
};
Result<SimSettings> sim_settings(const DeviceSpec& spec);

// Checks a device string without opening anything: its type, its path and
// its line options. A spool printer is refused at `queue printer add` rather
// than when its first job runs.
Result<void> check_device(std::string_view device);

// Opens the device. Errors say which device and why: "no such device",
// "busy (in use by another program)", "permission denied (add yourself to the
// dialout group)", "not a terminal".
Result<std::unique_ptr<ByteStream>> open_device(std::string_view device);

}  // namespace tactus::transport
