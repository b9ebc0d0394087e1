// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the reference firmware (firmware/, protocol v3) was built with: the
// S-curve ramp tables it walks from flash, the dot grids its pass records
// count in, and the backlash it adds on a reversal. firmware/tools/gen-ramp.py
// generates them from the printer profile and writes an exact copy to
// build/ramp.json, which profile::load_firmware_tables reads. The planner plans
// v3 jobs with these tables (table moves), so its step times are the
// firmware's to the machine cycle; HELLO_REPLY's table id must match.
#include <cstdint>
#include <vector>

namespace tactus::machine {

struct RampTable {
    // intervals[0..R-1]: timer ticks before steps 1..R of the ramp from rest;
    // intervals[R]: the cruise interval.
    std::vector<std::uint16_t> intervals;
    std::uint32_t grid_steps = 1;      // a pass record's distances count in these
    std::uint32_t backlash_steps = 0;  // added to a move that reverses the axis
    bool operator==(const RampTable&) const = default;

    // The interval (ticks) before step k (1-based) of a move of n steps:
    // T[min(k, n + 2 - k, R + 1) - 1] (firmware/PROTOCOL-v3.md, "Moves").
    [[nodiscard]] std::uint16_t interval(std::uint32_t k, std::uint32_t n) const;
    // From the move's start to its last step, in ticks.
    [[nodiscard]] std::uint64_t move_ticks(std::uint32_t n) const;
};

struct FirmwareTables {
    std::uint32_t table_id = 0;  // CRC-32 of the tables, as HELLO_REPLY reports it
    RampTable carriage;
    RampTable feed;
    bool operator==(const FirmwareTables&) const = default;
};

// The v3 controller's per-strike timing (CONFIGURE): at rest `settle_ticks`
// after the move, then the hammer on for `hammer_ticks`.
struct StrikeTiming {
    std::uint16_t settle_ticks = 0;
    std::uint16_t hammer_ticks = 0;
    bool operator==(const StrikeTiming&) const = default;
};

// The reference firmware's executor runs in its main loop, between the timed
// phases the step interrupt runs: these are the machine cycles it adds, as
// measured in s51 (tests/link/firmware_emulator_e2e_test.cpp, from the pin
// trace, mean of 38 to 44 strikes at 9600 baud). They are not exact: the main
// loop also decodes frames, so each varies by about +-300 cycles. The planner
// adds them so a plan's sheet time is the emulated one; the step times inside
// a move are the table's exactly.
struct FirmwareLatency {
    std::uint16_t move_start_ticks = 1840;   // from the previous phase's end to a move's start (building its phases)
    std::uint16_t settle_start_ticks = 550;  // from a move's last step to the settle's start
    std::uint16_t hammer_end_ticks = 385;    // the hammer stays on this much longer than CONFIGURE's pulse
};
inline constexpr FirmwareLatency kFirmwareLatency{};

}  // namespace tactus::machine
