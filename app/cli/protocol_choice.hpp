// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which link protocol a command plans for or speaks. Protocol 3, the
// reference firmware's, is the default everywhere (plan, plan files, emboss,
// its dry run, sim): it is planned with the firmware's ramp tables, from
// --firmware-tables (a firmware build's ramp.json) or made from the profile as
// `make -C firmware PROFILE=...` makes them. Protocol 2 is the legacy one,
// spoken only where asked for (--protocol 2, `sim?protocol=2`), or, with a
// one-line notice, when the firmware cannot run the profile.
#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "machine/firmware_tables.hpp"
#include "profile/profile.hpp"

namespace tactus::cli {

struct ProtocolArgs {
    int protocol = 0;             // 0: 3 when the firmware can run the profile, else 2; 2 or 3: that one
    std::string firmware_tables;  // a firmware build's ramp.json (protocol 3)
};

// --protocol and --firmware-tables on `cmd`; `what` ends the tables' help text.
void add_protocol_options(CLI::App& cmd, ProtocolArgs& args, std::string_view what);

// The tables for protocol 3, or none for protocol 2. `command` names the
// command in errors and the notice. Usage error for --protocol 2 with
// --firmware-tables; bad input for --protocol 3 with a profile the firmware
// cannot run.
std::optional<machine::FirmwareTables> protocol_tables(std::string_view command, const ProtocolArgs& args,
                                                       const profile::PrinterProfile& profile);

}  // namespace tactus::cli
