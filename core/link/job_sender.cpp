// SPDX-License-Identifier: GPL-3.0-or-later
// Streaming a job: keep the controller's ring full through a sliding window,
// resend what the line lost, and recover from a paused, faulted, restarted or
// unplugged controller without losing or repeating a dot.
#include <algorithm>
#include <cstdio>
#include <string>

#include "link/link_impl.hpp"
#include "common/try.hpp"

namespace tactus::link {

namespace {

struct JobState {
    explicit JobState(const plan::JobPlan& p) : plan(p), table(encode::pass_table(p)) {}
    const plan::JobPlan& plan;
    std::vector<encode::PassRef> table;
    std::size_t first = 0;     // first pass of this call
    std::size_t reported = 0;  // passes reported executed (job-wide index of the next one)
    std::uint16_t job_id = 0;
    encode::JobStream stream;
    std::vector<std::pair<std::size_t, std::size_t>> chunks;
    std::size_t next_chunk = 0;
    std::size_t bytes_sent = 0;
    std::size_t bytes_total = 0;
    // Op bytes per DATA frame: at most what the controller offers, halved at
    // each retransmission timeout and doubled again after 8 frames got
    // through, so a frame still crosses a noisy line (at 2e-2 per byte, drops,
    // flips and duplicates each, an 86-byte frame arrives whole 0.5 % of the
    // time, a 24-byte one 24 %). Only frames not yet sent are cut again: one
    // sent keeps its bytes and its SEQ until it is acknowledged.
    std::size_t payload_max = 0;
    std::size_t payload_min = 0;
    std::size_t payload_limit = 0;
    std::size_t acked_mark = 0;
    bool user_paused = false;
    double fault_since = -1;
    double last_resume = -1;
    std::string last_note;
    ControllerState last_state = ControllerState::idle;

