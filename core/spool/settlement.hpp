// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Settling an interrupted stream with the controller's own count, before
// anything is planned or sent again (docs/spool.md, "Exactly once"). A pure
// function of the run record, the stored plan shape and the controller's
// STATUS, so every case is tested on its own; the runner applies the result
// in one transaction (Spool::settle_run).
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "encode/messages.hpp"
#include "spool/records.hpp"

namespace tactus::spool {

// "sheet 3": how the runner and the settlement name a sheet in their messages.
inline std::string sheet_word(std::size_t n) { return "sheet " + std::to_string(n); }

struct RunSettlement {
    // Sheets whose executed passes the record had not yet caught up with:
    // (sheet, passes done), never lowering what is recorded.
    std::vector<std::pair<std::size_t, std::size_t>> record;
    // The sheet that left the machine unfinished, if any: discarded and
    // embossed again in full.
    std::optional<std::size_t> discard;
    std::string discard_message;
    std::string message;            // the "reconciled" event
    bool controller_count = false;  // the controller's own count was used
};

// The first pass (job-wide index) of each sheet, and the total at the end.
[[nodiscard]] std::vector<std::size_t> first_passes(const std::vector<SheetProgress>& progress);

// `job` has an open run record (`run_open`); `progress` is the shape of the
// plan that stream was cut from; `status` is what the controller reports now.
[[nodiscard]] RunSettlement settle(const JobRecord& job, const std::vector<SheetProgress>& progress,
                                   const encode::Status& status);

}  // namespace tactus::spool
