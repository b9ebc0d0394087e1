// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the motion and vibration views show, computed from core's plan and
// estimate stages: the document planned sheet by sheet (off the GUI thread,
// cancellable), and a pass's carriage motion as curves in time.
#include <QFuture>
#include <memory>
#include <optional>
#include <vector>

#include "common/result.hpp"
#include "layout/page.hpp"
#include "plan/plan.hpp"
#include "plan/planner.hpp"
#include "profile/profile.hpp"

namespace tactus::gui {

struct DocumentPlan {
    std::vector<plan::SheetPlan> sheets;  // the first `kept` sheets in full
    plan::JobPlan totals;                 // over every sheet of the document
    std::size_t sheet_count = 0;
    std::shared_ptr<plan::Planner> planner;  // its tuner holds the move shapes used
    profile::PrinterProfile profile;
    std::optional<Error> error;
    bool cancelled = false;
};
using DocumentPlanPtr = std::shared_ptr<DocumentPlan>;

// Plans every sheet; keeps the first `keep` sheet plans for the views.
DocumentPlanPtr plan_document(const layout::PagedDocument& doc, const profile::PrinterProfile& p, std::size_t keep,
                              const std::function<bool(std::size_t, std::size_t)>& progress = {});
QFuture<DocumentPlanPtr> plan_document_async(layout::PagedDocument doc, profile::PrinterProfile p, std::size_t keep);

struct Curves {
    std::vector<double> t;                   // s from the start of the pass
    std::vector<double> pos, vel, acc, jerk;  // mm, mm/s, mm/s^2, mm/s^3
    std::vector<double> strike_t, strike_pos;
    double duration_s = 0;
};

// The carriage during one pass, from the moves the planner chose.
Curves pass_curves(const plan::Pass& pass, plan::Planner& planner, int samples_per_move = 48);
// The same pass with every move made with one profile shape (no shaping, no
// auto-tune), to compare shapes on the same strikes.
Curves pass_curves_with(const plan::Pass& pass, const profile::PrinterProfile& p, profile::ProfileShape shape,
                        int samples_per_move = 48);

}  // namespace tactus::gui
