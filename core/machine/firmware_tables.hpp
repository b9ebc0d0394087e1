// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the reference firmware (firmware/, protocol v3) was built with: the
// S-curve ramp tables it walks from flash, the dot grids its pass records
// count in, and the backlash it adds on a reversal. profile::make_firmware_tables
// makes them from the printer profile; the firmware build (firmware/tools/
// gen-ramp.cpp) writes them into its sources and an exact copy to
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
    // T[min(k, n + 2 - k, R + 1) - 1] (docs/protocol.md, "Moves").
    [[nodiscard]] std::uint16_t interval(std::uint32_t k, std::uint32_t n) const;
    // From the move's start to its last step, in ticks.
    [[nodiscard]] std::uint64_t move_ticks(std::uint32_t n) const;
};

struct FirmwareTables {
    std::uint32_t table_id = 0;  // CRC-32 of the tables, as HELLO_REPLY reports it
    RampTable carriage;
    RampTable feed;
    // Machine cycles from the last timer event of one phase (a hammer going
    // up, the feed's last step) to the start of the next move: its first step
    // comes start_gap_ticks + T[0] after that event. The firmware schedules
    // every phase from its timer (docs/protocol.md, "Timing"): the
    // settle ends settle_ticks after a move's last step, the hammer goes up
    // hammer_ticks after it came down, exactly.
    std::uint32_t start_gap_ticks = 0;
    bool operator==(const FirmwareTables&) const = default;
};

// Machine cycles from a timer event of the firmware's schedule (the timer-2
// overflow) to the pin edge it makes: every carriage and feed step and every
// hammer going down or up, on every path of the step interrupt, whatever its
// latency (firmware/src/step.asm, EDGE_TICKS: it reads the timer and burns the
// latency's complement). The plan's times are the timer events; a pin trace's
// edge at t is the event at t - kPinEdgeTicks. controller::FirmwareTrace
// subtracts it; FirmwareEndToEnd.ThePinEdgeDelayIsTheFirmwares checks it
// against the assembled EDGE_TICKS.
inline constexpr std::uint32_t kPinEdgeTicks = 23;

// What the reference firmware's step interrupt (firmware/src/step.asm) and its
// flash impose on its ramp tables; profile::make_firmware_tables holds a
// profile to them (firmware/README.md, "Timing").
// The shortest interval the fast step-interrupt paths keep exact: a short
// move's turn and the switch to cruise end 46 cycles after their timer event
// (counted), and the next event's latency (that overrun + the instruction
// after RETI, up to 2) must stay within LAT_MAX (5): 43, and one cycle to spare.
inline constexpr std::uint32_t kMinCruiseTicks = 44;
// The slow (16-bit) path, used for the feed and for intervals over 256 ticks.
inline constexpr std::uint32_t kMinSlowTicks = 136;
// Intervals up to this many ticks take the fast path (one reload byte).
inline constexpr std::uint32_t kFastMaxTicks = 256;
inline constexpr std::uint32_t kFastBias = 7;  // bytes between the MOVC in step.asm and its table
inline constexpr std::uint32_t kMaxFastEntries = 255 - kFastBias + 1;
// Machine cycles from the last timer event of one phase to the start of a
// move: the time the main loop is given to build the move's phases
// (FirmwareTables::start_gap_ticks).
inline constexpr std::uint32_t kStartGapTicks = 3000;
// The longest ramp from rest to v_max the tables hold, in seconds.
inline constexpr double kMaxRampSeconds = 2.0;

// The v3 controller's per-strike timing (CONFIGURE): at rest `settle_ticks`
// after the move, then the hammer on for `hammer_ticks`.
struct StrikeTiming {
    std::uint16_t settle_ticks = 0;
    std::uint16_t hammer_ticks = 0;
    bool operator==(const StrikeTiming&) const = default;
};

}  // namespace tactus::machine
