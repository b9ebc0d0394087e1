// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/runner_token.hpp"

#include <charconv>
#include <cstdint>

#include "platform/process_info.hpp"

namespace tactus::spool {

std::string this_runner_token() {
    return platform::host_name() + ":" + std::to_string(platform::current_process_id());
}

std::string this_user_name() { return platform::user_name(); }

bool runner_alive(std::string_view token) {
    const auto colon = token.rfind(':');
    if (colon == std::string_view::npos) return false;
    if (token.substr(0, colon) != platform::host_name()) return true;
    std::int64_t pid = 0;
    const auto digits = token.substr(colon + 1);
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), pid);
    if (ec != std::errc{} || end != digits.data() + digits.size() || pid <= 0) return false;
    return platform::process_alive(pid);
}

}  // namespace tactus::spool
