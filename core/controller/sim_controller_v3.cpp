// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated controller speaking protocol 3, as the reference firmware does
// (docs/protocol.md, "Version 3 on the host"): its link, each rule the
// firmware's in the same order (firmware/src/link.c: sessions, window,
// duplicates, the DATA check, the job-stream check as bytes are copied in),
// and its reset, after the shared session checks (sim_session.cpp). The
// executor (exec.c) is in sim_controller_v3_exec.cpp. The
// conformance suite (tests/link/protocol_conformance_test.cpp) runs the same
// cases against both, so they cannot drift apart.
#include <algorithm>

#include "controller/sim_controller_v3.hpp"
#include "encode/crc16.hpp"
#include "encode/stream_v3.hpp"

namespace tactus::controller {

using encode::ControllerState;
using encode::FrameType;
using encode::NakReason;
namespace fault = encode::fault;
namespace op3 = encode::v3;
namespace pf = encode::v3::pass_flag;

namespace {

// link.c's vstate.st
enum : std::uint8_t { VS_OP, VS_FIXED, VS_FLAGS, VS_SKIP, VS_FEED, VS_FEED2, VS_FIRST, VS_FIRST2, VS_N, VS_ENTRY, VS_ENTRY2 };

}  // namespace

SimControllerV3::SimControllerV3(SimOptions options) : SimSession(std::move(options)) { boot(0, false); }

std::size_t SimControllerV3::ring_free() const {
    return ring_.size() >= v3::kRingBytes ? 0 : v3::kRingBytes - ring_.size();
}

void SimControllerV3::flush() {
    ring_.clear();
    ops_done_ = 0;
    check_ = {};
}

// main.c: a warm start keeps RAM (progress, the pass flag, the counters) and
// clears the registers; a cold one starts from nothing.
void SimControllerV3::boot(double now, bool keep_ram) {
    // The timer stops with the chip: a phase under way is cut where it is,
    // its steps already counted (exec.c counts a move when it starts).
    phase_busy_ = false;
    last_event_ = now - 1;  // nothing scheduled: the next phase starts when given
    reset_link();
    flush();
    set_waiting(false, now);
    xs_ = X::fetch;
    c_neg_ = false;  // exec_init
    f_neg_ = false;
    fired_ = false;
    p_drop_ = false;
    if (keep_ram) {
        faults_ |= fault::warm_reset;
        state_ = job_active_ ? ControllerState::fault : ControllerState::idle;
    } else {
        power_on_ram();
        cfg_travel_ = cfg_home_iv_ = cfg_hammer_ = cfg_settle_ = 0;
    }
    free_reported_ = ring_free();
}

// --- the link (link.c)

void SimControllerV3::frame(const encode::Frame& f, double now) {
    if (!receiving(now)) return;
    // The firmware's receive area is what the ring leaves free plus its slack:
    // a frame that cannot be stored there is a false start (decoder.c), never
    // answered.
    if (f.payload.size() + encode::kFrameOverhead - 1 > v3::kBufferBytes - ring_.size()) return;
    if (f.type == static_cast<std::uint8_t>(FrameType::hello)) {
        hello(f, now);
        return;
    }
    if (!in_sequence(f)) return;
    if (f.type == static_cast<std::uint8_t>(FrameType::data)) {
        data(f, now);
        return;
    }
    if (f.type < static_cast<std::uint8_t>(FrameType::configure) ||
        f.type > static_cast<std::uint8_t>(FrameType::keepalive)) {
        nak(NakReason::unknown_type);
        return;
    }
    control(f, now);
}

void SimControllerV3::hello(const encode::Frame& f, double now) {
    // A HELLO of a new session, whichever version it offers, comes from a
    // host that replaced the one that died with a reply on the wire
    // (mute_after_pass): the line back works again. Unmuted only on the v3
    // HELLO, the refusal of the new host's protocol-2 offer was never heard
    // and it gave up ("no answer to HELLO").
    if (f.payload.size() >= 2 &&
        (!session_ || static_cast<std::uint16_t>((f.payload[0] << 8) | f.payload[1]) != nonce_))
        muted_ = false;
    if (f.payload.size() != 3 || f.payload[2] != encode::kProtocolV3) {
        nak(NakReason::bad_payload);
        return;
    }
    const auto n = static_cast<std::uint16_t>((f.payload[0] << 8) | f.payload[1]);
    if (new_session(n)) {
        // A new session: the host re-sends the job from the progress it is
        // told, so whatever is buffered is dropped and the job holds still.
        flush();
        if (job_active_ && job_moving()) {
            if (busy()) {
                pause_requested_ = true;
            } else {
                state_ = ControllerState::paused;
                set_waiting(false, now);
            }
        }
        // The rest of a pass under way was in the ring: the executor leaves
        // it at the next safe point (exec.c exec_drop_pass). Without this it
        // took the new host's stream as that pass's strikes.
        if (xs_ == X::feed || xs_ == X::move || xs_ == X::settle || xs_ == X::dwell || xs_ == X::next)
            p_drop_ = true;
        open_session(n, f.seq);
    }
    encode::HelloReply r;
    r.protocol = encode::kProtocolV3;
    r.firmware_major = v3::kFirmwareMajor;
    r.firmware_minor = v3::kFirmwareMinor;
    r.capabilities = encode::capability::interpoint | encode::capability::lpt | encode::capability::uart |
                     encode::capability::warm_restart;
    r.ring_bytes = static_cast<std::uint8_t>(v3::kRingBytes);
    r.max_payload = static_cast<std::uint8_t>(v3::kMaxPayload);
    r.window_frames = static_cast<std::uint8_t>(v3::kWindowFrames);
    r.table_id = options_.firmware->table_id;
    reply(FrameType::hello_reply, encode::encode_hello_reply(r));
}

// link.c check_ops: the job-stream grammar over one payload's ops, carried
// across frames. Sets ops_done_ past the last thing the executor may start: a
// whole op, a pass header, or a whole strike entry (passes stream).
bool SimControllerV3::check_ops(std::span<const std::uint8_t> p) {
    std::size_t done_at = 0;
    auto& vs = check_;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const std::uint8_t b = p[i];
        switch (vs.st) {
            case VS_OP:
                switch (b) {
                    case op3::op_job_end:
                    case op3::op_sheet_end:
                    case op3::op_home: done_at = i + 1; continue;
                    case op3::op_job_begin: vs.n = 4; vs.st = VS_FIXED; continue;
                    case op3::op_sheet_begin:
                    case op3::op_seek_carriage:
                    case op3::op_seek_feed: vs.n = 2; vs.st = VS_FIXED; continue;
                    case op3::op_pass: vs.st = VS_FLAGS; continue;
                    default: return false;
                }
            case VS_FIXED:
                if (--vs.n == 0) {
                    vs.st = VS_OP;
                    done_at = i + 1;
                }
                continue;
            case VS_FLAGS:
                if (b & static_cast<std::uint8_t>(~pf::all)) return false;
                vs.flags = b;
                vs.st = (b & pf::skip) ? VS_SKIP : VS_FEED;
                continue;
            case VS_SKIP: vs.skip = b; vs.st = VS_FEED; continue;
            case VS_FEED: vs.st = (b & 0x80) ? VS_FEED2 : VS_FIRST; continue;
            case VS_FEED2: vs.st = VS_FIRST; continue;
            case VS_FIRST: vs.st = (b & 0x80) ? VS_FIRST2 : VS_N; continue;
            case VS_FIRST2: vs.st = VS_N; continue;
            case VS_N:
                if ((vs.flags & pf::skip) && vs.skip > b) return false;
                vs.n = b;
                vs.st = b ? VS_ENTRY : VS_OP;
                done_at = i + 1;  // the header: the feed may start
                continue;
            case VS_ENTRY:
                if (b & op3::entry::ext) {
                    vs.st = VS_ENTRY2;
                    continue;
                }
                [[fallthrough]];
            case VS_ENTRY2:
                vs.st = --vs.n ? VS_ENTRY : VS_OP;
                done_at = i + 1;
                continue;
            default: return false;
        }
    }
    if (done_at) ops_done_ = ring_.size() + done_at;
    return true;
}

