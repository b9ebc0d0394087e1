// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli profile: print the bundled default printer profile, or check one.
#include <iostream>

#include "command.hpp"
#include "profile_arg.hpp"

namespace tactus::cli {

void add_profile_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("profile", "Printer profiles (JSON): print the default, check a file");
    cmd->require_subcommand(1);
    cmd->add_subcommand("default", "Print the bundled default profile (A4, 27x24, interpoint)")
        ->callback([] { std::cout << profile::to_json(profile::default_profile()).dump(2) << '\n'; });
    auto* check = cmd->add_subcommand("check", "Validate a profile file; errors name the field");
    static std::string path;
    check->add_option("file", path, "Profile JSON")->required();
    check->callback([] {
        const auto p = load_profile_arg(path);
        std::cout << path << ": ok (" << p.name << ")\n";
    });
}

}  // namespace tactus::cli
