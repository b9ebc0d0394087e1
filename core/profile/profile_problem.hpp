// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Why a printer profile cannot be used, as data: the field to fix, what is wrong
// with it and the numbers involved. validate() words it in English (the command
// line, the logs); the desktop app words the same record in its own language.
#include <optional>
#include <string>

#include "profile/profile.hpp"

namespace tactus::profile {

enum class ProblemKind {
    out_of_range,              // value outside [limit, high]
    not_above_zero,            // value <= 0
    above_maximum,             // value > limit
    below_physical_minimum,    // 0 < value < limit: the models' numbers would overflow
    too_slow,                  // 0 < value < limit: days to plan and to emboss
    too_many_steps,            // needs `value` steps/s, the controller times `limit`
    not_above_dot_pitch,       // cell pitch `value` <= dot pitch `limit`
    not_above_cell_height,     // line pitch `value` <= cell height `limit`
    line_too_wide,             // `count` cells need `value` mm, the margins leave `limit`
    page_too_tall,             // `count` lines need `value` mm, the margins leave `limit`
    back_dots_off_paper,       // the back offset `value` puts dots off the paper
    wider_than_paper,          // the hammer offset `value` exceeds the paper's width `limit`
    finer_than_half_step,      // tolerance `value` um below half a carriage step `limit` um
};

struct ProfileProblem {
    std::string field;  // as in the JSON file: "paper.margin_left_mm"
    ProblemKind kind = ProblemKind::out_of_range;
    double value = 0;
    double limit = 0;
    double high = 0;     // out_of_range only
    int count = 0;       // line_too_wide, page_too_tall
    std::string unit;    // of value and limit: "mm", "mm/s", or empty
};

// The first constraint the planner relies on that `p` breaks, if any: one clear
// problem beats a cascade.
[[nodiscard]] std::optional<ProfileProblem> first_problem(const PrinterProfile& p);

// The problem in English, after the field's name: "is 25 mm, must be between 0 and 1 mm".
[[nodiscard]] std::string describe(const ProfileProblem& p);

}  // namespace tactus::profile
