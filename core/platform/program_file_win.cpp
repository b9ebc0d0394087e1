// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/program_file.hpp"

#include <windows.h>

#include <string>


namespace tactus::platform {

OsResult<std::filesystem::path> program_file() {
    // GetModuleFileNameW fills the buffer and returns its size when the name
    // is cut short (ERROR_INSUFFICIENT_BUFFER): grow until it fits.
    for (DWORD size = 260; size <= 32768; size *= 2) {
        std::wstring buffer(size, L'\0');
        const DWORD n = GetModuleFileNameW(nullptr, buffer.data(), size);
        if (n == 0) return std::unexpected(last_error());
        if (n < size) {
            buffer.resize(n);
            return std::filesystem::path(buffer);
        }
    }
    return os_fail("the program's path is longer than 32767 characters");
}

}  // namespace tactus::platform
