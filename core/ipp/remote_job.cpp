// SPDX-License-Identifier: GPL-3.0-or-later
#include "ipp/remote_job.hpp"

#include <optional>
#include <thread>

#include "ipp_connection.hpp"
#include "common/try.hpp"

namespace tactus::ipp {
namespace {

using detail::Ipp;

ipp_t* job_request(ipp_op_t op, const QueueUri& queue, int job_id) {
    ipp_t* req = ippNewRequest(op);
    ippAddString(req, IPP_TAG_OPERATION, IPP_TAG_URI, "printer-uri", nullptr, queue.uri.c_str());
    if (job_id > 0) ippAddInteger(req, IPP_TAG_OPERATION, IPP_TAG_INTEGER, "job-id", job_id);
    ippAddString(req, IPP_TAG_OPERATION, IPP_TAG_NAME, "requesting-user-name", nullptr, cupsUser());
    return req;
}

int integer(ipp_t* response, const char* name) {
    ipp_attribute_t* a = ippFindAttribute(response, name, IPP_TAG_INTEGER);
    return a ? ippGetInteger(a, 0) : -1;
}

Result<RemoteJobStatus> status_on(http_t* http, const QueueUri& queue, int job_id,
                                  bool* transient = nullptr) {
    ipp_t* req = job_request(IPP_OP_GET_JOB_ATTRIBUTES, queue, job_id);
    static const char* const wanted[] = {"job-id",
                                         "job-state",
                                         "job-state-reasons",
                                         "job-printer-state-message",
                                         "job-media-sheets-completed",
                                         "job-media-progress"};
    ippAddStrings(req, IPP_TAG_OPERATION, IPP_TAG_KEYWORD, "requested-attributes",
                  static_cast<int>(std::size(wanted)), nullptr, wanted);
    auto response = detail::call(http, req, queue.resource, "read job " + std::to_string(job_id),
                                 {}, transient);
    if (!response) return std::unexpected(response.error());
    RemoteJobStatus s;
    s.id = job_id;
    ipp_attribute_t* state = ippFindAttribute(response->get(), "job-state", IPP_TAG_ENUM);
    if (!state)
        return fail(ErrorKind::protocol, "the server did not say the job's state", queue.uri);
    s.state = static_cast<RemoteJobState>(ippGetInteger(state, 0));
    if (ipp_attribute_t* r =
            ippFindAttribute(response->get(), "job-state-reasons", IPP_TAG_KEYWORD))
        for (int i = 0; i < ippGetCount(r); ++i) {
            if (!s.reasons.empty()) s.reasons += ", ";
            s.reasons += ippGetString(r, i, nullptr);
        }
    if (ipp_attribute_t* m =
            ippFindAttribute(response->get(), "job-printer-state-message", IPP_TAG_TEXT))
        s.message = ippGetString(m, 0, nullptr);
    s.sheets_completed = integer(response->get(), "job-media-sheets-completed");
    s.media_progress = integer(response->get(), "job-media-progress");
    return s;
}

Result<void> cancel_on(http_t* http, const QueueUri& queue, int job_id) {
    auto r = detail::call(http, job_request(IPP_OP_CANCEL_JOB, queue, job_id), queue.resource,
                          "cancel job " + std::to_string(job_id));
    if (!r) return std::unexpected(r.error());
    return {};
}

}  // namespace

const char* to_string(RemoteJobState s) {
    switch (s) {
        case RemoteJobState::pending:
            return "pending";
        case RemoteJobState::held:
            return "held";
        case RemoteJobState::processing:
            return "processing";
        case RemoteJobState::stopped:
            return "stopped";
        case RemoteJobState::cancelled:
            return "cancelled";
        case RemoteJobState::aborted:
            return "aborted";
        case RemoteJobState::completed:
            return "completed";
    }
    return "unknown";
}

std::string RemoteJobStatus::why_ended() const {
    if (state == RemoteJobState::cancelled && reasons.find("job-canceled-by-user") != std::string::npos)
        return {};
    return message;
}

Result<int> submit_job(const QueueUri& queue, const RemoteJobRequest& request) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(request.file, ec))
        return fail(ErrorKind::input, "no such document", request.file.string());
    TACTUS_TRY(http, detail::connect(queue.host, queue.port, queue.tls));
    ipp_t* req = job_request(IPP_OP_PRINT_JOB, queue, 0);
    const auto name = request.file.filename().string();
    ippAddString(req, IPP_TAG_OPERATION, IPP_TAG_NAME, "job-name", nullptr,
                 (request.title.empty() ? name : request.title).c_str());
    ippAddString(req, IPP_TAG_OPERATION, IPP_TAG_NAME, "document-name", nullptr, name.c_str());
    // Typed by the server from the name and content (tactus.types), as lp does.
    ippAddString(req, IPP_TAG_OPERATION, IPP_TAG_MIMETYPE, "document-format", nullptr,
                 CUPS_FORMAT_AUTO);
    cups_option_t* options = nullptr;
    int count = 0;
    for (const auto& [k, v] : request.options)
        count = cupsAddOption(k.c_str(), v.c_str(), count, &options);
    if (request.copies > 1)
        count = cupsAddOption("copies", std::to_string(request.copies).c_str(), count, &options);
    cupsEncodeOptions2(req, count, options, IPP_TAG_JOB);
    cupsFreeOptions(count, options);
    auto response =
        detail::call(http.get(), req, queue.resource, "send the job", request.file.string());
    if (!response) return std::unexpected(response.error());
    const int id = integer(response->get(), "job-id");
    if (id <= 0)
        return fail(ErrorKind::protocol, "the server took the job but gave no job id", queue.uri);
    return id;
}

