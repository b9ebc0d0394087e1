// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli plan: where the hammers stop, how long the job takes, and how much
// the head still rings when it strikes. Sheets are planned and printed one at a
// time, so a whole book needs no more memory than one sheet. `--json` prints a
// plan file (plan/plan_file.hpp) that `emboss --plan` accepts, with the
// analysis added to each pass and sheet and at the end.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "conflict_warnings.hpp"
#include "encode/messages.hpp"
#include "encode/stream.hpp"
#include "layout_args.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/plan_file.hpp"
#include "plan/planner.hpp"
#include "profile/firmware_tables.hpp"
#include "profile_arg.hpp"
#include "protocol_choice.hpp"

namespace tactus::cli {
namespace {

// The pass's step schedule as the protocol sends it: its MOVE ops, in bytes.
std::size_t schedule_bytes(const plan::Pass& p) {
    std::size_t n = encode::move_bytes(p.feed);
    for (const auto& m : p.moves) n += encode::move_bytes(m);
    return n;
}

struct PlanArgs {
    LayoutArgs layout;
    std::string profile;
    bool json = false;
    ProtocolArgs protocol;
};

// What `plan --json` adds to a pass of the plan file.
nlohmann::json pass_analysis(const plan::Pass& p, std::size_t bytes) {
    nlohmann::json strikes = nlohmann::json::array();
    double worst = 0;
    for (const auto& s : p.strikes) {
        strikes.push_back(s.paper_x_mm);
        worst = std::max(worst, s.worst_residual_um);
    }
    return {{"strikes_mm", strikes},
            {"lower_bound_s", p.lower_bound_s},
            {"feed_steps", p.feed.steps},
            {"segments", p.segments},
            {"schedule_bytes", bytes},
            {"worst_residual_um", worst}};
}

nlohmann::json tuning_json(const estimate::MoveTuner& t) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& [steps, m] : t.decisions()) {
        const auto& c = m.choice;
        out.push_back({{"steps", steps},
                       {"distance_mm", c.distance_mm},
                       {"profile", profile::to_string(c.shape)},
                       {"shaper", profile::to_string(c.shaper)},
                       {"speed_scale", c.speed_scale},
                       {"settle_s", c.settle_s},
                       {"duration_s", c.duration_s},
                       {"residual_um", c.residual_um},
                       {"worst_residual_um", c.worst_residual_um},
                       {"why", c.why}});
    }
    return out;
}

