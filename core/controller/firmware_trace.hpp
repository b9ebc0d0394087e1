// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The strikes the reference firmware fired, read back from the emulated chip:
// s51 writes its port 1 (firmware/README.md, "Pin map": carriage and feed
// STEP/DIR, the two hammers) and the firmware's sheet number as a
// value-change dump, and this turns the dump into the strike log the C++
// simulated controller writes. Positions are counted from the STEP and DIR
// pins, backlash steps included, exactly as the firmware counts them; the feed
// counter restarts where the sheet number becomes non-zero (SHEET_BEGIN).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "controller/sim_controller.hpp"

namespace tactus::controller {

// One edge on the step and hammer pins: the time of the firmware's timer event
// that made it, on the emulator's clock (the pin changes
// machine::kPinEdgeTicks later).
struct PinEdge {
    enum class Kind { carriage_step, feed_step, hammer_down, hammer_up };
    Kind kind;
    double time_s;
    bool operator==(const PinEdge&) const = default;
};

class FirmwareTrace {
public:
    // steps/mm map positions to millimetres for the log (x_mm, y_mm).
    FirmwareTrace(double carriage_steps_per_mm, double feed_steps_per_mm)
        : carriage_spm_(carriage_steps_per_mm), feed_spm_(feed_steps_per_mm) {}

    // VCD text in any pieces (a growing file read as it grows); appends the
    // strikes whose hammer pulse it completes (a strike is logged when its
    // hammer comes off, with the time and place it went on; times are the
    // timer events', machine::kPinEdgeTicks before the pins; a pulse under
    // 0.5 ms moves no hammer and is no strike). Steps count only while the
    // drivers are enabled (P1.6 low). Fails on a dump without port 1.
    Result<void> push(std::string_view text, std::vector<LoggedStrike>& out);

    // Also keep every rising STEP edge and every hammer edge (edges()), to
    // check the firmware's step times against a plan's.
    void keep_edges(bool keep) { keep_edges_ = keep; }
    [[nodiscard]] const std::vector<PinEdge>& edges() const { return edges_; }

    [[nodiscard]] std::int32_t carriage_step() const { return carriage_; }
    [[nodiscard]] std::int32_t feed_step() const { return feed_; }

private:
    void line(std::string_view l, std::vector<LoggedStrike>& out);
    void change(const std::string& id, std::uint32_t value, std::vector<LoggedStrike>& out);

    double carriage_spm_, feed_spm_;
    std::string pending_;  // an unfinished line
    double tick_s_ = 1e-12;
    double now_s_ = 0;
    std::string port_id_, sheet_lo_id_, sheet_hi_id_;
    std::uint32_t port_ = 0xFF;
    std::uint16_t sheet_ = 0;
    std::int32_t carriage_ = 0, feed_ = 0;
    bool in_header_ = true;
    bool keep_edges_ = false;
    std::vector<PinEdge> edges_;
    // A hammer that is on: its strike, logged when it comes off after at
    // least kMinHammerPulseS (convex, concave).
    std::optional<LoggedStrike> hammer_on_[2];
    static constexpr double kMinHammerPulseS = 0.5e-3;
};

}  // namespace tactus::controller
