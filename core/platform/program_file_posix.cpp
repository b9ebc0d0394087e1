// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/program_file.hpp"

#include <unistd.h>

#include <vector>

namespace tactus::platform {

OsResult<std::filesystem::path> program_file() {
    // readlink does not say whether it cut the name short: grow until it fits.
    for (std::size_t size = 256; size <= 65536; size *= 2) {
        std::vector<char> buffer(size);
        const auto n = ::readlink("/proc/self/exe", buffer.data(), buffer.size());
        if (n < 0) return std::unexpected(last_error());
        if (static_cast<std::size_t>(n) < buffer.size())
            return std::filesystem::path(std::string(buffer.data(), static_cast<std::size_t>(n)));
    }
    return os_fail("the program's path is longer than 64 KiB");
}

}  // namespace tactus::platform
