// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated controller speaking protocol 2 (docs/protocol.md, step
// segments in the job stream): its frames after the shared session checks
// (sim_session.cpp) and its reset. The executor is in
// sim_controller_v2_exec.cpp.
#include "controller/sim_controller_v2.hpp"

#include <algorithm>

#include "machine/ram_budget.hpp"

namespace tactus::controller {

using encode::ControllerState;
using encode::FrameType;
using encode::NakReason;
namespace fault = encode::fault;

SimControllerV2::SimControllerV2(SimOptions options) : SimSession(std::move(options)) { boot(0, false); }

std::size_t SimControllerV2::ring_free() const { return machine::ram::kRingBytes - ring_.size(); }

// Protocol 2's reset: the op under way is cut, the registers cleared.
void SimControllerV2::boot(double now, bool keep_ram) {
    if (current_) interrupt_op(now);
    current_.reset();
    reset_link();
    in_move_ = false;
    ring_.clear();  // the op under way was cut; the host re-sends from the last known point
    set_waiting(false, now);
    if (keep_ram) {
        faults_ |= fault::warm_reset;
        if (job_active_) state_ = ControllerState::fault;
    } else {
        power_on_ram();
    }
    free_reported_ = ring_free();
}

void SimControllerV2::frame(const encode::Frame& f, double now) {
    if (!receiving(now)) return;
    if (f.type == static_cast<std::uint8_t>(FrameType::hello)) {
        hello(f, now);
        return;
    }
    if (!in_sequence(f)) return;
    if (!encode::is_known_type(f.type) || f.type >= 0x80) {
        nak(NakReason::unknown_type);
        return;
    }
    if (f.type == static_cast<std::uint8_t>(FrameType::data)) {
        data(f, now);
        return;
    }
    immediate(f, now);
}

void SimControllerV2::hello(const encode::Frame& f, double now) {
    const auto h = encode::decode_hello(f.payload);
    if (!h || h->protocol != encode::kProtocolVersion) {
        nak(NakReason::bad_payload);
        return;
    }
    if (new_session(h->nonce)) {
        // A new session: the host re-sends the job from the progress it is
        // told, so whatever is buffered is dropped and the job holds still.
        ring_.clear();
        if (job_active_ && job_moving()) {
            pause_requested_ = true;
            set_waiting(false, now);
            if (!current_) {
                pause_requested_ = false;
                state_ = ControllerState::paused;
            }
        }
        open_session(h->nonce, f.seq);
    }
    encode::HelloReply r;
    r.capabilities = encode::capability::interpoint | encode::capability::uart | encode::capability::lpt |
                     encode::capability::warm_restart;
    r.ring_bytes = static_cast<std::uint8_t>(machine::ram::kRingBytes);
    r.max_payload = static_cast<std::uint8_t>(encode::kMaxPayload);
    r.window_frames = static_cast<std::uint8_t>(machine::ram::kWindowFrames);
    reply(FrameType::hello_reply, encode::encode_hello_reply(r));
}

void SimControllerV2::data(const encode::Frame& f, double now) {
    if (f.payload.size() > ring_free()) {
        nak(NakReason::no_space);
        return;
    }
    // The firmware checks each op's shape as it copies it in, so the executor
    // never meets a malformed op.
    std::size_t pos = 0;
    while (pos < f.payload.size()) {
        const auto op = encode::decode_op(std::span(f.payload).subspan(pos));
        if (!op) {
            nak(NakReason::bad_payload);
            return;
        }
        pos += op->second;
    }
    ring_.insert(ring_.end(), f.payload.begin(), f.payload.end());
    max_ring_used_ = std::max(max_ring_used_, ring_.size());
    accept();
    advance(now);  // an idle executor starts at once, so the ACK reports the room it makes
    ack();
}

void SimControllerV2::immediate(const encode::Frame& f, double now) {
    const auto type = static_cast<FrameType>(f.type);
    switch (type) {
        case FrameType::configure: {
            const auto c = encode::decode_config(f.payload);
            if (!c) {
                nak(NakReason::bad_payload);
                return;
            }
            accept();
            config_ = *c;
            configured_ = true;
            ack();
            return;
        }
        case FrameType::pause:
            if (!f.payload.empty()) break;
            accept();
            if (job_moving()) pause_requested_ = true;
            advance(now);
            ack();
            return;
        case FrameType::resume:
            if (!f.payload.empty()) break;
            accept();
            resume_job();
            last_host_frame_ = now;
            advance(now);
            ack();
            return;
        case FrameType::abort:
            if (!f.payload.empty()) break;
            accept();
            if (current_) interrupt_op(now);
            current_.reset();
            ring_.clear();
            in_move_ = false;
            abort_job(now);
            ack();
            return;
        case FrameType::status:
            if (!f.payload.empty()) break;
            accept();
            reply(FrameType::status_reply, encode::encode_status(status()));
            return;
        case FrameType::keepalive:
            if (!f.payload.empty()) break;
            accept();
            ack();
            return;
        default: break;
    }
    nak(NakReason::bad_payload);
}

std::optional<double> SimControllerV2::keepalive_deadline() const {
    if (!session_ || !job_active_ || config_.keepalive_ms == 0) return std::nullopt;
    if (state_ != ControllerState::running && state_ != ControllerState::waiting) return std::nullopt;
    if ((faults_ & fault::host_timeout) != 0) return std::nullopt;
    return last_host_frame_ + config_.keepalive_ms / 1000.0 * options_.keepalive_scale;
}

}  // namespace tactus::controller
