// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/durable_file.hpp"

#include <windows.h>

#include "platform/os_error_win.hpp"

namespace tactus::platform {
namespace {

HANDLE handle_of(std::intptr_t h) { return reinterpret_cast<HANDLE>(h); }
std::intptr_t stored(HANDLE h) { return reinterpret_cast<std::intptr_t>(h); }

}  // namespace

OsResult<ReadableFile> ReadableFile::open(const std::filesystem::path& path) {
    // FILE_SHARE_DELETE: a save that replaces the file while it is read does not fail.
    const HANDLE h = CreateFileW(path.c_str(), GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
                                 nullptr, OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, nullptr);
    if (h == INVALID_HANDLE_VALUE) return std::unexpected(last_error());
    return ReadableFile(stored(h));
}

ReadableFile::~ReadableFile() {
    if (handle_ != -1) CloseHandle(handle_of(handle_));
}

OsResult<FileInfo> ReadableFile::info() const {
    const HANDLE h = handle_of(handle_);
    FileInfo out;
    switch (GetFileType(h)) {
        case FILE_TYPE_PIPE: out.type = FileType::fifo; return out;
        case FILE_TYPE_CHAR: out.type = FileType::device; return out;
        case FILE_TYPE_DISK: break;
        default: return out;
    }
    BY_HANDLE_FILE_INFORMATION fi{};
    if (!GetFileInformationByHandle(h, &fi)) return std::unexpected(last_error());
    if (fi.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY) {
        out.type = FileType::directory;
        return out;
    }
    out.type = FileType::regular;
    out.size = (static_cast<std::uint64_t>(fi.nFileSizeHigh) << 32) | fi.nFileSizeLow;
    return out;
}

OsResult<std::size_t> ReadableFile::read(char* buffer, std::size_t n) {
    DWORD got = 0;
    const auto want = static_cast<DWORD>(n > 0x4000'0000u ? 0x4000'0000u : n);
    if (!ReadFile(handle_of(handle_), buffer, want, &got, nullptr)) {
        if (GetLastError() == ERROR_HANDLE_EOF || GetLastError() == ERROR_BROKEN_PIPE) return std::size_t{0};
        return std::unexpected(last_error());
    }
    return static_cast<std::size_t>(got);
}

OsResult<NewFile> NewFile::create(const std::filesystem::path& path) {
    const HANDLE h = CreateFileW(path.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW, FILE_ATTRIBUTE_NORMAL, nullptr);
    if (h == INVALID_HANDLE_VALUE) return std::unexpected(last_error());
    return NewFile(stored(h));
}

NewFile::~NewFile() {
    if (handle_ != -1) CloseHandle(handle_of(handle_));
}

OsResult<void> NewFile::write_all(std::string_view bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const std::size_t left = bytes.size() - done;
        const auto chunk = static_cast<DWORD>(left > 0x4000'0000u ? 0x4000'0000u : left);
        DWORD wrote = 0;
        if (!WriteFile(handle_of(handle_), bytes.data() + done, chunk, &wrote, nullptr))
            return std::unexpected(last_error());
        done += wrote;
    }
    return {};
}

OsResult<void> NewFile::sync_and_close() {
    const HANDLE h = handle_of(release());
    if (!FlushFileBuffers(h)) {
        const auto e = last_error();
        CloseHandle(h);
        return std::unexpected(e);
    }
    if (!CloseHandle(h)) return std::unexpected(last_error());
    return {};
}

OsResult<void> sync_file(const std::filesystem::path& path) {
    // FlushFileBuffers needs write access to the file.
    const HANDLE h = CreateFileW(path.c_str(), GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE, nullptr,
                                 OPEN_EXISTING, FILE_ATTRIBUTE_NORMAL, nullptr);
    if (h == INVALID_HANDLE_VALUE) return std::unexpected(last_error());
    if (!FlushFileBuffers(h)) {
        const auto e = last_error();
        CloseHandle(h);
        return std::unexpected(e);
    }
    CloseHandle(h);
    return {};
}

OsResult<void> replace_file(const std::filesystem::path& from, const std::filesystem::path& to) {
    // Write-through: the call returns once the move itself is on the disk.
    if (!MoveFileExW(from.c_str(), to.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH))
        return std::unexpected(last_error());
    return {};
}

OsResult<std::filesystem::path> make_private_dir(const std::string& prefix) {
    // The user's own temporary folder is private to the user already.
    std::error_code ec;
    const auto base = std::filesystem::temp_directory_path(ec);
    if (ec) return os_fail("no temporary folder: " + ec.message());
    for (int attempt = 0; attempt < 100; ++attempt) {
        LARGE_INTEGER t{};
        QueryPerformanceCounter(&t);
        const auto dir = base / (prefix + "." + std::to_string(GetCurrentProcessId()) + "-" +
                                 std::to_string(static_cast<unsigned long long>(t.QuadPart) % 1'000'000'007ULL));
        if (CreateDirectoryW(dir.c_str(), nullptr)) return dir;
        if (GetLastError() != ERROR_ALREADY_EXISTS) return std::unexpected(last_error());
    }
    return os_fail("cannot make a temporary folder in " + base.string());
}

void remove_file(const std::filesystem::path& path) noexcept { DeleteFileW(path.c_str()); }

}  // namespace tactus::platform
