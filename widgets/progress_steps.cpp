// SPDX-License-Identifier: GPL-3.0-or-later
#include "progress_steps.hpp"

#include <algorithm>

namespace tactus::gui {

ProgressSteps::ProgressSteps(std::size_t sheets, std::chrono::milliseconds min_gap)
    : sheets_(std::max<std::size_t>(1, sheets)), gap_(min_gap) {}

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
    return true;
}

}  // namespace tactus::gui
