// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstddef>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

#include "common/result.hpp"

namespace tactus {

// Reads a whole file as bytes. Refuses files above `max_bytes` with a clear error
// instead of exhausting memory on a mistaken argument.
Result<std::string> read_file(const std::filesystem::path& path,
                              std::size_t max_bytes = std::size_t{512} << 20);

// Writes atomically: a temporary file in the same directory, fsync, rename.
// A crash leaves either the old file or the new one, never half of either.
// A path that is a symbolic link writes its target, the link kept (a teacher's
// file linked from a shared folder stays linked), and the file replaced keeps
// its permissions (one made private stays private).
Result<void> write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

// The same for output too big to hold in memory: `produce` writes into a stream
// on the temporary file; its error (or a write error) leaves the old file alone.
Result<void> write_file_atomic(const std::filesystem::path& path,
                               const std::function<Result<void>(std::ostream&)>& produce);

}  // namespace tactus
