// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/console.hpp"

#include <unistd.h>

namespace tactus::platform {

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

void write_stderr(std::string_view text) { (void)!::write(STDERR_FILENO, text.data(), text.size()); }

void binary_standard_streams() {}

}  // namespace tactus::platform
