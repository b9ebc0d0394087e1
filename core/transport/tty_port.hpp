// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A terminal device driven directly (platform::Terminal: termios on POSIX):
// pseudo-terminals (socat, emulators, `tactus-cli sim --pty`), which
// libserialport refuses to open, and the simulator's named pipe on Windows.
#include <optional>
#include <string>

#include "transport/byte_stream.hpp"
#include "transport/device.hpp"
#include "platform/terminal.hpp"

namespace tactus::transport {

class TtyPort final : public ByteStream {
public:
    static Result<std::unique_ptr<TtyPort>> open(const std::string& path, const UartSettings& uart);
    ~TtyPort() override;

    Result<void> write(std::span<const std::uint8_t> bytes) override;
    Result<std::size_t> read(std::span<std::uint8_t> buffer,
                             std::chrono::microseconds timeout) override;
    Result<void> reopen() override;
    [[nodiscard]] double bytes_per_second() const override;
    [[nodiscard]] std::string describe() const override { return "pty:" + path_; }

private:
    TtyPort(std::string path, UartSettings uart) : path_(std::move(path)), uart_(uart) {}
    Result<void> open_fd();
    void close_fd();
    std::string path_;
    UartSettings uart_;
    std::optional<platform::Terminal> line_;
};

}  // namespace tactus::transport