void run_plan(const PlanArgs& a) {
    const auto prof = load_profile_arg(a.profile);
    const auto options = a.layout.pipeline_options(prof);
    // Protocol 3: the plan `emboss` makes for the reference firmware
    // (spool::make_firmware_print_job), its table moves timed as it runs them.
    plan::PlanOptions options_plan;
    options_plan.firmware = protocol_tables("plan", a.protocol, prof);
    const auto doc = lay_out_for_cli(a.layout, options, &prof, options_plan.firmware, !options_plan.firmware);
    warn_about_conflicts(doc, prof);
    // A plan file's tables must be its profile's (plan_from_json checks them).
    if (options_plan.firmware) require(profile::check_firmware_tables(*options_plan.firmware, prof), exit_bad_input);
    const bool firmware = options_plan.firmware.has_value();
    auto planner = require(plan::Planner::create(prof, options_plan));
    auto& out = std::cout;
    if (a.json) {
        // The plan file's head, then its sheets one at a time.
        auto head = plan::plan_file_head(prof, options_plan.firmware).dump();
        head.pop_back();  // the closing brace: the sheets follow
        out << head << ",\"sheets\":[";
    }
    std::size_t passes = 0;
    std::size_t total_bytes = 0;
    // Sheets planned ahead on the machine's cores, handed out in order (the same plan).
    plan::SheetQueue sheets(planner, doc);
    for (std::size_t s = 1; s <= doc.sheet_count(); ++s) {
        auto sheet = sheets.next();
        if (!sheet) fail_with(exit_bad_input, located(sheet.error(), a.layout.file));
        passes += sheet->passes.size();
        nlohmann::json sj = a.json ? plan::sheet_to_json(*sheet) : nlohmann::json{};
        for (std::size_t i = 0; i < sheet->passes.size(); ++i) {
            const std::size_t bytes = schedule_bytes(sheet->passes[i]);
            total_bytes += bytes;
            if (a.json) sj["passes"][i].update(pass_analysis(sheet->passes[i], bytes));
            // Protocol 2's MOVE bytes mean nothing to the firmware: its passes
            // are pass records (bench/firmware/bytes_per_strike.py counts them).
            if (a.json && firmware) sj["passes"][i].erase("schedule_bytes");
        }
        if (!a.json) continue;
        sj["lower_bound_s"] = sheet->lower_bound_s;
        out << (s > 1 ? "," : "") << sj.dump();
    }
    const auto& t = planner.totals();
    const double ratio = t.lower_bound_s > 0 ? t.duration_s / t.lower_bound_s : 1.0;
    if (a.json) {
        out << "],\"duration_s\":" << nlohmann::json(t.duration_s).dump() << ",\"totals\":"
            << nlohmann::json{{"duration_s", t.duration_s},
                              {"lower_bound_s", t.lower_bound_s},
                              {"plan_over_lower_bound", ratio},
                              {"strikes", t.strikes},
                              {"passes", passes},
                              {"sheets", doc.sheet_count()},
                              {"max_residual_um", t.max_residual_um},
                              {"max_worst_residual_um", t.max_worst_residual_um},
                              {"tolerance_um", prof.vibration.tolerance_um},
                              {"strikes_over_tolerance", t.strikes_over_tolerance},
                              {"segments", t.segments},
                              {"schedule_bytes", firmware ? nlohmann::json() : nlohmann::json(total_bytes)}}
                   .dump()
            << ",\"tuning\":" << tuning_json(planner.tuner()).dump() << "}\n";
        return;
    }
    const auto hms = [](double s) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%d:%02d:%04.1f", static_cast<int>(s / 3600),
                      static_cast<int>(s / 60) % 60, s - 60 * static_cast<int>(s / 60));
        return std::string(buf);
    };
    std::printf("profile:          %s\n", prof.name.c_str());
    std::printf("sheets / passes:  %zu / %zu, %zu strikes\n", doc.sheet_count(), passes, t.strikes);
    std::printf("duration:         %s (%.1f s)\n", hms(t.duration_s).c_str(), t.duration_s);
    std::printf("lower bound:      %s (%.1f s): plan / bound = %.3f\n", hms(t.lower_bound_s).c_str(),
                t.lower_bound_s, ratio);
    std::printf("residual:         %.2f um nominal, %.2f um worst case in the band (tolerance %.1f um)\n",
                t.max_residual_um, t.max_worst_residual_um, prof.vibration.tolerance_um);
    if (t.strikes_over_tolerance)
        std::printf("WARNING:          %zu strikes over tolerance (profile and shaper fixed by the profile)\n",
                    t.strikes_over_tolerance);
    if (firmware) {
        std::printf("firmware tables:  %08x (every move a table move; %u cycles before each move)\n",
                    options_plan.firmware->table_id, options_plan.firmware->start_gap_ticks);
        return;
    }
    std::printf("step schedule:    %zu segments, %zu bytes\n", t.segments, total_bytes);
    std::printf("moves chosen (carriage steps: profile/shaper, speed, settle, duration, worst residual):\n");
    for (const auto& [steps, m] : planner.tuner().decisions()) {
        const auto& c = m.choice;
        std::printf("  %6u  %s/%s  %3.0f%%  %4.1f ms  %7.2f ms  %6.2f um\n", steps,
                    profile::to_string(c.shape), profile::to_string(c.shaper), c.speed_scale * 100,
                    c.settle_s * 1e3, c.duration_s * 1e3, c.worst_residual_um);
    }
}

}  // namespace

void add_plan_command(CLI::App& app) {
    static PlanArgs a;
    auto* cmd = app.add_subcommand("plan", "Plan the embossing: passes, strikes, moves, steps, time, vibration");
    a.layout.add_to(*cmd, /*with_interpoint=*/false);
    cmd->add_option("--profile,-p", a.profile, "Printer profile JSON (default: the bundled one)");
    cmd->add_flag("--json", a.json, "Print the plan as JSON");
    add_protocol_options(*cmd, a.protocol, ": the plan emboss sends to a firmware built with them");
    cmd->callback([] { run_plan(a); });
}

}  // namespace tactus::cli
