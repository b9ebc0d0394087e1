// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `tactus-cli emboss --queue`: lay the document out, store it in the spool
// with the printer's profile as it is now, and return; `tactus-cli serve`
// embosses it. Kept apart from cmd_emboss.cpp (direct embossing) so each
// path has one owner.
#include <cstddef>
#include <string>

#include <CLI/CLI.hpp>

#include "layout_args.hpp"

namespace tactus::cli {

struct EmbossQueueArgs {
    bool enabled = false;  // --queue
    std::string db;
    std::string printer;
    std::size_t copies = 1;
    std::string pages;
    int priority = 0;
    std::string title;
    std::string device;  // emboss --device: the queue printer on that device (made if none)
};

void add_emboss_queue_options(CLI::App& emboss, EmbossQueueArgs& args);
// Queues the job and prints its number; ends the command on any error.
void enqueue_emboss(const LayoutArgs& layout, const EmbossQueueArgs& args);

}  // namespace tactus::cli
