// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/process_info.hpp"

#include <pwd.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

namespace tactus::platform {

std::string host_name() {
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0) return "localhost";
    return name;
}

std::int64_t current_process_id() { return getpid(); }

std::string user_name() {
    if (const char* u = std::getenv("USER"); u && *u) return u;
    if (const passwd* pw = getpwuid(getuid())) return pw->pw_name;
    return "uid " + std::to_string(getuid());
}

bool process_alive(std::int64_t pid) {
    if (pid <= 0 || static_cast<pid_t>(pid) != pid) return false;
    if (pid == getpid()) return true;
    return kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

bool running_as_root() { return geteuid() == 0; }

}  // namespace tactus::platform
