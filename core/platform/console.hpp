// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The standard streams as the system has them: whether a person watches
// (a progress line redraws itself only on a terminal), and a line written in
// one call so two threads' lines never interleave.
#include <string_view>

namespace tactus::platform {

bool stderr_is_terminal();
// Writes `text` to the standard error in one call; a reader that is gone is ignored.
void write_stderr(std::string_view text);

}  // namespace tactus::platform
