// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// --profile for the commands that need a printer profile (plan, vibration).
#include <string>

#include "command.hpp"
#include "profile/profile_json.hpp"

namespace tactus::cli {

// The bundled default when `path` is empty, else the file, validated.
inline profile::PrinterProfile load_profile_arg(const std::string& path) {
    if (path.empty()) return profile::default_profile();
    return require(profile::load_profile(path), exit_bad_input);
}

}  // namespace tactus::cli
