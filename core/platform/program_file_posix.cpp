// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/program_file.hpp"

#include <unistd.h>
#ifdef __APPLE__
#include <mach-o/dyld.h>
#endif

#include <cstdint>
#include <vector>

namespace tactus::platform {

OsResult<std::filesystem::path> program_file() {
#ifdef __APPLE__
    // macOS has no /proc: dyld knows the path the program was started by.
    std::uint32_t size = 0;
    _NSGetExecutablePath(nullptr, &size);
    std::vector<char> buffer(size + 1, '\0');
    if (_NSGetExecutablePath(buffer.data(), &size) != 0) return os_fail("the program's path is not known");
    std::error_code ec;
    auto real = std::filesystem::canonical(buffer.data(), ec);
    return ec ? std::filesystem::path(buffer.data()) : real;
#else
    // readlink does not say whether it cut the name short: grow until it fits.
    for (std::size_t size = 256; size <= 65536; size *= 2) {
        std::vector<char> buffer(size);
        const auto n = ::readlink("/proc/self/exe", buffer.data(), buffer.size());
        if (n < 0) return std::unexpected(last_error());
        if (static_cast<std::size_t>(n) < buffer.size())
            return std::filesystem::path(std::string(buffer.data(), static_cast<std::size_t>(n)));
    }
    return os_fail("the program's path is longer than 64 KiB");
#endif
}

}  // namespace tactus::platform
