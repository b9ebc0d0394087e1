// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The reference firmware's build tables (firmware/build/ramp.json) as the host
// reads them, checked against the printer profile they must have been
// generated from, and the per-strike timing a v3 controller is configured with.
#include <filesystem>
#include <string_view>

#include "common/result.hpp"
#include "machine/firmware_tables.hpp"
#include "profile/profile.hpp"

namespace tactus::profile {

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
