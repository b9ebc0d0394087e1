// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The exactly-once check, from what the (simulated) controller actually struck.
// Each sheet's strikes in the log are split into attempts: an attempt follows
// the plan's strike sequence for that sheet from its first strike; a strike
// equal to the sheet's first planned strike (and not the next expected one)
// starts a new attempt on a fresh sheet. Then:
//   - exactly one attempt is complete (every planned dot, in order) and it is
//     the last one: the sheet was embossed once, never again afterwards;
//   - every other attempt is a partial sheet, and the spool reported at least
//     that many sheets as discarded (`spoiled`), so no partial sheet went
//     unreported;
//   - no strike is out of sequence (a dot struck twice, or one skipped).
// When the controller may have lost its count (killed or powered off with the
// host), a sheet it finished just before the cut cannot be told from one it
// left unfinished: the spool must discard it and emboss it again. Then a
// complete attempt followed by another is allowed, provided the spool
// reported it as discarded like any partial one.
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "controller/sim_controller.hpp"
#include "plan/plan.hpp"
#include "spool/records.hpp"

namespace tactus::spool::test {

struct AuditResult {
    std::string problems;  // empty: every sheet embossed exactly once
    std::size_t partial_attempts = 0;
    std::size_t sheets_checked = 0;
};

inline AuditResult audit_strikes(const plan::JobPlan& plan,
                                 const std::vector<controller::LoggedStrike>& log,
                                 const std::vector<SheetProgress>& progress, bool require_all = true,
                                 bool count_may_be_lost = false) {
    std::map<std::size_t, std::vector<controller::LoggedStrike>> planned, struck;
    for (const auto& s : controller::planned_strikes(plan)) planned[s.sheet].push_back(s);
    for (const auto& s : log) struck[s.sheet].push_back(s);
    std::ostringstream out;
    AuditResult r;
    for (const auto& [sheet, seq] : struck)
        if (!planned.count(sheet)) out << "sheet " << sheet << ": struck but not in the plan\n";
    for (const auto& [sheet, p] : planned) {
        const auto& l = struck[sheet];
        std::vector<std::size_t> attempts;  // strikes per attempt
        std::size_t idx = 0;
        bool started = false;
        for (std::size_t i = 0; i < l.size(); ++i) {
            if (started && idx < p.size() && l[i] == p[idx]) {
                ++idx;
            } else if (l[i] == p[0]) {
                if (started) attempts.push_back(idx);
                started = true;
                idx = 1;
            } else {
                out << "sheet " << sheet << ": strike " << i + 1 << " of the log is out of sequence (expected "
                    << (started ? "planned strike " + std::to_string(idx + 1) : std::string("the first")) << ")\n";
                break;
            }
        }
        if (started) attempts.push_back(idx);
        std::size_t complete = 0, partial = 0;
        for (std::size_t a = 0; a < attempts.size(); ++a) {
            if (attempts[a] == p.size() && count_may_be_lost && a + 1 != attempts.size()) {
                ++partial;  // finished as the count was lost: must be reported as discarded
            } else if (attempts[a] == p.size()) {
                ++complete;
                if (a + 1 != attempts.size()) out << "sheet " << sheet << ": struck again after it was complete\n";
            } else {
                ++partial;
            }
        }
        r.partial_attempts += partial;
        ++r.sheets_checked;
        if (complete > 1) out << "sheet " << sheet << ": embossed " << complete << " times\n";
        if (complete == 0 && require_all) out << "sheet " << sheet << ": never completed\n";
        std::size_t spoiled = 0;
        for (const auto& pr : progress)
            if (pr.sheet == sheet) spoiled = pr.spoiled;
        if (partial > spoiled)
            out << "sheet " << sheet << ": " << partial << " partial attempt(s) but the spool reported "
                << spoiled << " discarded\n";
    }
    r.problems = out.str();
    return r;
}

}  // namespace tactus::spool::test
