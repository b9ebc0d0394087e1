// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/runner_token.hpp"

#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdlib>
#include <pwd.h>
#include <unistd.h>

namespace tactus::spool {
namespace {

std::string host_name() {
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0) return "localhost";
    return name;
}

}  // namespace

std::string this_runner_token() { return host_name() + ":" + std::to_string(getpid()); }

std::string this_user_name() {
    if (const char* u = std::getenv("USER"); u && *u) return u;
    if (const passwd* pw = getpwuid(getuid())) return pw->pw_name;
    return "uid " + std::to_string(getuid());
}

bool runner_alive(std::string_view token) {
    const auto colon = token.rfind(':');
    if (colon == std::string_view::npos) return false;
    if (token.substr(0, colon) != host_name()) return true;
    pid_t pid = 0;
    const auto digits = token.substr(colon + 1);
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), pid);
    if (ec != std::errc{} || end != digits.data() + digits.size() || pid <= 0) return false;
    if (pid == getpid()) return true;
    return kill(pid, 0) == 0 || errno == EPERM;
}

}  // namespace tactus::spool
