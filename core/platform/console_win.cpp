// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/console.hpp"

#include <windows.h>

#include <fcntl.h>
#include <io.h>
#include <cstdio>

namespace tactus::platform {

bool stderr_is_terminal() {
    DWORD mode = 0;
    return GetConsoleMode(GetStdHandle(STD_ERROR_HANDLE), &mode) != 0;
}

void write_stderr(std::string_view text) {
    DWORD wrote = 0;
    (void)WriteFile(GetStdHandle(STD_ERROR_HANDLE), text.data(), static_cast<DWORD>(text.size()), &wrote, nullptr);
}

void binary_standard_streams() {
    ::_setmode(::_fileno(stdin), _O_BINARY);
    ::_setmode(::_fileno(stdout), _O_BINARY);
}

}  // namespace tactus::platform
