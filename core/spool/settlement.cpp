// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/settlement.hpp"

#include <algorithm>

namespace tactus::spool {
namespace {


// After the controller's count was lost: the first unfinished sheet of the
// stream is the one that was under way. If passes of it were recorded it has
// dots on it. If none were but the stream had finished sheets before it, the
// controller had gone on to it (the stream runs ahead of the record): its
// first pass may have struck dots before the count was lost (serve and the
// controller killed together), so it is discarded too, said to be possibly
// blank; a partly embossed sheet reported as good would end up in the book.
// The stream's very first sheet with nothing recorded is the same case when
// the controller has run no job since its power came on (job id 0): its
// memory is gone, so whether the stream began cannot be known, and a sheet
// that may have dots is discarded rather than counted as blank paper. When
// the controller still names an earlier job, the stream's JOB_BEGIN never
// reached it: nothing of the stream was struck, and nothing is discarded.
RunSettlement without_count(const JobRecord& job, const std::vector<SheetProgress>& progress,
                            const std::string& why, bool memory_lost) {
    RunSettlement s;
    s.message = why;
    const std::size_t start = std::max<std::size_t>(job.run_start_sheet, 1);
    for (std::size_t k = start; k <= progress.size(); ++k) {
        const auto& p = progress[k - 1];
        if (p.done()) continue;
        if (p.passes_done > 0) {
            s.discard = k;
            s.discard_message = sheet_word(k) + " was under way when the stream stopped and the controller's count "
                                "was lost: at least " + std::to_string(p.passes_done) + " of " +
                                std::to_string(p.passes_total) +
                                " passes were embossed; discard it, it is embossed again in full";
        } else if (k > start) {
            s.discard = k;
            s.discard_message = sheet_word(k) + " followed " + sheet_word(k - 1) +
                                " in the stream when it stopped and the controller's count was lost: its first "
                                "pass may have begun (it may be blank); discard it, it is embossed again in full";
        } else if (memory_lost) {
            s.discard = k;
            s.discard_message = sheet_word(k) + " began the stream when it stopped, and the controller has run no "
                                "job since its power came on (its count was lost): its first pass may have begun "
                                "(it may be blank); discard it, it is embossed again in full";
        }
        break;
    }
    return s;
}

}  // namespace

std::vector<std::size_t> first_passes(const std::vector<SheetProgress>& progress) {
    std::vector<std::size_t> first(progress.size() + 1, 0);
    for (std::size_t i = 0; i < progress.size(); ++i) first[i + 1] = first[i] + progress[i].passes_total;
    return first;
}

RunSettlement settle(const JobRecord& job, const std::vector<SheetProgress>& progress,
                     const encode::Status& status) {
    const std::size_t n = progress.size();
    if (n == 0 || job.run_start_sheet < 1 || job.run_start_sheet > n) {
        RunSettlement s;
        s.message = "the run record names no sheet of this job; nothing to settle";
        return s;
    }
    const auto first = first_passes(progress);
    const std::size_t start = job.run_start_sheet;
    const std::size_t total = first[n];
    const std::uint16_t ours = job.link_job.value_or(0);
    const std::uint16_t theirs = status.ack.job_id;
    if (ours == 0 || theirs != ours)
        return without_count(job, progress,
                             "the controller does not know this stream (it reports job " + std::to_string(theirs) +
                                 ", the stream was job " + std::to_string(ours) +
                                 "): it never began, or the controller lost its memory",
                             theirs == 0);
    const std::size_t executed = status.ack.executed_passes;
    if (job.run_first_pass != first[start - 1] || executed < first[start - 1] || executed > total)
        return without_count(job, progress,
                             "the controller's count (" + std::to_string(executed) +
                                 " passes) does not fit this stream (passes " +
                                 std::to_string(first[start - 1] + 1) + " to " + std::to_string(total) +
                                 "); it is not used",
                             false);

    RunSettlement s;
    s.controller_count = true;
    std::size_t missing = 0;
    for (std::size_t k = start; k <= n && first[k - 1] < executed; ++k) {
        const std::size_t done = std::min(progress[k - 1].passes_total, executed - first[k - 1]);
        if (done > progress[k - 1].passes_done) {
            missing += done - progress[k - 1].passes_done;
            s.record.emplace_back(k, done);
        }
    }
    const bool ended = (status.flags & encode::flag::job_ended) != 0;
    if (executed == total) {
        s.message = std::string(ended ? "the controller finished the job by itself" : "the controller executed every pass") +
                    " (job " + std::to_string(ours) + ", " + std::to_string(total) + " passes); " +
                    std::to_string(missing) + " pass(es) not yet recorded, recorded now";
        return s;
    }
    // The sheet holding the next pass: it was in the machine if any pass of it
    // was executed, strikes of its next pass were made, or it was loaded.
    std::size_t k = start;
    while (first[k] <= executed) ++k;
    const std::size_t in_sheet = executed - first[k - 1];
    const std::size_t strikes = status.ack.strikes_in_pass;
    const bool loaded = status.sheet == k;
    s.message = "the controller executed " + std::to_string(executed - first[start - 1]) +
                " pass(es) of this stream (job " + std::to_string(ours) + "); " + std::to_string(missing) +
                " not yet recorded, recorded now";
    if (in_sheet > 0 || strikes > 0 || loaded) {
        s.discard = k;
        std::string where = "after pass " + std::to_string(in_sheet) + " of " +
                            std::to_string(progress[k - 1].passes_total);
        if (strikes > 0) where += " and " + std::to_string(strikes) + " strike(s) of the next";
        if (in_sheet == 0 && strikes == 0) where = "before its first dot (it may be blank)";
        s.discard_message = sheet_word(k) + " was interrupted " + where +
                            " (the controller's count): discard it; it is embossed again in full";
    }
    return s;
}

}  // namespace tactus::spool