void SimControllerV3::data(const encode::Frame& f, double now) {
    if (f.payload.size() < 3 || f.payload.size() > v3::kMaxPayload) {
        nak(NakReason::bad_payload);
        return;
    }
    const auto ops = std::span(f.payload).first(f.payload.size() - 2);
    const auto check = static_cast<std::uint16_t>((f.payload[ops.size()] << 8) | f.payload[ops.size() + 1]);
    if (encode::data_check_v3(ops) != check) {
        // The frame CRC passed but the DATA check did not: an error the frame
        // CRC missed. Dropped like a bad frame (its SEQ cannot be trusted);
        // the host sends it again. Never executed.
        ++data_check_errors_;
        return;
    }
    if (ops.size() > ring_free()) {
        nak(NakReason::no_space);
        return;
    }
    const std::size_t done_before = ops_done_;
    if (!check_ops(ops)) {
        // A malformed op: a host bug, and the ops before it may end
        // mid-record. The ring is dropped with a fault.
        ops_done_ = done_before;
        flush();
        faults_ |= fault::stream_error;
        state_ = ControllerState::fault;
        if (busy()) abort_motion();
        nak(NakReason::bad_payload);
        return;
    }
    accept();
    ring_.insert(ring_.end(), ops.begin(), ops.end());
    max_ring_used_ = std::max(max_ring_used_, ring_.size());
    ack();
    advance(now);  // the main loop runs on: an idle executor starts what arrived
}

