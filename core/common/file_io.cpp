// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/file_io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>

namespace tactus {

namespace {

// What a file that is not a regular file is, in words a user knows.
std::string not_regular(mode_t mode) {
    if (S_ISDIR(mode)) return "is a directory, not a file";
    if (S_ISFIFO(mode)) return "is a named pipe (FIFO), not a regular file: save what it carries to a file first";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
    if (S_ISSOCK(mode)) return "is a socket, not a regular file";
    return "is not a regular file";
}

}  // namespace

Result<std::string> read_file(const std::filesystem::path& path, std::size_t max_bytes) {
    // Opened without blocking and checked before reading: a named pipe with no
    // writer would block open() and read() for ever, a device could give bytes
    // without end.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) return fail(std::string("cannot open: ") + std::strerror(errno), path.string());
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const std::string why = std::strerror(errno);
        ::close(fd);
        return fail("cannot examine: " + why, path.string());
    }
    if (!S_ISREG(st.st_mode)) {
        ::close(fd);
        return fail(not_regular(st.st_mode), path.string());
    }
    const auto size = static_cast<std::size_t>(st.st_size);
    if (size > max_bytes) {
        ::close(fd);
        return fail("file is " + std::to_string(size) + " bytes, above the limit of " + std::to_string(max_bytes),
                    path.string());
    }
    std::string bytes(size, '\0');
    std::size_t done = 0;
    while (done < size) {
        const auto n = ::read(fd, bytes.data() + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const std::string why = std::strerror(errno);
            ::close(fd);
            return fail("read error: " + why, path.string());
        }
        if (n == 0) break;  // shrank while read: what is there
        done += static_cast<std::size_t>(n);
    }
    ::close(fd);
    bytes.resize(done);
    return bytes;
}

Result<void> write_file_atomic(const std::filesystem::path& path, std::string_view bytes) {
    const auto dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::random_device rd;
    const auto tmp = dir / ("." + path.filename().string() + ".tmp" + std::to_string(rd()));
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) return fail(ErrorKind::io, std::string("cannot create: ") + std::strerror(errno), tmp.string());
    std::size_t done = 0;
    while (done < bytes.size()) {
        const auto n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            const std::string why = std::strerror(errno);
            ::close(fd);
            ::unlink(tmp.c_str());
            return fail(ErrorKind::io, "write failed: " + why, path.string());
        }
        done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        const std::string why = std::strerror(errno);
        ::unlink(tmp.c_str());
        return fail(ErrorKind::io, "cannot flush to disk: " + why, path.string());
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        ::unlink(tmp.c_str());
        return fail(ErrorKind::io, "cannot replace file: " + why, path.string());
    }
    return {};
}

Result<void> write_file_atomic(const std::filesystem::path& path,
                               const std::function<Result<void>(std::ostream&)>& produce) {
    const auto dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::random_device rd;
    const auto tmp = dir / ("." + path.filename().string() + ".tmp" + std::to_string(rd()));
    auto discard = [&](Error e) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        return std::unexpected(std::move(e));
    };
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) return fail(ErrorKind::io, std::string("cannot create: ") + std::strerror(errno), tmp.string());
        if (auto ok = produce(out); !ok) return discard(ok.error());
        out.flush();
        if (!out) return discard(Error{"write failed (disk full?)", path.string(), ErrorKind::io});
    }
    // Make the data durable before the rename makes it visible.
    const int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || ::fsync(fd) != 0) {
        const std::string why = std::strerror(errno);
        if (fd >= 0) ::close(fd);
        return discard(Error{"cannot flush to disk: " + why, path.string(), ErrorKind::io});
    }
    ::close(fd);
    if (::rename(tmp.c_str(), path.c_str()) != 0)
        return discard(Error{std::string("cannot replace file: ") + std::strerror(errno), path.string(), ErrorKind::io});
    return {};
}

}  // namespace tactus
