// SPDX-License-Identifier: GPL-3.0-or-later
#include "motion_model.hpp"

#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>

#include "estimate/tune.hpp"
#include "motion/motion.hpp"

namespace tactus::gui {
namespace {

// Appends one move (or the rest between moves) sampled in time.
void add_move(Curves& c, const motion::MoveShape& shape, double t0, double from_mm, int sign, int samples) {
    for (int k = 0; k <= samples; ++k) {
        const double tau = shape.duration * k / samples;
        const auto d = shape.at(tau);
        c.t.push_back(t0 + tau);
        c.pos.push_back(from_mm + sign * d[0]);
        c.vel.push_back(sign * d[1]);
        c.acc.push_back(sign * d[2]);
        c.jerk.push_back(sign * d[3]);
    }
}

void add_rest(Curves& c, double t, double at_mm) {
    c.t.push_back(t);
    c.pos.push_back(at_mm);
    c.vel.push_back(0);
    c.acc.push_back(0);
    c.jerk.push_back(0);
}

double start_mm(const plan::Pass& pass, double steps_per_mm) {
    if (pass.strikes.empty() || pass.moves.empty()) return 0;
    return (pass.strikes[0].carriage_step - pass.moves[0].steps) / steps_per_mm;
}

}  // namespace

DocumentPlanPtr plan_document(const layout::PagedDocument& doc, const profile::PrinterProfile& p, std::size_t keep,
                              const std::function<bool(std::size_t, std::size_t)>& progress) {
    auto out = std::make_shared<DocumentPlan>();
    out->profile = p;
    out->sheet_count = doc.sheet_count();
    auto planner = plan::Planner::create(p);
    if (!planner) {
        out->error = planner.error();
        return out;
    }
    out->planner = std::make_shared<plan::Planner>(std::move(*planner));
    for (std::size_t n = 1; n <= out->sheet_count; ++n) {
        if (progress && progress(n - 1, out->sheet_count)) {
            out->cancelled = true;
            return out;
        }
        auto sheet = out->planner->plan_sheet(doc, n);
        if (!sheet) {
            out->error = located(sheet.error(), "sheet " + std::to_string(n));
            return out;
        }
        if (n <= keep) out->sheets.push_back(std::move(*sheet));
    }
    out->totals = out->planner->totals();
    return out;
}

QFuture<DocumentPlanPtr> plan_document_async(layout::PagedDocument doc, profile::PrinterProfile p, std::size_t keep) {
    return QtConcurrent::run([doc = std::move(doc), p = std::move(p), keep](QPromise<DocumentPlanPtr>& promise) {
        promise.setProgressRange(0, 100);
        promise.addResult(plan_document(doc, p, keep, [&](std::size_t i, std::size_t n) {
            promise.setProgressValue(n ? static_cast<int>(100 * i / n) : 100);
            return promise.isCanceled();
        }));
    });
}

Curves pass_curves(const plan::Pass& pass, plan::Planner& planner, int samples) {
    Curves c;
    const auto& p = planner.profile();
    const double spm = p.carriage.steps_per_mm;
    const double t_pass = pass.strikes.empty() ? 0 : pass.strikes.front().time_s - pass.moves.front().duration_s;
    double at = start_mm(pass, spm);
    add_rest(c, 0, at);
    for (std::size_t i = 0; i < pass.strikes.size() && i < pass.moves.size(); ++i) {
        const auto& move = pass.moves[i];
        const auto& strike = pass.strikes[i];
        const double t_strike = strike.time_s - t_pass;
        if (move.steps != 0) {
            auto tuned = planner.tuner().carriage(static_cast<std::uint32_t>(std::abs(move.steps)));
            if (tuned) {
                // The move ends, then the head settles (if the tuner asked for it) before the strike.
                const double t0 = t_strike - (*tuned)->choice.duration_s;
                add_rest(c, t0, at);
                add_move(c, (*tuned)->shape, t0, at, move.steps > 0 ? 1 : -1, samples);
            }
        }
        at = strike.carriage_step / spm;
        add_rest(c, t_strike, at);
        c.strike_t.push_back(t_strike);
        c.strike_pos.push_back(at);
        add_rest(c, t_strike + p.head.dwell_s, at);
    }
    c.duration_s = c.t.empty() ? 0 : c.t.back();
    return c;
}

Curves pass_curves_with(const plan::Pass& pass, const profile::PrinterProfile& p, profile::ProfileShape shape,
                        int samples) {
    Curves c;
    const double spm = p.carriage.steps_per_mm;
    const motion::Limits lim{p.carriage.v_max_mm_s, p.carriage.a_max_mm_s2, p.carriage.j_max_mm_s3};
    double t = 0;
    double at = start_mm(pass, spm);
    add_rest(c, 0, at);
    for (std::size_t i = 0; i < pass.strikes.size() && i < pass.moves.size(); ++i) {
        const auto& move = pass.moves[i];
        if (move.steps != 0) {
            const auto m = motion::make_move(shape, std::abs(move.steps) / spm, lim);
            add_move(c, m, t, at, move.steps > 0 ? 1 : -1, samples);
            t += m.duration;
        }
        at = pass.strikes[i].carriage_step / spm;
        c.strike_t.push_back(t);
        c.strike_pos.push_back(at);
        t += p.head.dwell_s;
        add_rest(c, t, at);
    }
    c.duration_s = t;
    return c;
}

}  // namespace tactus::gui
