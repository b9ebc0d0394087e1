// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/file_io.hpp"

#include <fstream>
#include <random>

#include "platform/durable_file.hpp"

namespace tactus {

namespace {

// What a file that is not a regular file is, in words a user knows.
std::string not_regular(platform::FileType type) {
    switch (type) {
        case platform::FileType::directory: return "is a directory, not a file";
        case platform::FileType::fifo:
            return "is a named pipe (FIFO), not a regular file: save what it carries to a file first";
        case platform::FileType::device: return "is a device, not a regular file";
        case platform::FileType::socket: return "is a socket, not a regular file";
        default: return "is not a regular file";
    }
}

// The file a write replaces: a symbolic link's final target, else the path.
// A dangling link is replaced by the file, as there is no target to keep.
std::filesystem::path write_target(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_symlink(path, ec)) return path;
    auto target = std::filesystem::canonical(path, ec);
    return ec ? path : target;
}

// The replaced file's permissions on its replacement (nothing to keep for a new file).
void keep_permissions(const std::filesystem::path& replaced, const std::filesystem::path& replacement) {
    std::error_code ec;
    const auto st = std::filesystem::status(replaced, ec);
    if (ec || !std::filesystem::exists(st)) return;
    std::filesystem::permissions(replacement, st.permissions(), std::filesystem::perm_options::replace, ec);
}

}  // namespace

Result<std::string> read_file(const std::filesystem::path& path, std::size_t max_bytes) {
    // Opened without blocking and checked before reading: a named pipe with no
    // writer would block open() and read() for ever, a device could give bytes
    // without end.
    auto file = platform::ReadableFile::open(path);
    if (!file) return fail(ErrorKind::input, "cannot open: " + file.error().what, path.string());
    const auto info = file->info();
    if (!info) return fail(ErrorKind::input, "cannot examine: " + info.error().what, path.string());
    if (info->type != platform::FileType::regular) return fail(ErrorKind::input, not_regular(info->type), path.string());
    const auto size = static_cast<std::size_t>(info->size);
    if (size > max_bytes)
        return fail(ErrorKind::input, "file is " + std::to_string(size) + " bytes, above the limit of " + std::to_string(max_bytes),
                    path.string());
    std::string bytes(size, '\0');
    std::size_t done = 0;
    while (done < size) {
        const auto n = file->read(bytes.data() + done, size - done);
        if (!n) return fail(ErrorKind::io, "read error: " + n.error().what, path.string());
        if (*n == 0) break;  // shrank while read: what is there
        done += *n;
    }
    bytes.resize(done);
    return bytes;
}

Result<void> write_file_atomic(const std::filesystem::path& asked, std::string_view bytes) {
    const auto path = write_target(asked);
    const auto dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::random_device rd;
    const auto tmp = dir / ("." + path.filename().string() + ".tmp" + std::to_string(rd()));
    auto file = platform::NewFile::create(tmp);
    if (!file) return fail(ErrorKind::io, "cannot create: " + file.error().what, tmp.string());
    if (auto w = file->write_all(bytes); !w) {
        { auto closing = std::move(*file); }
        platform::remove_file(tmp);
        return fail(ErrorKind::io, "write failed: " + w.error().what, path.string());
    }
    if (auto s = file->sync_and_close(); !s) {
        platform::remove_file(tmp);
        return fail(ErrorKind::io, "cannot flush to disk: " + s.error().what, path.string());
    }
    keep_permissions(path, tmp);
    if (auto r = platform::replace_file(tmp, path); !r) {
        platform::remove_file(tmp);
        return fail(ErrorKind::io, "cannot replace file: " + r.error().what, path.string());
    }
    return {};
}

Result<void> write_file_atomic(const std::filesystem::path& asked,
                               const std::function<Result<void>(std::ostream&)>& produce) {
    const auto path = write_target(asked);
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
        if (!out) return fail(ErrorKind::io, "cannot create: " + platform::last_error().what, tmp.string());
        if (auto ok = produce(out); !ok) return discard(ok.error());
        out.flush();
        if (!out) return discard(Error{"write failed (disk full?)", path.string(), ErrorKind::io});
    }
    // Make the data durable before the rename makes it visible.
    if (auto s = platform::sync_file(tmp); !s)
        return discard(Error{"cannot flush to disk: " + s.error().what, path.string(), ErrorKind::io});
    keep_permissions(path, tmp);
    if (auto r = platform::replace_file(tmp, path); !r)
        return discard(Error{"cannot replace file: " + r.error().what, path.string(), ErrorKind::io});
    return {};
}

}  // namespace tactus
