// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/durable_file.hpp"
#include "platform/posix_fd.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

namespace tactus::platform {
namespace {


FileType type_of(mode_t mode) {
    if (S_ISREG(mode)) return FileType::regular;
    if (S_ISDIR(mode)) return FileType::directory;
    if (S_ISFIFO(mode)) return FileType::fifo;
    if (S_ISCHR(mode) || S_ISBLK(mode)) return FileType::device;
    if (S_ISSOCK(mode)) return FileType::socket;
    return FileType::other;
}

}  // namespace

OsResult<ReadableFile> ReadableFile::open(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) return std::unexpected(last_error());
    return ReadableFile(fd);
}

ReadableFile::~ReadableFile() {
    if (handle_ >= 0) ::close(fd_of(handle_));
}

OsResult<FileInfo> ReadableFile::info() const {
    struct stat st {};
    if (::fstat(fd_of(handle_), &st) != 0) return std::unexpected(last_error());
    return FileInfo{type_of(st.st_mode), static_cast<std::uint64_t>(st.st_size)};
}

OsResult<std::size_t> ReadableFile::read(char* buffer, std::size_t n) {
    for (;;) {
        const auto r = ::read(fd_of(handle_), buffer, n);
        if (r >= 0) return static_cast<std::size_t>(r);
        if (errno != EINTR) return std::unexpected(last_error());
    }
}

OsResult<NewFile> NewFile::create(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) return std::unexpected(last_error());
    return NewFile(fd);
}

NewFile::~NewFile() {
    if (handle_ >= 0) ::close(fd_of(handle_));
}

OsResult<void> NewFile::write_all(std::string_view bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const auto n = ::write(fd_of(handle_), bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return std::unexpected(last_error());
        }
        done += static_cast<std::size_t>(n);
    }
    return {};
}

OsResult<void> NewFile::sync_and_close() {
    const int fd = fd_of(release());
    if (::fsync(fd) != 0) {
        const auto e = last_error();
        ::close(fd);
        return std::unexpected(e);
    }
    if (::close(fd) != 0) return std::unexpected(last_error());
    return {};
}

OsResult<void> sync_file(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return std::unexpected(last_error());
    if (::fsync(fd) != 0) {
        const auto e = last_error();
        ::close(fd);
        return std::unexpected(e);
    }
    ::close(fd);
    return {};
}

OsResult<void> replace_file(const std::filesystem::path& from, const std::filesystem::path& to) {
    if (::rename(from.c_str(), to.c_str()) != 0) return std::unexpected(last_error());
    return {};
}

OsResult<std::filesystem::path> make_private_dir(const std::string& prefix) {
    std::string tmpl = (std::filesystem::temp_directory_path() / (prefix + ".XXXXXX")).string();
    if (!::mkdtemp(tmpl.data())) return std::unexpected(last_error());
    return std::filesystem::path(tmpl);
}

void remove_file(const std::filesystem::path& path) noexcept { ::unlink(path.c_str()); }

}  // namespace tactus::platform