    [[nodiscard]] std::size_t sheet_of(std::size_t pass) const {
        if (pass < table.size()) return table[pass].sheet;
        return plan.sheets.empty() ? 0 : plan.sheets.back().index;
    }
};

// "30 s", "2.5 s".
std::string seconds_text(std::chrono::milliseconds ms) {
    char b[32];
    std::snprintf(b, sizeof b, "%g s", static_cast<double>(ms.count()) / 1000.0);
    return b;
}

}  // namespace

Result<JobOutcome> Link::Impl::send_job(const plan::JobPlan& plan, std::size_t start_sheet,
                                        const ProgressFn& progress, const CancelToken& cancel,
                                        std::uint16_t job_id) {
    if (!session) return fail(ErrorKind::internal, "no session: call hello() first", device);
    JobState js(plan);
    std::size_t sp = 0;
    js.first = 0;
    while (sp < plan.sheets.size() && plan.sheets[sp].index != start_sheet) {
        js.first += plan.sheets[sp].passes.size();
        ++sp;
    }
    if (sp == plan.sheets.size())
        return fail(ErrorKind::usage, "sheet " + std::to_string(start_sheet) + " is not in the plan (it has " +
                        std::to_string(plan.sheets.size()) + " sheets)",
                    "start_sheet");
    js.reported = js.first;
    // A fresh job id per call, so counts left from an earlier job are never
    // mistaken for this one's: the caller's, or one from the direct range that
    // differs from the controller's last.
    js.job_id = job_id;
    while (js.job_id == 0 || (job_id == 0 && js.job_id == ack.job_id))
        js.job_id = static_cast<std::uint16_t>(opt.job_id + (rng() % 0x7FFF) + 1);

    if (v3() && !tables)
        return fail(ErrorKind::usage,
                    "the controller speaks protocol 3 (the reference firmware): plan with its ramp tables and "
                    "give them to the link (use_firmware_tables)",
                    device);
    auto build = [&](const encode::StreamStart& st) -> Result<void> {
        auto stream = v3() ? encode::encode_job_v3(plan, *tables, timing, js.job_id, st)
                           : encode::encode_job(plan, js.job_id, st);
        if (!stream) return std::unexpected(stream.error());
        js.stream = std::move(*stream);
        std::size_t max_payload =
            std::min<std::size_t>(encode::kMaxPayload, std::max<std::uint8_t>(info.max_payload, 8));
        if (opt.max_payload > 0) max_payload = std::min(max_payload, std::max<std::size_t>(opt.max_payload, 8));
        // v3: ops may span frames; each payload ends with the 2-byte DATA check.
        js.payload_max = v3() ? max_payload - 2 : max_payload;
        js.payload_min = std::min(js.payload_max, v3() ? std::size_t{8} : std::size_t{16});
        if (js.payload_limit == 0) {
            // A line that already lost frames while the session opened starts small.
            js.payload_limit = js.payload_max;
            js.acked_mark = data_acked;
            for (std::size_t k = 0; k < std::min<std::size_t>(session_timeouts, 3); ++k)
                js.payload_limit = std::max(js.payload_min, js.payload_limit / 2);
        }
        js.payload_limit = std::clamp(js.payload_limit, js.payload_min, js.payload_max);
        js.chunks = v3() ? encode::chunk_stream_v3(js.stream, js.payload_limit)
                         : encode::chunk_stream(js.stream, js.payload_limit);
        js.next_chunk = 0;
        js.bytes_total += js.stream.bytes.size();
        return {};
    };
    TACTUS_TRY_VOID(build({js.first, 0, false}));

    const std::size_t total = js.table.size() - js.first;
    double data_start = -1;
    double data_end = -1;

    auto snapshot = [&] {
        Status st;
        st.ack = ack;
        return st;
    };
    auto note = [&](const std::string& text) {
        if (text == js.last_note) return;
        js.last_note = text;
        if (!progress) return;
        Progress p;
        p.note = text;
        p.bytes_sent = js.bytes_sent;
        p.bytes_total = js.bytes_total;
        p.status = snapshot();
        progress(p);
    };
    auto report_executed = [&] {
        if (ack.job_id != js.job_id) return;
        while (js.reported < ack.executed_passes && js.reported < js.table.size()) {
            const auto& ref = js.table[js.reported];
            ++js.reported;
            last_progress = s->now();
            if (!progress) continue;
            PassExecuted e{ref.sheet, ref.pass_in_sheet, js.reported - js.first, total};
            Progress p;
            p.executed = &e;
            p.bytes_sent = js.bytes_sent;
            p.bytes_total = js.bytes_total;
            p.status = snapshot();
            progress(p);
        }
    };
    auto finish = [&](JobEnd end, Error e) -> JobOutcome {
        // Requests this stream did not get to are moot, not for the next one.
        pause_req = false;
        resume_req = false;
        JobOutcome out;
        out.end = end;
        out.passes_done = js.reported - js.first;
        out.resume_sheet = end == JobEnd::completed ? 0 : js.sheet_of(js.reported);
        out.error = std::move(e);
        if (data_start >= 0) stats.data_seconds = (data_end >= 0 ? data_end : s->now()) - data_start;
        out.stats = stats;
        return out;
    };
    auto where = [&] {
        return "sheet " + std::to_string(js.sheet_of(js.reported)) + " (pass " +
               std::to_string(js.reported + 1) + " of the job)";
    };

    // Rebuilds the stream from what the controller reports it has done, after
    // it restarted or stopped on a fault that dropped its buffer.
    auto restart = [&]() -> Result<void> {
        ++stats.restarts;
        TACTUS_TRY_VOID(hello());
        // A NAK *no session* that came before the HELLO_REPLY answered a
        // frame sent to the restarted controller before this HELLO (it
        // replies in order): it is about the session this one replaces.
        session_lost = false;
        if (config) {
            TACTUS_TRY(payload, config_payload());
            if (auto r = transact(FrameType::configure, std::move(payload)); !r) return r;
        }
        TACTUS_TRY(st, status());
        ack = st.ack;
        report_executed();
        encode::StreamStart start{js.reported, 0, false};
        if (st.ack.job_id == js.job_id && (st.flags & encode::flag::job_active)) {
            const bool in_pass = (st.flags & encode::flag::pass_active) != 0;
            start.skip = in_pass ? st.ack.strikes_in_pass : 0;
            start.mid_sheet = st.sheet != 0 && st.sheet == js.sheet_of(js.reported);
        }
        note("controller " + std::string(saw_power_loss ? "lost power" : "restarted") +
             ": resuming at " + where() +
             (start.skip ? " after strike " + std::to_string(start.skip) : ""));
        if (auto r = transact(FrameType::resume, {}); !r) return r;
        return build(start);
    };

    // A new frame size for what has not been sent yet.
    auto resize_frames = [&](std::size_t limit) {
        limit = std::clamp(limit, js.payload_min, js.payload_max);
        js.acked_mark = data_acked;
        if (limit == js.payload_limit) return;
        js.payload_limit = limit;
        const std::size_t from =
            js.next_chunk < js.chunks.size() ? js.chunks[js.next_chunk].first : js.stream.bytes.size();
        js.chunks.resize(js.next_chunk);
        const auto rest = v3() ? encode::chunk_stream_v3(js.stream, limit, from)
                               : encode::chunk_stream(js.stream, limit, from);
        js.chunks.insert(js.chunks.end(), rest.begin(), rest.end());
    };

    // The device failed: reopen it, then resend whatever is unacknowledged.
    auto recover_device = [&](const Error& why) -> Result<void> {
        note("connection lost (" + why.message + "): reconnecting");
        if (auto r = reconnect_device(); !r) return r;
        note("reconnected");
        return resend_all();
    };

    last_progress = s->now();
    for (;;) {
        if (refused) return finish(JobEnd::failed, *refused);
        if (cancel.cancelled()) {
            (void)transact(FrameType::abort, {});
            return finish(JobEnd::cancelled, {});
        }
        // The bounded give-up: nothing taken and nothing executed for that
        // long, whether the line is silent (reopened in vain) or the
        // controller answers without ever taking a frame.
        if (s->now() - last_progress > seconds(opt.give_up_after)) {
            const auto sheet = std::to_string(js.sheet_of(js.reported));
            return finish(JobEnd::not_answering,
                          Error{"the embosser stopped answering: nothing acknowledged for " +
                                    seconds_text(opt.give_up_after) + " at " + where() +
                                    "; check that it is switched on and its cable is in, then resume from sheet " +
                                    sheet,
                                device, ErrorKind::device});
        }
        Result<void> step{};
        // A request made before the controller has begun this stream waits
        // until it has: a PAUSE sent to an idle controller pauses nothing, and
        // the job then ran on while the spool said "paused". Control frames
        // take part in the window: nothing outstanding ever exceeds it (a
        // request waits for room).
        const bool begun = ack.job_id == js.job_id;
        const auto room = [&] { return unacked.size() < window_frames(); };
        if (begun && room() && pause_req.exchange(false)) {
            js.user_paused = true;
            step = send(FrameType::pause, {});
        }
        if (step && begun && room() && resume_req.exchange(false)) {
            js.user_paused = false;
            step = send(FrameType::resume, {});
        }
        report_executed();
        if (ack.state != js.last_state) {
            js.last_state = ack.state;
            if (ack.state == ControllerState::paused || ack.state == ControllerState::fault)
                note(std::string("controller ") + encode::state_name(ack.state));
        }

        const bool this_job = ack.job_id == js.job_id;
        if (js.reported == js.table.size() && js.next_chunk == js.chunks.size() && unacked.empty() &&
            this_job && ack.state == ControllerState::idle) {
            if (data_end < 0) data_end = s->now();
            return finish(JobEnd::completed, {});
        }
        if (saw_power_loss)
            return finish(JobEnd::failed,
                          Error{"the controller lost power during " + where() +
                                    ": positions and buffered data are gone; put a fresh sheet in "
                                    "and resume from that sheet",
                                device, ErrorKind::device});
        if (step && (session_lost || (ack.faults & kRestartFaults) != 0)) {
            if (auto r = restart(); !r) return finish(JobEnd::failed, r.error());
            continue;
        }
        if (ack.faults & fault::hammer)
            return finish(JobEnd::failed,
                          Error{"hammer fault at " + where() +
                                    ": check the print head, then resume from that sheet",
                                device, ErrorKind::device});
        if (ack.faults & fault::paper_out) {
            if (js.fault_since < 0) js.fault_since = s->now();
            note("paper out at " + where() + ": load paper");
            if (s->now() - js.fault_since > seconds(opt.fault_wait))
                return finish(JobEnd::failed,
                              Error{"paper out at " + where() + " and not loaded within " +
                                        std::to_string(opt.fault_wait.count() / 1000) + " s",
                                    device, ErrorKind::device});
        } else {
            js.fault_since = -1;
        }
        // Paused by the controller itself (paper loaded again, keep-alive lost
        // while the cable was out): carry on unless the user paused.
        const bool resume_outstanding = std::any_of(unacked.begin(), unacked.end(), [](const Outgoing& o) {
            return o.type == FrameType::resume;
        });
        if (step && room() && !resume_outstanding && ack.state == ControllerState::paused && this_job &&
            !js.user_paused &&
            (ack.faults & fault::paper_out) == 0 && s->now() - js.last_resume > rto()) {
            js.last_resume = s->now();
            note("resuming");
            step = send(FrameType::resume, {});
        }

        if (data_acked >= js.acked_mark + 8) resize_frames(js.payload_limit * 2);
        // Fill the window with whole chunks the controller has room for.
        while (step && js.next_chunk < js.chunks.size() && unacked.size() < window_frames()) {
            const auto [b, e] = js.chunks[js.next_chunk];
            if (e - b > credit()) break;
            if (data_start < 0) data_start = s->now();
            const std::span<const std::uint8_t> ops(js.stream.bytes.data() + b, e - b);
            step = send(FrameType::data, v3() ? encode::data_payload_v3(ops)
                                              : std::vector<std::uint8_t>(ops.begin(), ops.end()));
            js.bytes_sent += e - b;
            ++js.next_chunk;
        }
        if (step && js.next_chunk == js.chunks.size() && unacked.empty() && data_end < 0)
            data_end = s->now();

        const double now = s->now();
        if (step && !unacked.empty() && now >= unacked.front().sent_at + rto()) {
            ++stats.timeouts;
            resize_frames(js.payload_limit / 2);
            step = resend_all();
        }
        if (step && silent_too_long(last_rx)) {
            step = fail(ErrorKind::device, "no answer from the controller for " + quiet_text(false), device);
        }
        // Nothing outstanding: poll, so a lost ACK never stalls the window and
        // the controller's keep-alive watchdog stays quiet. Poll faster while
        // data is waiting for room in the ring.
        const bool blocked = js.next_chunk < js.chunks.size();
        const double poll = blocked ? std::min(0.1, seconds(opt.keepalive_period))
                                    : seconds(opt.keepalive_period);
        if (step && unacked.empty() && now - last_tx >= poll) step = send(FrameType::keepalive, {});

        double wait = unacked.empty() ? poll - (s->now() - last_tx)
                                      : unacked.front().sent_at + rto() - s->now();
        wait = std::clamp(wait, 0.0005, 0.5);
        if (step) step = pump(wait);
        if (!step) {
            if (refused) return finish(JobEnd::failed, *refused);
            if (auto r = recover_device(step.error()); !r) return finish(JobEnd::failed, r.error());
        }
    }
}

}  // namespace tactus::link
