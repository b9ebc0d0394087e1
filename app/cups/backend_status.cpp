// SPDX-License-Identifier: GPL-3.0-or-later
#include "backend_status.hpp"

#include <algorithm>

namespace tactus::cups {
namespace {

bool contains(const std::string& s, const char* what) { return s.find(what) != std::string::npos; }

std::string capitalised(std::string s) {
    if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
    return s;
}

}  // namespace

StatusReporter::StatusReporter(const std::vector<spool::SheetProgress>& at_start) {
    for (const auto& p : at_start)
        if (p.done()) counted_.insert(p.sheet);
}

std::vector<std::string> StatusReporter::set_reason(const char* reason, bool on) {
    if (on == reasons_.contains(reason)) return {};
    if (on) reasons_.insert(reason);
    else reasons_.erase(reason);
    return {std::string("STATE: ") + (on ? "+" : "-") + reason};
}

std::vector<std::string> StatusReporter::update(const JobView& job) {
    using spool::JobState;
    std::vector<std::string> out;
    // Sheets: each counted once, in sheet order, the moment its last pass ran.
    std::size_t done = 0;
    const spool::SheetProgress* current = nullptr;
    for (const auto& p : job.progress) {
        if (p.done()) {
            ++done;
            if (counted_.insert(p.sheet).second) out.push_back("PAGE: " + std::to_string(p.sheet) + " 1");
        } else if (!current) {
            current = &p;
        }
    }
    if (current && current->passes_total > 0) {
        const int pct = static_cast<int>(100 * current->passes_done / current->passes_total);
        if (media_progress_ != pct) {
            media_progress_ = pct;
            out.push_back("ATTR: job-media-progress=" + std::to_string(pct));
        }
    }

    // The runner pauses on the first fault report ("controller fault"); the
    // link's next note names it ("paper out at sheet 2: load paper").
    const bool paper_out =
        job.state == JobState::paused && (contains(job.reason, "paper out") || contains(job.last_note, "paper out"));
    const bool offline = job.state == JobState::running && contains(job.last_note, "connection lost");
    for (auto& l : set_reason(kPaperOut, paper_out)) out.push_back(std::move(l));
    for (auto& l : set_reason(kOffline, offline)) out.push_back(std::move(l));

    std::string info;
    const std::string of = " of " + std::to_string(job.total_sheets);
    switch (job.state) {
    case JobState::queued:
        info = job.jobs_ahead ? "Waiting: the embosser has " + std::to_string(job.jobs_ahead) +
                                    " other job(s) to finish first"
                              : "Waiting for the embosser";
        if (!job.reason.empty()) info += " (" + job.reason + ")";
        break;
    case JobState::running:
        info = offline ? "The embosser is not answering (" + job.last_note + ")"
                       : "Embossing sheet " + std::to_string(current ? current->sheet : std::min(done + 1, job.total_sheets)) + of;
        break;
    case JobState::paused:
        info = paper_out ? capitalised(contains(job.reason, "paper out") ? job.reason : job.last_note)
                         : "Paused: " + job.reason;
        break;
    case JobState::completed: info = "Embossed all " + std::to_string(job.total_sheets) + " sheet(s)"; break;
    case JobState::cancelled: info = "Cancelled after " + std::to_string(done) + of + " sheet(s)"; break;
    case JobState::failed: info = "Failed: " + job.reason; break;
    }
    if (info != info_) {
        info_ = info;
        out.push_back("INFO: " + info);
    }
    return out;
}

std::vector<std::string> StatusReporter::clear() {
    std::vector<std::string> out;
    for (const auto& r : std::set<std::string>(reasons_)) out.push_back("STATE: -" + r);
    reasons_.clear();
    return out;
}

}  // namespace tactus::cups
