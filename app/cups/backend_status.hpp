// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the backend tells cupsd while the spool embosses a job (backend(7)
// messages on stderr): a pure function of what the spool database says, so
// it reads the same whether the backend itself or a `tactus-cli serve`
// drives the embosser, and it is tested without cupsd.
//   PAGE: <sheet> 1                 once per sheet embossed (page accounting)
//   ATTR: job-media-progress=<0-100> how far the sheet in the machine is
//   STATE: +media-empty-error / -...  paper out
//   STATE: +offline-report / -...     the cable is gone, the link reconnects
//   INFO: <plain words>               becomes the printer's state message
#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "spool/records.hpp"

namespace tactus::cups {

struct JobView {
    spool::JobState state = spool::JobState::queued;
    std::string reason;
    std::vector<spool::SheetProgress> progress;
    std::size_t total_sheets = 0;
    // The newest note the link reported for this job ("connection lost (...):
    // reconnecting", "reconnected", "paper out at sheet 2: load paper").
    std::string last_note;
    std::size_t jobs_ahead = 0;  // other jobs the runner does first
};

inline constexpr const char* kPaperOut = "media-empty-error";
inline constexpr const char* kOffline = "offline-report";

class StatusReporter {
public:
    // Sheets already embossed when this backend started (an earlier run of
    // the same CUPS job) were counted then and are not counted again.
    explicit StatusReporter(const std::vector<spool::SheetProgress>& at_start = {});

    // The lines to send for what changed since the last call.
    std::vector<std::string> update(const JobView& job);
    // Clears every state reason this reporter set (the job is over).
    std::vector<std::string> clear();

    [[nodiscard]] std::size_t sheets_reported() const { return counted_.size(); }

private:
    std::vector<std::string> set_reason(const char* reason, bool on);

    std::set<std::size_t> counted_;
    std::set<std::string> reasons_;
    std::optional<int> media_progress_;
    std::string info_;
};

}  // namespace tactus::cups
