// SPDX-License-Identifier: GPL-3.0-or-later
#include "progress_steps.hpp"

#include <algorithm>

namespace tactus::gui {

ProgressSteps::ProgressSteps(std::size_t sheets, std::chrono::milliseconds min_gap, std::chrono::milliseconds heartbeat)
    : sheets_(std::max<std::size_t>(1, sheets)), gap_(min_gap), heartbeat_(heartbeat) {}

long ProgressSteps::spoken_step_of(int percent, std::size_t sheet) const {
    // Fewer than ten sheets: a sheet is more than 10 %, so sheets are the rarer step.
    if (sheets_ < 10) return static_cast<long>(std::min(sheet, sheets_)) - 1;
    return percent / 10;
}

std::optional<ProgressSteps::Step> ProgressSteps::update(std::size_t passes_done, std::size_t passes_total,
                                                         std::size_t sheet) {
    const int percent = passes_total ? static_cast<int>(100 * std::min(passes_done, passes_total) / passes_total) : 0;
    sheet = std::min(std::max<std::size_t>(1, sheet), sheets_);
    step_ = std::max(step_, spoken_step_of(percent, sheet));
    latest_ = std::max(latest_, percent);
    latest_sheet_ = std::max(latest_sheet_, sheet);
    if (percent / 10 <= shown_tenth_ && sheet <= shown_sheet_) return std::nullopt;
    shown_tenth_ = std::max(shown_tenth_, percent / 10);
    shown_sheet_ = std::max(shown_sheet_, sheet);
    shown_ = percent;
    return Step{percent, sheet, sheets_, sheets_ < 10};
}

bool ProgressSteps::speak(Clock::time_point now) {
    if (step_ <= spoken_step_ || shown_ >= 100) return false;  // the end has its own message
    if (spoken_at_ && now - *spoken_at_ < gap_) return false;
    spoken_step_ = step_;
    spoken_at_ = now;
    spoken_percent_ = shown_;
    return true;
}

std::optional<ProgressSteps::Step> ProgressSteps::overdue(Clock::time_point now) {
    if (!spoken_at_) {
        spoken_at_ = now;
        return std::nullopt;
    }
    if (now - *spoken_at_ < heartbeat_ || latest_ <= spoken_percent_ || latest_ >= 100) return std::nullopt;
    spoken_at_ = now;
    spoken_percent_ = latest_;
    return Step{latest_, latest_sheet_, sheets_, false};
}

}  // namespace tactus::gui
