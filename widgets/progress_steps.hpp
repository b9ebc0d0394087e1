// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// When embossing progress is worth telling. The link reports progress after
// every pass (hundreds per sheet); sending each one to the accessibility layer
// flooded Orca ("DELUGE", minutes of silence, 68,226 events for 317 sheets).
// So the bar moves only at each tenth and each new sheet, and the screen reader
// hears a step only every 10 % or every sheet, whichever is rarer, at most every
// few seconds. The clock is passed in, so the rule is tested without waiting.
#include <chrono>
#include <cstddef>
#include <optional>

namespace tactus::gui {

class ProgressSteps {
public:
    using Clock = std::chrono::steady_clock;
    // `sheets`: the sheets the job embosses. `min_gap`: the least time between
    // two spoken steps.
    explicit ProgressSteps(std::size_t sheets, std::chrono::milliseconds min_gap = std::chrono::seconds(3),
                           std::chrono::milliseconds heartbeat = std::chrono::seconds(30));

    struct Step {
        int percent = 0;         // whole percent of the passes done
        std::size_t sheet = 0;   // the sheet being embossed, counted from the job's first (1-based)
        std::size_t sheets = 0;  // sheets in the job
        bool by_sheet = false;   // the steps are sheets (few sheets), not tenths
    };

    // Progress from the link: passes done of all passes, and the sheet (1-based
    // within the job). Returns what to show when the bar should move (a new tenth
    // or a new sheet), else nothing.
    std::optional<Step> update(std::size_t passes_done, std::size_t passes_total, std::size_t sheet);
    // After update() returned a step: whether to say it now (a new step, and the
    // last spoken one is at least min_gap old). A step not spoken is said with a
    // later one; the job's end is announced by its own message.
    bool speak(Clock::time_point now);
    // When nothing was said for `heartbeat` while the job moved on: the step to
    // say now. At the plan's own speed a sheet takes minutes, and minutes of
    // silence sound like a stalled job. The first call starts the clock.
    std::optional<Step> overdue(Clock::time_point now);

    [[nodiscard]] int shown_percent() const { return shown_; }

private:
    [[nodiscard]] long spoken_step_of(int percent, std::size_t sheet) const;

    std::size_t sheets_;
    std::chrono::milliseconds gap_;
    std::chrono::milliseconds heartbeat_;
    int latest_ = 0;  // the last reported progress, moved to a step or not
    std::size_t latest_sheet_ = 1;
    int spoken_percent_ = 0;
    int shown_ = -1;
    int shown_tenth_ = -1;
    std::size_t shown_sheet_ = 0;
    long step_ = 0;         // the spoken step reached
    long spoken_step_ = 0;  // step 0 (the start) is announced as "Embossing ..."
    std::optional<Clock::time_point> spoken_at_;
};

}  // namespace tactus::gui
