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
// Standard input and output carry bytes as they are: Windows would otherwise
// turn "\n" into "\r\n" on the way out (a plan, JSON or a BRF would differ
// from the same output on POSIX, and a BRF's own "\r\n" would become
// "\r\r\n"). Nothing to do on POSIX.
void binary_standard_streams();

}  // namespace tactus::platform
