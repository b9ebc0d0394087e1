// SPDX-License-Identifier: GPL-3.0-or-later
#include "transport/tty_port.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace tactus::transport {
namespace {

speed_t speed_of(int baud) {
    switch (baud) {
        case 1200: return B1200;
        case 2400: return B2400;
        case 4800: return B4800;
        case 9600: return B9600;
        case 19200: return B19200;
        case 38400: return B38400;
        case 57600: return B57600;
        case 115200: return B115200;
        case 230400: return B230400;
        default: return B0;
    }
}

std::string open_error(int err) {
    switch (err) {
        case ENOENT:
        case ENXIO:
        case ENODEV: return "no such device";
        case EACCES:
        case EPERM: return "permission denied (is your user in the dialout group?)";
        case EBUSY:
        case EWOULDBLOCK: return "busy (in use by another program)";
        default: return std::strerror(err);
    }
}

}  // namespace

Result<void> make_raw(int fd, const UartSettings& uart, const std::string& where) {
    termios t{};
    if (tcgetattr(fd, &t) != 0) return fail(ErrorKind::device, "not a terminal: " + std::string(std::strerror(errno)), where);
    cfmakeraw(&t);
    t.c_cflag |= CLOCAL | CREAD;
    t.c_cflag &= ~static_cast<tcflag_t>(PARENB | PARODD | CSTOPB | CRTSCTS);
    if (uart.parity != 'n') t.c_cflag |= PARENB;
    if (uart.parity == 'o') t.c_cflag |= PARODD;
    if (uart.stop_bits == 2) t.c_cflag |= CSTOPB;
    if (uart.flow == UartSettings::Flow::rtscts) t.c_cflag |= CRTSCTS;
    if (uart.flow == UartSettings::Flow::xonxoff) t.c_iflag |= IXON | IXOFF;
    t.c_cc[VMIN] = 0;
    t.c_cc[VTIME] = 0;
    const speed_t sp = speed_of(uart.baud);
    if (sp == B0) return fail(ErrorKind::device, "unsupported baud rate " + std::to_string(uart.baud), where);
    cfsetispeed(&t, sp);
    cfsetospeed(&t, sp);
    if (tcsetattr(fd, TCSANOW, &t) != 0)
        return fail(ErrorKind::device, "cannot set terminal mode: " + std::string(std::strerror(errno)), where);
    return {};
}

Result<std::unique_ptr<TtyPort>> TtyPort::open(const std::string& path, const UartSettings& uart) {
    std::unique_ptr<TtyPort> p(new TtyPort(path, uart));
    if (auto r = p->open_fd(); !r) return std::unexpected(r.error());
    return p;
}

TtyPort::~TtyPort() { close_fd(); }

void TtyPort::close_fd() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
}

Result<void> TtyPort::open_fd() {
    const std::string where = "pty:" + path_;
    fd_ = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0) return fail(ErrorKind::device, open_error(errno), where);
    if (!isatty(fd_)) {
        close_fd();
        return fail(ErrorKind::device, "not a terminal", where);
    }
    // Two senders on one line would interleave frames: take the line exclusively.
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int err = errno;
        close_fd();
        return fail(ErrorKind::device, open_error(err == EWOULDBLOCK ? EBUSY : err), where);
    }
    if (auto r = make_raw(fd_, uart_, where); !r) {
        close_fd();
        return r;
    }
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
    const std::string where = "pty:" + path_;
    if (fd_ < 0) return fail(ErrorKind::device, "device not open", where);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const auto n = ::write(fd_, bytes.data() + done, bytes.size() - done);
        if (n > 0) {
            done += static_cast<std::size_t>(n);
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        if (n < 0 && errno == EAGAIN) {
            pollfd p{fd_, POLLOUT, 0};
            if (::poll(&p, 1, 1000) <= 0) return fail(ErrorKind::device, "write timed out (line blocked)", where);
            continue;
        }
        return fail(ErrorKind::device, "device disconnected: " + std::string(std::strerror(errno)), where);
    }
    return {};
}

Result<std::size_t> TtyPort::read(std::span<std::uint8_t> buffer, std::chrono::microseconds timeout) {
    const std::string where = "pty:" + path_;
    if (fd_ < 0) return fail(ErrorKind::device, "device not open", where);
    pollfd p{fd_, POLLIN, 0};
    const int ms = static_cast<int>((timeout.count() + 999) / 1000);
    const int r = ::poll(&p, 1, ms);
    if (r < 0) {
        if (errno == EINTR) return std::size_t{0};
        return fail(ErrorKind::device, std::strerror(errno), where);
    }
    if (r == 0) return std::size_t{0};
    const auto n = ::read(fd_, buffer.data(), buffer.size());
    if (n > 0) return static_cast<std::size_t>(n);
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) return std::size_t{0};
    // EIO or end of file: the other end of the pty (or the USB adapter) is gone.
    return fail(ErrorKind::device, "device disconnected", where);
}

}  // namespace tactus::transport
