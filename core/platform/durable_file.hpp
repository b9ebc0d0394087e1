// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Files as the system stores them: read without blocking on a FIFO or a device,
// written to a new file that is made durable and then put in place of the old
// one in one step. POSIX: open(O_NONBLOCK), fsync, rename. Windows: CreateFileW,
// FlushFileBuffers, MoveFileExW(MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "platform/os_error.hpp"

namespace tactus::platform {

enum class FileType : std::uint8_t { regular, directory, fifo, device, socket, other };

struct FileInfo {
    FileType type = FileType::other;
    std::uint64_t size = 0;
};

// A file opened for reading without waiting for a writer (a FIFO) or a carrier (a device).
class ReadableFile {
public:
    static OsResult<ReadableFile> open(const std::filesystem::path& path);
    ReadableFile(ReadableFile&& o) noexcept : handle_(o.release()) {}
    ReadableFile& operator=(ReadableFile&&) = delete;
    ~ReadableFile();

    OsResult<FileInfo> info() const;
    // Up to n bytes; 0 at the end of the file.
    OsResult<std::size_t> read(char* buffer, std::size_t n);

private:
    explicit ReadableFile(std::intptr_t h) : handle_(h) {}
    std::intptr_t release() noexcept {
        const auto h = handle_;
        handle_ = -1;
        return h;
    }
    std::intptr_t handle_ = -1;
};

// A file created here and now (never one that exists), for writing.
class NewFile {
public:
    static OsResult<NewFile> create(const std::filesystem::path& path);
    NewFile(NewFile&& o) noexcept : handle_(o.release()) {}
    NewFile& operator=(NewFile&&) = delete;
    ~NewFile();

    OsResult<void> write_all(std::string_view bytes);
    // Waits until the bytes are on the disk, then closes.
    OsResult<void> sync_and_close();

private:
    explicit NewFile(std::intptr_t h) : handle_(h) {}
    std::intptr_t release() noexcept {
        const auto h = handle_;
        handle_ = -1;
        return h;
    }
    std::intptr_t handle_ = -1;
};

// Waits until a closed file's bytes are on the disk.
OsResult<void> sync_file(const std::filesystem::path& path);

// Puts `from` in place of `to` in one step: a reader sees the old file or the new one.
OsResult<void> replace_file(const std::filesystem::path& from, const std::filesystem::path& to);

// Makes a new folder only this user can enter, named `prefix` and a random
// tail, in the system's temporary folder.
OsResult<std::filesystem::path> make_private_dir(const std::string& prefix);

// Removes a file, quietly (a temporary one a failed save leaves).
void remove_file(const std::filesystem::path& path) noexcept;

}  // namespace tactus::platform
