// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `tactus-cli emboss --device ipp://host/printers/NAME FILE`: the job goes to
// a Tactus queue on a CUPS server over IPP (core/ipp), and the command follows
// it there until it ends. Kept apart from cmd_emboss.cpp (a cable here) and
// emboss_queue.cpp (the local spool) so each path has one owner.
#include <CLI/CLI.hpp>
#include <string>

#include "layout_args.hpp"

namespace tactus::cli {

// Sends `layout.file` to the queue at `uri` with the layout options the
// command line gave (`cmd` tells which were given); options the server's
// profile decides are refused. Exit: 0 completed, 1 cancelled or aborted on
// the server, 2 an option that cannot go to a queue, 3 a document the server
// cannot take, 4 no such server or queue.
void emboss_remote(const LayoutArgs& layout, const std::string& uri, const CLI::App& cmd,
                   std::size_t copies, const std::string& title);

}  // namespace tactus::cli
