// SPDX-License-Identifier: GPL-3.0-or-later
#include "emboss_remote.hpp"

#include <atomic>
#include <iostream>

#include "command.hpp"
#include "ipp/queue_options.hpp"
#include "ipp/remote_job.hpp"
#include "platform/termination.hpp"

// Without libcups the emboss command refuses an ipp:// device itself
// (cmd_emboss.cpp) and nothing here is built.
#if TACTUS_HAVE_IPP
namespace tactus::cli {
namespace {

std::atomic<bool> g_remote_cancel{false};
extern "C" void on_interrupt_remote(int) { g_remote_cancel.store(true); }

bool given(const CLI::App& cmd, const char* name) { return cmd.count(name) > 0; }

// The command line's layout options as the queue's job options. The page
// format, margins and profile are the server's: the filter lays the document
// out for the embosser the server holds, so those options are refused here
// rather than silently dropped.
std::vector<std::pair<std::string, std::string>> queue_options(const LayoutArgs& a,
                                                               const CLI::App& cmd) {
    for (const char* server_side :
         {"--preset", "--margin-left", "--margin-right", "--margin-top", "--margin-bottom",
          "--indent", "--reflow", "--blank-page", "--profile", "--dry-run", "--plan",
          "--start-sheet", "--format", "--queue", "--pages", "--priority", "--printer", "--db"})
        if (given(cmd, server_side))
            throw CommandFailed(exit_usage,
                                std::string("emboss: ") + server_side +
                                    " cannot go to a CUPS queue: the server lays the document out "
                                    "with its embosser's profile (docs/cups.md)");
    namespace o = ipp::option;
    std::vector<std::pair<std::string, std::string>> out;
    auto add = [&](std::string_view k, std::string v) {
        out.emplace_back(std::string(k), std::move(v));
    };
    if (given(cmd, "--table")) add(o::braille_table, a.tables);
    if (given(cmd, "--cells")) add(o::cells_per_line, std::to_string(a.cells));
    if (given(cmd, "--lines")) add(o::lines_per_page, std::to_string(a.lines));
    if (given(cmd, "--page-numbers")) add(o::page_numbers, a.page_numbers);
    if (a.no_print_pages) add(o::print_pages, "false");
    if (a.eight_dot) add(o::eight_dot, "true");
    if (!a.encoding.empty()) add(o::text_encoding, a.encoding);
    return out;
}

std::string describe(const ipp::RemoteJobStatus& s) {
    std::string line = "job " + std::to_string(s.id) + " " + ipp::to_string(s.state);
    if (s.sheets_completed >= 0) line += ", sheets embossed: " + std::to_string(s.sheets_completed);
    if (s.media_progress >= 0 && s.state == ipp::RemoteJobState::processing)
        line += ", " + std::to_string(s.media_progress) + "% of the sheet";
    if (!s.message.empty()) line += ": " + s.message;
    return line;
}

}  // namespace

void emboss_remote(const LayoutArgs& layout, const std::string& uri, const CLI::App& cmd,
                   std::size_t copies, const std::string& title) {
    const auto queue = require(ipp::parse_queue_uri(uri));
    ipp::RemoteJobRequest request;
    request.file = layout.file;
    request.title = title;
    request.copies = static_cast<int>(copies);
    request.options = queue_options(layout, cmd);
    // Ctrl-C cancels the job on the server (as it stops a local job), and the
    // command still waits to see it end. One line per status worth telling.
    g_remote_cancel.store(false);
    int id = 0;
    const auto end = ipp::send_and_follow(
        queue, request,
        [&](int sent) {
            id = sent;
            std::cout << "sent " << layout.file << " to " << uri << " as job " << id << std::endl;
            platform::on_termination(on_interrupt_remote);
        },
        [](const ipp::RemoteJobStatus& s) { std::cout << describe(s) << std::endl; }, g_remote_cancel);
    platform::default_termination();
    const auto last = require(end);
    switch (last.state) {
        case ipp::RemoteJobState::completed:
            std::cout << "embossed job " << id << " on " << uri << std::endl;
            return;
        case ipp::RemoteJobState::cancelled:
            // CUPS also ends a job its filter refused as cancelled: the
            // printer's message then says why.
            throw CommandFailed(exit_failure,
                                "job " + std::to_string(id) + " was cancelled on " + uri +
                                    (last.why_ended().empty() ? "" : ": " + last.why_ended()));
        default:
            throw CommandFailed(exit_failure,
                                "job " + std::to_string(id) + " was aborted on " + uri +
                                    (last.why_ended().empty() ? "" : ": " + last.why_ended()));
    }
}

}  // namespace tactus::cli
#endif
