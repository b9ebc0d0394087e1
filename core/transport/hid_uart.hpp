// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// USB HID-to-UART bridges: Silicon Labs CP2110/CP2114 and FTDI FT260. They carry
// UART bytes in HID interrupt reports and take their line settings as feature
// reports. The report formats live here, apart from hidapi, so both sides of the
// hardware boundary can be tested: HidDevice is the chip as the host sees it.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "transport/byte_stream.hpp"
#include "transport/device.hpp"
#include "transport/serial_port.hpp"

namespace tactus::transport {

enum class HidBridge { cp2110, ft260 };
// Which bridge a USB id is, if it is one we drive.
std::optional<HidBridge> bridge_for(std::uint16_t vid, std::uint16_t pid);
const char* bridge_name(HidBridge b);

namespace hid_report {
// CP2110/CP2114 (AN434): reports 0x01-0x3F carry that many UART bytes.
// FT260 (AN_394): reports 0xF0-0xFE carry up to 4, 8 ... 60 bytes: [id, len, data, padding].
inline constexpr std::uint8_t kCp2110UartEnable = 0x41;
inline constexpr std::uint8_t kCp2110Purge = 0x43;
inline constexpr std::uint8_t kCp2110UartConfig = 0x50;
inline constexpr std::uint8_t kFt260SystemSetting = 0xA1;
inline constexpr std::uint8_t kFt260SetUartMode = 0x03;
inline constexpr std::uint8_t kFt260ConfigureUart = 0x41;
inline constexpr std::uint8_t kFt260UartBase = 0xF0;

// UART bytes -> output reports (report id first).
std::vector<std::vector<std::uint8_t>> uart_out(HidBridge b, std::span<const std::uint8_t> bytes);
// An input report -> the UART bytes it carries (empty for other reports).
Result<std::vector<std::uint8_t>> uart_in(HidBridge b, std::span<const std::uint8_t> report);
// Feature reports that enable the UART and set baud, parity, stop bits, flow.
std::vector<std::vector<std::uint8_t>> uart_setup(HidBridge b, const UartSettings& uart);
}  // namespace hid_report

// One HID device, as hidapi (or a test's fake chip) presents it.
class HidDevice {
public:
    virtual ~HidDevice() = default;
    virtual Result<void> write_report(std::span<const std::uint8_t> report) = 0;
    // Reads one input report; 0 on timeout.
    virtual Result<std::size_t> read_report(std::span<std::uint8_t> buffer, int timeout_ms) = 0;
    virtual Result<void> send_feature(std::span<const std::uint8_t> report) = 0;
};

class HidUart final : public ByteStream {
public:
    using Opener = std::function<Result<std::unique_ptr<HidDevice>>()>;
    // Opens through `opener` (again on reopen) and configures the bridge's UART.
    static Result<std::unique_ptr<HidUart>> open(Opener opener, HidBridge bridge,
                                                 const UartSettings& uart, std::string name);

    Result<void> write(std::span<const std::uint8_t> bytes) override;
    Result<std::size_t> read(std::span<std::uint8_t> buffer,
                             std::chrono::microseconds timeout) override;
    Result<void> reopen() override;
    [[nodiscard]] double bytes_per_second() const override { return uart_.bytes_per_second(); }
    [[nodiscard]] std::string describe() const override { return name_; }

private:
    HidUart(Opener opener, HidBridge bridge, UartSettings uart, std::string name)
        : opener_(std::move(opener)), bridge_(bridge), uart_(uart), name_(std::move(name)) {}
    Result<void> start();
    Opener opener_;
    HidBridge bridge_;
    UartSettings uart_;
    std::string name_;
    std::unique_ptr<HidDevice> dev_;
    std::vector<std::uint8_t> pending_;
};

// hid:VID:PID[:serial] through hidapi.
Result<std::unique_ptr<ByteStream>> open_hid(const DeviceSpec& spec);
Result<std::vector<PortInfo>> list_hid_uarts();

}  // namespace tactus::transport
