// SPDX-License-Identifier: GPL-3.0-or-later
// FirmwareTrace on hand-written value-change dumps in s51's format: the times
// it reports are the firmware's timer events, machine::kPinEdgeTicks before
// the pins change (firmware/src/step.asm makes every step and hammer edge
// that many cycles after its event), so they compare with a plan's directly.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "controller/firmware_trace.hpp"
#include "machine/firmware_tables.hpp"
#include "machine/limits.hpp"

namespace tactus::controller {
namespace {

constexpr double kCyclePs = 1e12 / machine::kTickHz;

std::string at_cycle(long long cycle, unsigned port) {
    std::string bits;
    for (int b = 31; b >= 0; --b) bits += ((port >> b) & 1U) ? '1' : '0';
    return "#" + std::to_string(std::llround(static_cast<double>(cycle) * kCyclePs)) + "\nb" + bits + " !\n";
}

const std::string kHeader =
    "$timescale 1ps $end\n$scope module ucsim_vcd_0 $end\n$var wire 32 ! port1_value $end\n"
    "$upscope $end\n$enddefinitions $end\n";

TEST(FirmwareTrace, EdgesAndStrikesAreAtTheTimerEventsBehindThePins) {
    FirmwareTrace trace(80, 40);
    trace.keep_edges(true);
    std::vector<LoggedStrike> strikes;
    // Drivers enabled (P1.6 low), carriage away from home (P1.1): a step at
    // cycle 1000, then the convex hammer down at 5000 and up at 9000.
    const std::string vcd = kHeader + at_cycle(0, 0x02) + at_cycle(1000, 0x03) + at_cycle(1010, 0x02) +
                            at_cycle(5000, 0x12) + at_cycle(9000, 0x02);
    ASSERT_TRUE(trace.push(vcd, strikes));
    const auto& e = trace.edges();
    ASSERT_EQ(e.size(), 3U);
    const auto cycle = [](double s) { return std::llround(s * machine::kTickHz); };
    EXPECT_EQ(e[0].kind, PinEdge::Kind::carriage_step);
    EXPECT_EQ(cycle(e[0].time_s), 1000 - static_cast<long long>(machine::kPinEdgeTicks));
    EXPECT_EQ(e[1].kind, PinEdge::Kind::hammer_down);
    EXPECT_EQ(cycle(e[1].time_s), 5000 - static_cast<long long>(machine::kPinEdgeTicks));
    EXPECT_EQ(e[2].kind, PinEdge::Kind::hammer_up);
    EXPECT_EQ(cycle(e[2].time_s), 9000 - static_cast<long long>(machine::kPinEdgeTicks));
    ASSERT_EQ(strikes.size(), 1U);
    EXPECT_EQ(strikes[0].carriage_step, 1);
    EXPECT_EQ(cycle(strikes[0].time_s), 5000 - static_cast<long long>(machine::kPinEdgeTicks));
}

}  // namespace
}  // namespace tactus::controller