Result<void> cancel_job(const QueueUri& queue, int job_id) {
    TACTUS_TRY(http, detail::connect(queue.host, queue.port, queue.tls));
    return cancel_on(http.get(), queue, job_id);
}

Result<RemoteJobStatus> follow_job(const QueueUri& queue, int job_id,
                                   const std::function<void(const RemoteJobStatus&)>& on_change,
                                   const std::atomic<bool>& cancel, FollowOptions options) {
    using clock = std::chrono::steady_clock;
    detail::Http http;
    bool cancel_sent = false;
    std::optional<RemoteJobStatus> last;
    std::optional<clock::time_point> first_ended;
    constexpr auto kStopping = std::chrono::seconds(3);
    auto answered = clock::now();
    for (;;) {
        if (options.stop && options.stop->load()) {
            if (last) return *last;
            RemoteJobStatus unknown;
            unknown.id = job_id;
            return unknown;
        }
        Result<RemoteJobStatus> s = fail(ErrorKind::device, "not connected");
        bool transient = true;  // a failed connect is worth another try
        if (!http) {
            if (auto h = detail::connect(queue.host, queue.port, queue.tls))
                http = std::move(*h);
            else
                s = std::unexpected(h.error());
        }
        if (http) {
            if (cancel.load() && !cancel_sent) {
                if (auto c = cancel_on(http.get(), queue, job_id); c) cancel_sent = true;
            }
            s = status_on(http.get(), queue, job_id, &transient);
        }
        if (s) {
            answered = clock::now();
            // An ended job whose backend is still stopping says only
            // processing-to-stop-point; the reason it ended for
            // (job-canceled-by-user, ...) follows a moment later.
            const bool stopping = s->ended() &&
                                  s->reasons.find("processing-to-stop-point") != std::string::npos &&
                                  clock::now() - first_ended.value_or(clock::now()) < kStopping;
            if (stopping) {
                if (!first_ended) first_ended = clock::now();
            } else {
                if (!last || *last != *s) {
                    on_change(*s);
                    last = *s;
                }
                if (s->ended()) return *s;
            }
        } else {
            // A job the server no longer knows, or a server that is gone for
            // longer than a restart takes: the end of following.
            if (!transient || clock::now() - answered > options.patience)
                return std::unexpected(s.error());
            http.reset();
        }
        std::this_thread::sleep_for(options.poll);
    }
}

bool worth_telling(const std::optional<RemoteJobStatus>& shown, const RemoteJobStatus& now) {
    return !shown || shown->state != now.state ||
           shown->sheets_completed != now.sheets_completed || shown->message != now.message ||
           shown->reasons != now.reasons || shown->media_progress / 10 != now.media_progress / 10;
}

Result<RemoteJobStatus> send_and_follow(const QueueUri& queue, const RemoteJobRequest& request,
                                        const std::function<void(int)>& on_sent,
                                        const std::function<void(const RemoteJobStatus&)>& on_change,
                                        const std::atomic<bool>& cancel, FollowOptions options) {
    TACTUS_TRY(id, submit_job(queue, request));
    on_sent(id);
    std::optional<RemoteJobStatus> shown;
    return follow_job(
        queue, id,
        [&](const RemoteJobStatus& s) {
            if (!worth_telling(shown, s)) return;
            on_change(s);
            shown = s;
        },
        cancel, options);
}

}  // namespace tactus::ipp