void SimControllerV3::control(const encode::Frame& f, double now) {
    const auto type = static_cast<FrameType>(f.type);
    if (type == FrameType::configure) {
        const auto& p = f.payload;
        auto be16 = [&](std::size_t i) { return static_cast<std::uint16_t>((p[i] << 8) | p[i + 1]); };
        // A homing interval below what the step interrupt keeps up with, or a
        // hammer pulse of zero, would silently misbehave: refused.
        if (p.size() != 10 || be16(0) == 0 || be16(2) < 64 || be16(4) == 0) {
            nak(NakReason::bad_payload);
            return;
        }
        cfg_travel_ = be16(0);
        cfg_home_iv_ = be16(2);
        cfg_hammer_ = be16(4);
        cfg_settle_ = be16(6);
        // The firmware takes the keep-alive but does not enforce it (firmware/README.md, "Not done").
        config_.carriage_travel_steps = cfg_travel_;
        config_.home_interval_ticks = cfg_home_iv_;
        config_.hammer_ticks = cfg_hammer_;
        config_.keepalive_ms = be16(8);
        configured_ = true;
        accept();
        ack();
        return;
    }
    if (!f.payload.empty()) {
        nak(NakReason::bad_payload);
        return;
    }
    accept();
    const bool in_motion = busy();
    switch (type) {
        case FrameType::pause:
            if (job_moving()) {
                if (in_motion) {
                    pause_requested_ = true;
                } else {
                    state_ = ControllerState::paused;
                    set_waiting(false, now);
                }
            }
            break;
        case FrameType::resume:
            resume_job();
            break;
        case FrameType::abort:
            abort_motion();
            flush();
            abort_job(now);
            break;
        case FrameType::status: reply(FrameType::status_reply, encode::encode_status(status())); return;
        default: break;  // KEEPALIVE: the ACK is the point
    }
    ack();
    advance(now);
}

}  // namespace tactus::controller
