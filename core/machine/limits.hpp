// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the 89C52 imposes on every stage above it: its timer clock, the fixed
// point its step interrupt adds in, and the fastest step it can fire. The
// profile validates against these and the planner plans in them, so both read
// them from here (docs/architecture.md).
#include <cstdint>

namespace tactus::machine {

// Timer ticks: the 11.0592 MHz crystal divided by the 8051's 12 clocks per
// machine cycle.
inline constexpr double kTickHz = 11'059'200.0 / 12.0;

// Step intervals are Q16.16 ticks: the step interrupt adds the 16-bit fraction
// into an accumulator and loads its timer with the integer part plus the carry.
inline constexpr int kStepFractionBits = 16;

// Segment intervals and adds lie on a grid of 2^0..2^15 Q16.16 units: the
// planner picks the coarsest that fits, the protocol omits the zero low bits.
inline constexpr unsigned kMaxGridShift = 15;

// The shortest step interval the step interrupt sustains, in timer ticks.
inline constexpr std::uint32_t kMinTicksPerStep = 8;
inline constexpr double kMaxStepsPerSecond = kTickHz / kMinTicksPerStep;

}  // namespace tactus::machine
