// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A job on a remote Tactus queue (docs/cups.md, "printing to a CUPS queue"):
// the client sends the source document, not braille, because the server's
// tactus-layout filter lays it out with the profile of the embosser it holds
// (the client does not know that embosser's paper, cells or table limits).
// Then the client follows the job on the server until it ends.
#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/result.hpp"
#include "ipp/queue_uri.hpp"

namespace tactus::ipp {

// IPP job-state (RFC 8011 5.3.7), in its order: the last three are final.
enum class RemoteJobState { pending = 3, held, processing, stopped, cancelled, aborted, completed };
[[nodiscard]] const char* to_string(RemoteJobState s);

struct RemoteJobStatus {
    int id = 0;
    RemoteJobState state = RemoteJobState::pending;
    std::string reasons;  // job-state-reasons, comma-separated
    std::string message;  // job-printer-state-message: the backend's last INFO/ERROR line
    int sheets_completed =
        -1;                   // job-media-sheets-completed (the backend's PAGE: lines); -1 unknown
    int media_progress = -1;  // job-media-progress, percent of the current sheet; -1 unknown

    [[nodiscard]] bool ended() const { return state >= RemoteJobState::cancelled; }
    // Why an ended job ended, in the printer's words: its last message (the
    // filter's or backend's ERROR: line), but nothing for a job a user
    // cancelled (job-canceled-by-user), whose last message is only the
    // progress it had reached.
    [[nodiscard]] std::string why_ended() const;
    friend bool operator==(const RemoteJobStatus&, const RemoteJobStatus&) = default;
};

struct RemoteJobRequest {
    std::filesystem::path file;  // the source document, typed by the server (tactus.types)
    std::string title;           // job-name; empty: the file name
    int copies = 1;
    std::vector<std::pair<std::string, std::string>> options;  // queue_options.hpp names
};

// Print-Job: the job's id on the server.
Result<int> submit_job(const QueueUri& queue, const RemoteJobRequest& request);
Result<void> cancel_job(const QueueUri& queue, int job_id);

// Polls the job every `poll` until it ends, calling `on_change` with each
// status that differs from the last one, and returns the final status (once
// the backend has stopped, so its reasons say why it ended, within 3 s). When
// `cancel` becomes true, Cancel-Job is sent once and the job is followed to
// its end. A server that stops answering (cupsd restarting) is asked again
// for `patience` before it is an error. When `stop` (if given) becomes true,
// following ends with the last status seen: the job goes on on the server
// (the app quits; its job is not cancelled by that).
struct FollowOptions {
    std::chrono::milliseconds poll{250};
    std::chrono::seconds patience{60};
    const std::atomic<bool>* stop = nullptr;
};
Result<RemoteJobStatus> follow_job(const QueueUri& queue, int job_id,
                                   const std::function<void(const RemoteJobStatus&)>& on_change,
                                   const std::atomic<bool>& cancel, FollowOptions options = {});

// Whether `now` is news after `shown` (the last status told to the user):
// another state, sheet count, printer message or reasons, or another tenth of
// the sheet in hand (the server reports progress by the percent). The CLI
// prints a line and the app updates its job view on exactly these.
[[nodiscard]] bool worth_telling(const std::optional<RemoteJobStatus>& shown,
                                 const RemoteJobStatus& now);

// One job to a Tactus queue, as `tactus-cli emboss --device ipp://...` and
// the app's Ctrl+P send it: Print-Job (then `on_sent` with the job id), then
// the job followed to its end, `on_change` called with each status worth
// telling. An error before the job is sent (no server, no queue, a document
// refused) comes back without `on_sent` being called.
Result<RemoteJobStatus> send_and_follow(const QueueUri& queue, const RemoteJobRequest& request,
                                        const std::function<void(int)>& on_sent,
                                        const std::function<void(const RemoteJobStatus&)>& on_change,
                                        const std::atomic<bool>& cancel, FollowOptions options = {});

}  // namespace tactus::ipp
