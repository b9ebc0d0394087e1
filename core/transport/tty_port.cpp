// SPDX-License-Identifier: GPL-3.0-or-later
#include "transport/tty_port.hpp"
#include "common/try.hpp"

namespace tactus::transport {
namespace {

platform::LineSettings line_settings(const UartSettings& uart) {
    platform::LineSettings line;
    line.baud = uart.baud;
    line.parity = uart.parity;
    line.stop_bits = uart.stop_bits;
    line.flow = uart.flow == UartSettings::Flow::rtscts    ? platform::LineSettings::Flow::rtscts
                : uart.flow == UartSettings::Flow::xonxoff ? platform::LineSettings::Flow::xonxoff
                                                           : platform::LineSettings::Flow::none;
    return line;
}

}  // namespace

Result<std::unique_ptr<TtyPort>> TtyPort::open(const std::string& path, const UartSettings& uart) {
    std::unique_ptr<TtyPort> p(new TtyPort(path, uart));
    TACTUS_TRY_VOID(p->open_fd());
    return p;
}

TtyPort::~TtyPort() { close_fd(); }

void TtyPort::close_fd() { line_.reset(); }

Result<void> TtyPort::open_fd() {
    auto line = platform::Terminal::open(path_, line_settings(uart_));
    if (!line) return fail(ErrorKind::device, line.error().what, describe());
    line_.emplace(std::move(*line));
    return {};
}

Result<void> TtyPort::reopen() {
    close_fd();
    return open_fd();
}

double TtyPort::bytes_per_second() const {
    return uart_.bytes_per_second();
}

Result<void> TtyPort::write(std::span<const std::uint8_t> bytes) {
    if (!line_) return fail(ErrorKind::device, "device not open", describe());
    if (auto r = line_->write_all(bytes); !r) return fail(ErrorKind::device, r.error().what, describe());
    return {};
}

Result<std::size_t> TtyPort::read(std::span<std::uint8_t> buffer, std::chrono::microseconds timeout) {
    if (!line_) return fail(ErrorKind::device, "device not open", describe());
    auto n = line_->read(buffer, timeout);
    if (!n) return fail(ErrorKind::device, n.error().what, describe());
    return *n;
}

}  // namespace tactus::transport
