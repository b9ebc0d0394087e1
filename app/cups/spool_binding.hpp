// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How a CUPS queue finds its embosser in the Tactus spool. CUPS runs the
// filter and the backend as the unprivileged `lp` user, with no home of its
// own, so the spool is not the per-user one (docs/spool.md) but a system one:
//   $TACTUS_SPOOL_DB (cupsd passes it with `SetEnv` in cups-files.conf),
//   else /var/spool/tactus/spool.db (the .deb creates the folder, owned by lp,
//   group lp, mode 2775: local users in group lp queue to the same embosser
//   with `--db /var/spool/tactus/spool.db`).
// The spool printer is the one on the same cable as the CUPS queue's URI, so
// CUPS jobs and local jobs share one runner and never fight over the cable.
#include <filesystem>
#include <string_view>

#include "common/result.hpp"
#include "spool/records.hpp"
#include "spool/spool.hpp"

namespace tactus::cups {

inline constexpr const char* kSystemSpool = "/var/spool/tactus/spool.db";

std::filesystem::path cups_spool_path();

// Opens (creating) the spool the CUPS filter and backend share. A failed open
// is tried again for up to a second before it counts: the filter and the
// backend of a job start together, and another user's process (root's
// `tactus-cli queue list`, say) may be making the WAL's shared-memory file at
// that moment, which SQLite then briefly refuses as "unable to open database
// file"; the backend's failure would stop the whole CUPS queue.
Result<spool::Spool> open_cups_spool();

// The spool printer on `device`'s cable (same kind and path; line settings
// such as baud are the spool's). None yet: one is added, named after the CUPS
// queue, with the default profile (`tactus-cli queue printer set NAME
// --profile ...` changes it; the next job lays out with the new one).
Result<spool::PrinterRecord> bind_printer(spool::Spool& spool, std::string_view device,
                                          std::string_view queue_name);

}  // namespace tactus::cups
