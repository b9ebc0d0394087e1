// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/channel.hpp"

#include <fcntl.h>
#include <poll.h>
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
    const auto ns = std::max<std::int64_t>(0, timeout.count());
    const timespec ts{static_cast<time_t>(ns / 1'000'000'000), static_cast<long>(ns % 1'000'000'000)};
    std::vector<bool> ready(channels.size(), false);
    const int r = ::ppoll(fds.data(), fds.size(), &ts, nullptr);
    if (r < 0 && errno != EINTR) return std::unexpected(last_error());
    for (std::size_t i = 0; r > 0 && i < fds.size(); ++i) ready[i] = (fds[i].revents & POLLIN) != 0;
    return ready;
}

OsResult<Channel> open_fifo(const std::filesystem::path& path) {
    if (::mkfifo(path.c_str(), 0600) != 0) return std::unexpected(last_error());
    const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) return std::unexpected(last_error());
    return Channel(fd);
}

}  // namespace tactus::platform
