// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the planner's files share and nobody else sees: a dot to strike, the
// table of every dot position of the profile's page, the sheet's dots in
// striking order, and the carriage's reversal rule.
#include <cstdint>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "common/result.hpp"
#include "layout/page.hpp"
#include "motion/steps.hpp"
#include "plan/geometry.hpp"
#include "plan/planner.hpp"
#include "profile/profile.hpp"

namespace tactus::plan {

// One dot to strike, with where the feed and the head must stand for it.
struct Planner::Hit {
    std::int32_t feed_step = 0;
    std::int32_t head_step = 0;
    Side side = Side::front;
    DotPlace place;
};

// Every dot position of the profile's page on either side, computed once per
// planner (the same make_hit, so the same numbers): a sheet's dots are then
// looked up, not placed again.
struct Planner::HitTable {
    int lines = 0, cells = 0;
    std::vector<Hit> hits[2];  // [side][(line * cells + cell) * 8 + dot - 1]
    HitTable(const profile::PrinterProfile& p, const motion::StepAxis& carriage, const motion::StepAxis& feed);
    // The dot's hit; nullptr outside the profile's page (a layout not checked against it).
    [[nodiscard]] const Hit* find(Side side, std::size_t line, std::size_t cell, int dot) const {
        if (line >= static_cast<std::size_t>(lines) || cell >= static_cast<std::size_t>(cells) || dot < 1 || dot > 8)
            return nullptr;
        return &hits[side == Side::front ? 0 : 1][(line * static_cast<std::size_t>(cells) + cell) * 8 +
                                                  static_cast<std::size_t>(dot - 1)];
    }
};

// The carriage moves a SheetQueue's planners share (thread-safe).
struct Planner::MoveCache {
    std::mutex mutex;
    std::unordered_map<std::uint32_t, motion::StepMove> moves;  // by carriage steps
};

// Every dot of one sheet, sorted by feed position then carriage position.
// Returns a reference to a buffer of this thread that the next call reuses
// (a sheet's dots without a reallocation per sheet).
Result<const std::vector<Planner::Hit>*> collect_hits(const profile::PrinterProfile& p,
                                                      const layout::PagedDocument& doc, std::size_t sheet_number,
                                                      const motion::StepAxis& carriage, const motion::StepAxis& feed,
                                                      bool check, const Planner::HitTable* table = nullptr);

// The carriage steps from the stop `cur` to the next, for `dot`: the command
// stops `aim` steps past the dot in the direction it moves
// (MoveTuner::aim_steps; 0 for table moves: on the dot), a head lagging
// behind it reaching the dot sooner; it does not move when it is on (or
// aimed at) the dot already. The sources' reversal test on the last,
// current and next stops (a reversal takes up the backlash). Moves the stops
// on (prev, cur) when the head moves, and sets `aimed` to cur less the dot.
std::int32_t head_move(std::int32_t& prev, std::int32_t& cur, std::int32_t& aimed, std::int32_t dot,
                       std::int32_t aim, std::int32_t backlash);

}  // namespace tactus::plan
