// SPDX-License-Identifier: GPL-3.0-or-later
// What makes a profile physically possible. Each check names the field to fix;
// the planner may then assume every quantity is finite and in range, so no NaN
// or infinity can reach a plan.
#include <cmath>
#include <cstdio>
#include <string>

#include "machine/limits.hpp"
#include "profile/profile_json.hpp"
#include "profile/profile_problem.hpp"

namespace tactus::profile {
namespace {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

struct Checker {
    std::optional<ProfileProblem> first;
    // Records the first failure only: one clear message beats a cascade.
    void require(bool ok, ProfileProblem problem) {
        if (!first && !ok) first = std::move(problem);
    }
    void range(double v, double lo, double hi, const char* field, const char* unit = "") {
        require(std::isfinite(v) && v >= lo && v <= hi, {field, ProblemKind::out_of_range, v, lo, hi, 0, unit});
    }
    void positive(double v, double hi, const char* field, const char* unit = "") {
        require(std::isfinite(v) && v > 0 && v <= hi,
                {field, v <= 0 ? ProblemKind::not_above_zero : ProblemKind::above_maximum, v, v <= 0 ? 0 : hi, 0, 0,
                 unit});
    }
    // Above 0 and at least `lo`: a physical quantity whose tiny values pass
    // "above 0" yet make the models' numbers overflow (a 1e-300 kg head rings
    // at a frequency whose square is infinite, and the residual is NaN).
    void physical(double v, double lo, double hi, const char* field, const char* unit = "") {
        if (!(std::isfinite(v) && v > 0 && v <= hi)) return positive(v, hi, field, unit);
        require(v >= lo, {field, ProblemKind::below_physical_minimum, v, lo, 0, 0, unit});
    }
};

void check_axis(Checker& c, const Axis& a, const std::string& name) {
    // Field names are built once per axis; keep them alive for the checker's char*.
    static thread_local std::string f[5];
    f[0] = name + ".steps_per_mm";
    f[1] = name + ".v_max_mm_s";
    f[2] = name + ".a_max_mm_s2";
    f[3] = name + ".j_max_mm_s3";
    f[4] = name + ".backlash_mm";
    c.positive(a.steps_per_mm, 1e4, f[0].c_str());
    c.positive(a.v_max_mm_s, 1e4, f[1].c_str(), "mm/s");
    c.positive(a.a_max_mm_s2, 1e7, f[2].c_str(), "mm/s2");
    c.positive(a.j_max_mm_s3, 1e11, f[3].c_str(), "mm/s3");
    c.range(a.backlash_mm, 0, 1, f[4].c_str(), "mm");
    // Far slower than any embosser: a move would last days, and the planner
    // would spend as long timing its steps.
    auto at_least = [&](double v, double lo, const char* field, const char* unit) {
        c.require(!std::isfinite(v) || v <= 0 || v >= lo, {field, ProblemKind::too_slow, v, lo, 0, 0, unit});
    };
    at_least(a.v_max_mm_s, 1, f[1].c_str(), "mm/s");
    at_least(a.a_max_mm_s2, 1, f[2].c_str(), "mm/s2");
    at_least(a.j_max_mm_s3, 1, f[3].c_str(), "mm/s3");
    // The controller times each step with the 89C52 timer; it needs at least a
    // few ticks between steps to do its additions.
    const double steps_per_s = a.v_max_mm_s * a.steps_per_mm;
    c.require(!std::isfinite(steps_per_s) || steps_per_s <= machine::kMaxStepsPerSecond,
              {f[1], ProblemKind::too_many_steps, steps_per_s, machine::kMaxStepsPerSecond, 0, 0, "steps/s"});
}

}  // namespace

std::optional<ProfileProblem> first_problem(const PrinterProfile& p) {
    Checker c;
    const auto& pa = p.paper;
    const auto& g = p.geometry;
    c.positive(pa.width_mm, 2000, "paper.width_mm", "mm");
    c.positive(pa.height_mm, 5000, "paper.height_mm", "mm");
    c.range(pa.margin_left_mm, 0, pa.width_mm, "paper.margin_left_mm", "mm");
    c.range(pa.margin_right_mm, 0, pa.width_mm, "paper.margin_right_mm", "mm");
    c.range(pa.margin_top_mm, 0, pa.height_mm, "paper.margin_top_mm", "mm");
    c.range(pa.margin_bottom_mm, 0, pa.height_mm, "paper.margin_bottom_mm", "mm");

    c.positive(g.dot_pitch_mm, 20, "geometry.dot_pitch_mm", "mm");
    // Above 100 mm is out of range; at or below the dot pitch, neighbouring cells touch.
    if (g.cell_pitch_mm > 100) c.range(g.cell_pitch_mm, g.dot_pitch_mm, 100, "geometry.cell_pitch_mm", "mm");
    c.require(g.cell_pitch_mm > g.dot_pitch_mm,
              {"geometry.cell_pitch_mm", ProblemKind::not_above_dot_pitch, g.cell_pitch_mm, g.dot_pitch_mm, 0, 0, "mm"});
    const int rows = g.eight_dot ? 4 : 3;
    const double cell_h = (rows - 1) * g.dot_pitch_mm;
    if (g.line_pitch_mm > 200) c.range(g.line_pitch_mm, cell_h, 200, "geometry.line_pitch_mm", "mm");
    c.require(g.line_pitch_mm > cell_h,
              {"geometry.line_pitch_mm", ProblemKind::not_above_cell_height, g.line_pitch_mm, cell_h, 0, 0, "mm"});
    c.range(g.cells_per_line, 1, 1000, "geometry.cells_per_line");
    c.range(g.lines_per_page, 1, 1000, "geometry.lines_per_page");
    if (c.first) return c.first;

    const double line_w = (g.cells_per_line - 1) * g.cell_pitch_mm + g.dot_pitch_mm;
    const double room_w = pa.width_mm - pa.margin_left_mm - pa.margin_right_mm;
    c.require(line_w <= room_w + 1e-9,
              {"geometry.cells_per_line", ProblemKind::line_too_wide, line_w, room_w, 0, g.cells_per_line, "mm"});
    const double page_h = (g.lines_per_page - 1) * g.line_pitch_mm + (rows - 1) * g.dot_pitch_mm;
    const double room_h = pa.height_mm - pa.margin_top_mm - pa.margin_bottom_mm;
    c.require(page_h <= room_h + 1e-9,
              {"geometry.lines_per_page", ProblemKind::page_too_tall, page_h, room_h, 0, g.lines_per_page, "mm"});
    if (g.interpoint) {
        // The back grid, mirrored and offset, must still land on the paper.
        const double x_lo = g.back_mirror == BackMirror::x ? pa.width_mm - pa.margin_left_mm - line_w
                                                          : pa.margin_left_mm;
        const double y_lo = g.back_mirror == BackMirror::y ? pa.height_mm - pa.margin_top_mm - page_h
                                                          : pa.margin_top_mm;
        c.require(x_lo + g.back_offset_x_mm >= 0 && x_lo + line_w + g.back_offset_x_mm <= pa.width_mm,
                  {"geometry.back_offset_x_mm", ProblemKind::back_dots_off_paper, g.back_offset_x_mm, 0, 0, 0, "mm"});
        c.require(y_lo + g.back_offset_y_mm >= 0 && y_lo + page_h + g.back_offset_y_mm <= pa.height_mm,
                  {"geometry.back_offset_y_mm", ProblemKind::back_dots_off_paper, g.back_offset_y_mm, 0, 0, 0, "mm"});
    }

    c.require(std::isfinite(p.head.concave_offset_mm) &&
                  std::fabs(p.head.concave_offset_mm) < pa.width_mm,
              {"head.concave_offset_mm", ProblemKind::wider_than_paper, p.head.concave_offset_mm, pa.width_mm, 0, 0, "mm"});
    c.physical(p.head.dwell_s, 1e-5, 10, "head.dwell_s", "s");

    c.range(p.motion.step_tolerance, 0, 0.5, "motion.step_tolerance");
    check_axis(c, p.carriage, "carriage");
    check_axis(c, p.feed, "feed");

    const auto& d = p.dynamics;
    // The bounds are physical for a desktop embosser's head and drive, with
    // room on both sides; within them every estimate is a finite number.
    c.physical(d.head_mass_kg, 1e-3, 1000, "dynamics.head_mass_kg", "kg");
    c.physical(d.belt_stiffness_n_m, 1, 1e9, "dynamics.belt_stiffness_n_m", "N/m");
    c.range(d.damping_ratio, 0, 0.99, "dynamics.damping_ratio");
    c.range(d.rotor_inertia_kg_m2, 0, 1, "dynamics.rotor_inertia_kg_m2", "kg m2");
    if (d.rotor_inertia_kg_m2 > 0) {
        c.physical(d.rotor_inertia_kg_m2, 1e-9, 1, "dynamics.rotor_inertia_kg_m2", "kg m2");
        c.physical(d.pulley_radius_m, 1e-4, 1, "dynamics.pulley_radius_m", "m");
        c.physical(d.motor_stiffness_nm_rad, 1e-3, 1e6, "dynamics.motor_stiffness_nm_rad", "N m/rad");
    }

    const auto& v = p.vibration;
    c.range(v.damping_band, 0, 0.95, "vibration.damping_band");
    c.range(v.frequency_band, 0, 0.9, "vibration.frequency_band");
    c.positive(v.tolerance_um, 1e5, "vibration.tolerance_um", "um");
    // The head can only stop on whole steps: an error tolerance finer than half a
    // step is unreachable however slowly it moves.
    const double half_step_um = 500.0 / p.carriage.steps_per_mm;
    c.require(!(v.tolerance_um < half_step_um),
              {"vibration.tolerance_um", ProblemKind::finer_than_half_step, v.tolerance_um, half_step_um, 0, 0, "um"});

    // Graphics: bounds from the cell's dot pitch. Along a line, no closer than
    // 1.2 half pitches: half a pitch is the hammer's least distance between
    // any two dots (plan::min_dot_separation_mm), and the fifth more keeps
    // neighbours apart after each is rounded onto the grid. No wider than two
    // pitches: beyond that a finger reads a row of dots, not a line.
    const auto& gr = p.graphic;
    const double pitch = g.dot_pitch_mm;
    c.range(gr.line_dot_spacing_mm, 0.6 * pitch, 2 * pitch, "graphic.line_dot_spacing_mm", "mm");
    // A dotted line and a dashed line's gaps must be told from a solid line:
    // dots half as far apart again, gaps of at least two spacings (one dot left out).
    c.range(gr.dotted_dot_spacing_mm, 1.5 * gr.line_dot_spacing_mm, 20, "graphic.dotted_dot_spacing_mm", "mm");
    c.range(gr.dash_gap_mm, 2 * gr.line_dot_spacing_mm, 30, "graphic.dash_gap_mm", "mm");
    // A texture's rows at least a dot pitch apart (closer, the area feels solid)
    // and its dots no closer than a line's.
    c.range(gr.texture_pitch_mm, pitch, 50, "graphic.texture_pitch_mm", "mm");
    c.range(gr.texture_dot_spacing_mm, 0.6 * pitch, 50, "graphic.texture_dot_spacing_mm", "mm");
    return c.first;
}

std::string describe(const ProfileProblem& p) {
    const auto u = p.unit.empty() ? std::string() : " " + p.unit;
    const auto is = "is " + num(p.value) + u;
    switch (p.kind) {
        case ProblemKind::out_of_range: return is + ", must be between " + num(p.limit) + " and " + num(p.high) + u;
        case ProblemKind::not_above_zero: return is + ", must be above 0";
        case ProblemKind::above_maximum: return is + ", must not exceed " + num(p.limit) + u;
        case ProblemKind::below_physical_minimum: return is + ", below the physical minimum of " + num(p.limit) + u;
        case ProblemKind::too_slow:
            return is + ", below " + num(p.limit) + u + ": motion that slow would take days to plan and to emboss";
        case ProblemKind::too_many_steps:
            return "needs " + num(p.value) + " steps/s, more than the controller can time (" + num(p.limit) +
                   " steps/s, 8 timer ticks per step)";
        case ProblemKind::not_above_dot_pitch:
            return is + ", must exceed the dot pitch (" + num(p.limit) + u + ") so neighbouring cells stay apart";
        case ProblemKind::not_above_cell_height: return is + ", must exceed the cell height (" + num(p.limit) + u + ")";
        case ProblemKind::line_too_wide:
            return std::to_string(p.count) + " cells need " + num(p.value) + u + " but the paper leaves " +
                   num(p.limit) + u + " between the margins";
        case ProblemKind::page_too_tall:
            return std::to_string(p.count) + " lines need " + num(p.value) + u + " but the paper leaves " +
                   num(p.limit) + u + " between the margins";
        case ProblemKind::back_dots_off_paper: return is + ", which puts back-side dots off the paper";
        case ProblemKind::wider_than_paper:
            return is + ", wider than the paper (" + num(p.limit) + u + "): one hammer could never reach it";
        case ProblemKind::finer_than_half_step:
            return is + ", finer than half a carriage step (" + num(p.limit) + u + "): unreachable at any speed";
    }
    return is;
}

Result<void> validate(const PrinterProfile& p) {
    if (auto problem = first_problem(p)) return fail(ErrorKind::input, describe(*problem), "field " + problem->field);
    return {};
}

}  // namespace tactus::profile
