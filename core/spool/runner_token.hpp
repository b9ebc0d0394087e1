// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Who runs a printer: "host:pid". A holder on this host whose process is gone
// is dead (kill -9 leaves no chance to clean up, so liveness is checked, not
// announced); a holder on another host is trusted to be alive.
#include <string>
#include <string_view>

namespace tactus::spool {

std::string this_runner_token();
// Who submits a job from this process: $USER, else the account name, else "uid N".
std::string this_user_name();
bool runner_alive(std::string_view token);

}  // namespace tactus::spool
