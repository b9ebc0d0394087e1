// SPDX-License-Identifier: GPL-3.0-or-later
#include "protocol_choice.hpp"

#include <iostream>

#include "command.hpp"
#include "profile/firmware_tables.hpp"

namespace tactus::cli {

void add_protocol_options(CLI::App& cmd, ProtocolArgs& args, std::string_view what) {
    cmd.add_option("--protocol", args.protocol,
                   "Link protocol: 3 (the reference firmware's, the default) or 2 (legacy step schedules). "
                   "Without it: 3, or 2 with a notice when the firmware cannot run the profile")
        ->check(CLI::IsMember({2, 3}));
    cmd.add_option("--firmware-tables", args.firmware_tables,
                   "The reference firmware's ramp tables (its build/ramp.json) for protocol 3 (default: the "
                   "tables the profile makes, as make -C firmware PROFILE=... builds them)" +
                       std::string(what))
        ->check(CLI::ExistingFile);
}

std::optional<machine::FirmwareTables> protocol_tables(std::string_view command, const ProtocolArgs& args,
                                                       const profile::PrinterProfile& profile) {
    const std::string name(command);
    if (!args.firmware_tables.empty() && args.protocol == 2)
        throw CommandFailed(exit_usage, name + ": --firmware-tables is protocol 3; leave it out for --protocol 2");
    if (!args.firmware_tables.empty()) return require(profile::load_firmware_tables(args.firmware_tables));
    if (args.protocol == 2) return std::nullopt;
    auto t = profile::make_firmware_tables(profile);
    if (t) return *t;
    if (args.protocol == 3)
        throw CommandFailed(exit_bad_input, name + ": --protocol 3: the reference firmware cannot run this profile: " +
                                                t.error().to_string());
    std::cerr << name << ": protocol 2 (legacy), since the reference firmware cannot run this profile ("
              << t.error().to_string() << ")" << std::endl;
    return std::nullopt;
}

}  // namespace tactus::cli
