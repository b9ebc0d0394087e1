// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Real serial ports (USB-serial adapters, on-board COM ports) through libserialport.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "transport/byte_stream.hpp"
#include "transport/device.hpp"

struct sp_port;

namespace tactus::transport {

class SerialPort final : public ByteStream {
public:
    static Result<std::unique_ptr<SerialPort>> open(const std::string& path, const UartSettings& uart);
    ~SerialPort() override;

    Result<void> write(std::span<const std::uint8_t> bytes) override;
    Result<std::size_t> read(std::span<std::uint8_t> buffer,
                             std::chrono::microseconds timeout) override;
    Result<void> reopen() override;
    [[nodiscard]] double bytes_per_second() const override;
    [[nodiscard]] std::string describe() const override { return "serial:" + path_; }

private:
    SerialPort(std::string path, UartSettings uart) : path_(std::move(path)), uart_(uart) {}
    Result<void> open_port();
    void close_port();
    std::string path_;
    UartSettings uart_;
    sp_port* port_ = nullptr;
};

// A port as `tactus-cli ports` lists it.
struct PortInfo {
    std::string device;  // a device string that opens it
    std::string kind;    // usb-serial, native, bluetooth, hid-uart, lpt
    std::string description;
    std::optional<int> vid, pid;
    std::string serial_number;
    std::string manufacturer;
    std::string product;
};

Result<std::vector<PortInfo>> list_serial_ports();

}  // namespace tactus::transport
