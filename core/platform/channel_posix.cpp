// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/channel.hpp"
#include "platform/posix_fd.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <ctime>

namespace tactus::platform {

Channel& Channel::operator=(Channel&& o) noexcept {
    if (this != &o) {
        close();
        handle_ = o.release();
    }
    return *this;
}

void Channel::close() noexcept {
    if (handle_ >= 0) ::close(static_cast<int>(handle_));
    handle_ = -1;
}

OsResult<std::size_t> Channel::read_some(std::span<std::uint8_t> buffer) {
    const auto n = ::read(static_cast<int>(handle_), buffer.data(), buffer.size());
    if (n >= 0) return static_cast<std::size_t>(n);
    if (errno == EAGAIN || errno == EINTR) return std::size_t{0};
    return std::unexpected(last_error());
}

OsResult<std::size_t> Channel::write_some(std::span<const std::uint8_t> bytes) {
    for (;;) {
        const auto n = ::write(static_cast<int>(handle_), bytes.data(), bytes.size());
        if (n >= 0) return static_cast<std::size_t>(n);
        if (errno == EAGAIN) return std::size_t{0};
        if (errno != EINTR) return std::unexpected(last_error());
    }
}

OsResult<std::vector<bool>> wait_readable(std::span<Channel* const> channels, std::chrono::nanoseconds timeout) {
    std::vector<pollfd> fds;
    for (const Channel* c : channels) fds.push_back({static_cast<int>(c->native()), POLLIN, 0});
    std::vector<bool> ready(channels.size(), false);
    const int r = poll_for(fds.data(), static_cast<nfds_t>(fds.size()), timeout);
    if (r < 0 && errno != EINTR) return std::unexpected(last_error());
    for (std::size_t i = 0; r > 0 && i < fds.size(); ++i) ready[i] = (fds[i].revents & POLLIN) != 0;
    return ready;
}

namespace {
sockaddr_in loopback(std::uint16_t port) {
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    return a;
}
}  // namespace

OsResult<Channel> connect_loopback(std::uint16_t port) {
    Channel c(cloexec_socket(AF_INET, SOCK_STREAM));
    if (!c.is_open()) return std::unexpected(last_error());
    const auto a = loopback(port);
    if (::connect(static_cast<int>(c.native()), reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0)
        return std::unexpected(last_error());
    const int one = 1;
    ::setsockopt(static_cast<int>(c.native()), IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    return c;
}

OsResult<std::uint16_t> unused_loopback_port() {
    Channel c(cloexec_socket(AF_INET, SOCK_STREAM));
    if (!c.is_open()) return std::unexpected(last_error());
    auto a = loopback(0);
    socklen_t len = sizeof a;
    if (::bind(static_cast<int>(c.native()), reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0 ||
        ::getsockname(static_cast<int>(c.native()), reinterpret_cast<sockaddr*>(&a), &len) != 0)
        return std::unexpected(last_error());
    return ntohs(a.sin_port);
}

OsResult<Channel> open_fifo(const std::filesystem::path& path) {
    if (::mkfifo(path.c_str(), 0600) != 0) return std::unexpected(last_error());
    const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) return std::unexpected(last_error());
    return Channel(fd);
}

}  // namespace tactus::platform
