// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/terminal.hpp"
#include "platform/posix_fd.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace tactus::platform {
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

OsResult<void> make_raw(int fd, const LineSettings& line) {
    termios t{};
    if (tcgetattr(fd, &t) != 0) return os_fail("not a terminal: " + std::string(std::strerror(errno)));
    cfmakeraw(&t);
    t.c_cflag |= CLOCAL | CREAD;
    t.c_cflag &= ~static_cast<tcflag_t>(PARENB | PARODD | CSTOPB | CRTSCTS);
    if (line.parity != 'n') t.c_cflag |= PARENB;
    if (line.parity == 'o') t.c_cflag |= PARODD;
    if (line.stop_bits == 2) t.c_cflag |= CSTOPB;
    if (line.flow == LineSettings::Flow::rtscts) t.c_cflag |= CRTSCTS;
    if (line.flow == LineSettings::Flow::xonxoff) t.c_iflag |= IXON | IXOFF;
    t.c_cc[VMIN] = 0;
    t.c_cc[VTIME] = 0;
    const speed_t sp = speed_of(line.baud);
    if (sp == B0) return os_fail("unsupported baud rate " + std::to_string(line.baud), OsErrorKind::unsupported);
    cfsetispeed(&t, sp);
    cfsetospeed(&t, sp);
    if (tcsetattr(fd, TCSANOW, &t) != 0)
        return os_fail("cannot set terminal mode: " + std::string(std::strerror(errno)));
    return {};
}

}  // namespace

OsResult<Terminal> Terminal::open(const std::string& path, const LineSettings& line) {
    const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        const int err = errno;
        return os_fail(open_error(err), last_error().kind);
    }
    Terminal t(fd);
    if (!isatty(fd)) return os_fail("not a terminal");
    // Two senders on one line would interleave frames: take the line exclusively.
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int err = errno;
        return os_fail(open_error(err == EWOULDBLOCK ? EBUSY : err), OsErrorKind::busy);
    }
    if (auto r = make_raw(fd, line); !r) return std::unexpected(r.error());
    return t;
}

Terminal& Terminal::operator=(Terminal&& o) noexcept {
    if (this != &o) {
        if (handle_ >= 0) ::close(fd_of(handle_));
        handle_ = o.release();
    }
    return *this;
}

Terminal::~Terminal() {
    if (handle_ >= 0) ::close(fd_of(handle_));
}

OsResult<void> Terminal::write_all(std::span<const std::uint8_t> bytes) {
    const int fd = fd_of(handle_);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const auto n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n > 0) {
            done += static_cast<std::size_t>(n);
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        if (n < 0 && errno == EAGAIN) {
            pollfd p{fd, POLLOUT, 0};
            if (::poll(&p, 1, 1000) <= 0) return os_fail("write timed out (line blocked)");
            continue;
        }
        return os_fail("device disconnected: " + std::string(std::strerror(errno)));
    }
    return {};
}

OsResult<std::size_t> Terminal::read(std::span<std::uint8_t> buffer, std::chrono::microseconds timeout) {
    const int fd = fd_of(handle_);
    pollfd p{fd, POLLIN, 0};
    const int ms = static_cast<int>((timeout.count() + 999) / 1000);
    const int r = ::poll(&p, 1, ms);
    if (r < 0) {
        if (errno == EINTR) return std::size_t{0};
        return os_fail(std::strerror(errno));
    }
    if (r == 0) return std::size_t{0};
    const auto n = ::read(fd, buffer.data(), buffer.size());
    if (n > 0) return static_cast<std::size_t>(n);
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) return std::size_t{0};
    // EIO or end of file: the other end of the pty (or the USB adapter) is gone.
    return os_fail("device disconnected");
}

}  // namespace tactus::platform
