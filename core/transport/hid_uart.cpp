// SPDX-License-Identifier: GPL-3.0-or-later
#include "transport/hid_uart.hpp"
#include "common/try.hpp"

#include <algorithm>

namespace tactus::transport {

std::optional<HidBridge> bridge_for(std::uint16_t vid, std::uint16_t pid) {
    if (vid == 0x10C4 && (pid == 0xEA80 || pid == 0xEAB0)) return HidBridge::cp2110;
    if (vid == 0x0403 && pid == 0x6030) return HidBridge::ft260;
    return std::nullopt;
}

const char* bridge_name(HidBridge b) { return b == HidBridge::cp2110 ? "CP2110/CP2114" : "FT260"; }

namespace hid_report {

std::vector<std::vector<std::uint8_t>> uart_out(HidBridge b, std::span<const std::uint8_t> bytes) {
    std::vector<std::vector<std::uint8_t>> reports;
    const std::size_t max = b == HidBridge::cp2110 ? 63 : 60;
    for (std::size_t i = 0; i < bytes.size(); i += max) {
        const std::size_t n = std::min(max, bytes.size() - i);
        const auto piece = bytes.subspan(i, n);
        std::vector<std::uint8_t> r;
        if (b == HidBridge::cp2110) {
            r.push_back(static_cast<std::uint8_t>(n));
            r.insert(r.end(), piece.begin(), piece.end());
        } else {
            // The report id picks the size class: 0xF0 holds 4 bytes, 0xF1 8, ... 0xFE 60.
            const std::size_t cls = (n - 1) / 4;
            r.push_back(static_cast<std::uint8_t>(kFt260UartBase + cls));
            r.push_back(static_cast<std::uint8_t>(n));
            r.insert(r.end(), piece.begin(), piece.end());
            r.resize(2 + 4 * (cls + 1), 0);
        }
        reports.push_back(std::move(r));
    }
    return reports;
}

Result<std::vector<std::uint8_t>> uart_in(HidBridge b, std::span<const std::uint8_t> report) {
    if (report.empty()) return std::vector<std::uint8_t>{};
    const std::uint8_t id = report[0];
    if (b == HidBridge::cp2110) {
        if (id < 0x01 || id > 0x3F) return std::vector<std::uint8_t>{};  // not UART data
        if (report.size() < 1U + id)
            return fail(ErrorKind::device, "CP2110 report 0x" + std::to_string(id) + " shorter than its length",
                        "hid report");
        return std::vector<std::uint8_t>(report.begin() + 1, report.begin() + 1 + id);
    }
    if (id < kFt260UartBase || id > 0xFE) return std::vector<std::uint8_t>{};
    if (report.size() < 2) return fail(ErrorKind::device, "FT260 UART report without a length", "hid report");
    const std::size_t n = report[1];
    const std::size_t cap = 4 * (static_cast<std::size_t>(id - kFt260UartBase) + 1);
    if (n > cap || report.size() < 2 + n)
        return fail(ErrorKind::device, "FT260 UART report claims " + std::to_string(n) + " bytes", "hid report");
    return std::vector<std::uint8_t>(report.begin() + 2, report.begin() + 2 + static_cast<std::ptrdiff_t>(n));
}

std::vector<std::vector<std::uint8_t>> uart_setup(HidBridge b, const UartSettings& u) {
    const auto baud = static_cast<std::uint32_t>(u.baud);
    const std::uint8_t parity = u.parity == 'o' ? 1 : u.parity == 'e' ? 2 : 0;
    if (b == HidBridge::cp2110) {
        // Config: baud (big-endian), parity, flow (0 none, 1 RTS/CTS), data bits
        // (3 = 8 bits), stop bits (0 short = 1, 1 long = 2).
        return {{kCp2110UartEnable, 0x01},
                {kCp2110UartConfig, static_cast<std::uint8_t>(baud >> 24),
                 static_cast<std::uint8_t>(baud >> 16), static_cast<std::uint8_t>(baud >> 8),
                 static_cast<std::uint8_t>(baud), parity,
                 static_cast<std::uint8_t>(u.flow == UartSettings::Flow::rtscts ? 1 : 0), 0x03,
                 static_cast<std::uint8_t>(u.stop_bits == 2 ? 1 : 0)},
                {kCp2110Purge, 0x03}};
    }
    // FT260 flow modes: 0 off, 1 RTS/CTS, 2 DTR/DSR, 3 XON/XOFF, 4 none.
    const std::uint8_t flow = u.flow == UartSettings::Flow::rtscts    ? 1
                              : u.flow == UartSettings::Flow::xonxoff ? 3
                                                                      : 4;
    return {{kFt260SystemSetting, kFt260SetUartMode, flow},
            {kFt260SystemSetting, kFt260ConfigureUart, flow, static_cast<std::uint8_t>(baud),
             static_cast<std::uint8_t>(baud >> 8), static_cast<std::uint8_t>(baud >> 16),
             static_cast<std::uint8_t>(baud >> 24), 8, parity,
             static_cast<std::uint8_t>(u.stop_bits == 2 ? 2 : 0), 0}};
}

}  // namespace hid_report

Result<std::unique_ptr<HidUart>> HidUart::open(Opener opener, HidBridge bridge,
                                               const UartSettings& uart, std::string name) {
    std::unique_ptr<HidUart> h(new HidUart(std::move(opener), bridge, uart, std::move(name)));
    TACTUS_TRY_VOID(h->start());
    return h;
}

Result<void> HidUart::start() {
    dev_.reset();
    TACTUS_TRY(d, opener_());
    dev_ = std::move(d);
    for (const auto& f : hid_report::uart_setup(bridge_, uart_))
        if (auto r = dev_->send_feature(f); !r)
            return fail(ErrorKind::device, std::string(bridge_name(bridge_)) + " refused its UART setup: " +
                            r.error().message,
                        name_);
    pending_.clear();
    return {};
}

Result<void> HidUart::reopen() { return start(); }

Result<void> HidUart::write(std::span<const std::uint8_t> bytes) {
    if (!dev_) return fail(ErrorKind::device, "device not open", name_);
    for (const auto& report : hid_report::uart_out(bridge_, bytes))
        if (auto r = dev_->write_report(report); !r)
            return fail(ErrorKind::device, "device disconnected: " + r.error().message, name_);
    return {};
}

Result<std::size_t> HidUart::read(std::span<std::uint8_t> buffer, std::chrono::microseconds timeout) {
    if (!dev_) return fail(ErrorKind::device, "device not open", name_);
    int ms = static_cast<int>((timeout.count() + 999) / 1000);
    while (pending_.empty()) {
        std::array<std::uint8_t, 64> report{};
        auto n = dev_->read_report(report, ms);
        if (!n) return fail(ErrorKind::device, "device disconnected: " + n.error().message, name_);
        if (*n == 0) return std::size_t{0};
        auto data = hid_report::uart_in(bridge_, std::span(report).first(*n));
        if (!data) return std::unexpected(data.error());
        pending_.insert(pending_.end(), data->begin(), data->end());
        ms = 0;  // other report types (status, GPIO) do not count as data: look once more
        if (pending_.empty()) return std::size_t{0};
    }
    const std::size_t n = std::min(buffer.size(), pending_.size());
    std::copy_n(pending_.begin(), n, buffer.begin());
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(n));
    return n;
}

}  // namespace tactus::transport
