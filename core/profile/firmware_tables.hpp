// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The reference firmware's build tables (firmware/build/ramp.json) as the host
// reads them, checked against the printer profile they must have been
// generated from, and the per-strike timing a v3 controller is configured with.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "machine/firmware_tables.hpp"
#include "profile/profile.hpp"

namespace tactus::profile {

// The reference firmware's tables for this profile: the S-curve ramp from
// rest to v_max of each axis as step intervals (timer ticks), integrated as
// docs/protocol.md states it, the dot grids and the backlash in whole
// steps, and their identity (CRC-32), which HELLO_REPLY reports. Refused
// (ErrorKind::input) when the firmware could not run the profile: a step
// rate above what its interrupt sustains, a ramp its tables cannot hold, a
// distance that is not whole steps; the error names the field and the limit.
// The one copy of the rule: the firmware build writes its sources with it
// (firmware/tools/gen-ramp.cpp), the simulated controller speaks protocol 3
// with it, the host plans with it.
Result<machine::FirmwareTables> make_firmware_tables(const PrinterProfile& p);

// The tables' identity: CRC-32 of their text (docs/protocol.md).
std::uint32_t table_identity(const machine::FirmwareTables& t);
// The first carriage entry that the fast (one reload byte) path walks.
std::uint32_t fast_from(const machine::FirmwareTables& t);

// The firmware build's generated sources for these tables: ramp.h,
// ramp_tables.c, ramp_up.inc, ramp_dn.inc, ramp_eq.inc and ramp.json (the
// host's copy, read by load_firmware_tables). `profile_file` names the
// profile in ramp.h's banner.
struct GeneratedFile {
    std::string name;
    std::string text;
};
std::vector<GeneratedFile> firmware_build_files(const machine::FirmwareTables& t, std::string_view profile_file);
// ramp.json's text: the host's copy of a firmware build's tables, and what a
// protocol-3 plan file carries (parse_firmware_tables reads it back).
std::string ramp_json(const machine::FirmwareTables& t);
// One line: ramp lengths, cruise rates, grids and id.
std::string describe_firmware_tables(const machine::FirmwareTables& t, const PrinterProfile& p);

// Reads ramp.json; errors name the file and the field.
Result<machine::FirmwareTables> parse_firmware_tables(std::string_view text);
Result<machine::FirmwareTables> load_firmware_tables(const std::filesystem::path& path);

// The tables must be the profile's: the cruise interval from v_max and
// steps/mm, the backlash in whole steps. A mismatch names the profile field
// ("the firmware was built for another profile").
Result<void> check_firmware_tables(const machine::FirmwareTables& t, const PrinterProfile& p);

// Settle and hammer pulse of a v3 strike, in timer ticks. The settle waits out
// four time constants of the head-on-belt mode (1 / (zeta omega_n), one-mass
// model: omega_n = sqrt(belt_stiffness / head_mass)), where its ringing has
// decayed to 2 %; the hammer pulse is head.dwell_s (controller_config).
machine::StrikeTiming strike_timing(const PrinterProfile& p);

}  // namespace tactus::profile
