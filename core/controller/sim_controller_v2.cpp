// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated controller speaking protocol 2 (docs/protocol.md, step
// segments in the job stream): its frames after the shared session checks
// (sim_controller.cpp), its reset, and the executor that runs the ring's ops
// in simulated time.
#include <algorithm>
#include <cstdlib>

#include "controller/sim_controller.hpp"

namespace tactus::controller {

using encode::ControllerState;
using encode::FrameType;
using encode::NakReason;
using encode::Op;
using encode::OpCode;
namespace fault = encode::fault;

bool SimController::move_buffered(std::size_t first_op_size) const {
    std::size_t pos = first_op_size;
    while (pos < ring_.size()) {
        const auto d = encode::decode_op(std::span(ring_).subspan(pos));
        if (!d) return true;  // checked on receipt; cannot happen
        if (d->first.code != OpCode::move || !d->first.continuation) return true;
        pos += d->second;
    }
    // The rest of the move has not arrived; a full ring cannot wait for it.
    return ring_free() < encode::kMaxPayload;
}

// Protocol 2's reset: the op under way is cut, the registers cleared.
void SimController::v2_boot(double now, bool keep_ram) {
    if (current_) interrupt_op(now);
    current_.reset();
    expected_seq_ = 0;
    session_ = false;
    nonce_ = 0;
    homed_ = false;  // the stepper driver lost power: steps may have slipped
    pause_requested_ = false;
    in_move_ = false;
    decoder_.reset();
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

void SimController::v2_frame(const encode::Frame& f, double now) {
    if (!receiving(now)) return;
    if (f.type == static_cast<std::uint8_t>(FrameType::hello)) {
        const auto h = encode::decode_hello(f.payload);
        if (!h || h->protocol != encode::kProtocolVersion) {
            nak(NakReason::bad_payload);
            return;
        }
        // A repeated HELLO of the same session is answered but changes nothing:
        // a stale duplicate must never rewind the sequence.
        if (!session_ || h->nonce != nonce_) {
            // A new session: the host re-sends the job from the progress it is
            // told, so whatever is buffered is dropped and the job holds still.
            ring_.clear();
            if (job_active_ && (state_ == ControllerState::running ||
                                state_ == ControllerState::waiting || state_ == ControllerState::homing)) {
                pause_requested_ = true;
                set_waiting(false, now);
                if (!current_) {
                    pause_requested_ = false;
                    state_ = ControllerState::paused;
                }
            }
            session_ = true;
            muted_ = false;
            nonce_ = h->nonce;
            expected_seq_ = static_cast<std::uint8_t>(f.seq + 1);
            faults_ &= static_cast<std::uint8_t>(~(fault::power_on_reset | fault::warm_reset));
            if (state_ == ControllerState::fault && faults_ == 0)
                state_ = job_active_ ? ControllerState::paused : ControllerState::idle;
        }
        encode::HelloReply r;
        r.capabilities = encode::capability::interpoint | encode::capability::uart |
                         encode::capability::lpt | encode::capability::warm_restart;
        r.ring_bytes = static_cast<std::uint8_t>(machine::ram::kRingBytes);
        r.max_payload = static_cast<std::uint8_t>(encode::kMaxPayload);
        r.window_frames = static_cast<std::uint8_t>(machine::ram::kWindowFrames);
        reply(FrameType::hello_reply, encode::encode_hello_reply(r));
        return;
    }
    if (!in_sequence(f)) return;
    if (!encode::is_known_type(f.type) || f.type >= 0x80) {
        nak(NakReason::unknown_type);
        return;
    }
    if (f.type == static_cast<std::uint8_t>(FrameType::data)) {
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
        ++expected_seq_;
        ++frames_accepted_;
        advance(now);  // an idle executor starts at once, so the ACK reports the room it makes
        ack();
        return;
    }
    immediate(f, now);
}

void SimController::immediate(const encode::Frame& f, double now) {
    const auto type = static_cast<FrameType>(f.type);
    auto accept = [&] {
        ++expected_seq_;
        ++frames_accepted_;
    };
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
            if (state_ == ControllerState::running || state_ == ControllerState::waiting ||
                state_ == ControllerState::homing)
                pause_requested_ = true;
            advance(now);
            ack();
            return;
        case FrameType::resume:
            if (!f.payload.empty()) break;
            accept();
            pause_requested_ = false;
            faults_ &= static_cast<std::uint8_t>(
                ~(fault::host_timeout | fault::limit_switch | fault::hammer | fault::stream_error |
                  fault::underrun));
            if (paper_present_) faults_ &= static_cast<std::uint8_t>(~fault::paper_out);
            if ((faults_ & (fault::paper_out | fault::power_on_reset | fault::warm_reset)) == 0 &&
                (state_ == ControllerState::paused || state_ == ControllerState::fault))
                state_ = job_active_ ? ControllerState::running : ControllerState::idle;
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
            if (job_active_) job_ended_ = false;  // an aborted job did not run to its end
            job_active_ = false;
            pass_active_ = false;
            pause_requested_ = false;
            in_move_ = false;
            set_waiting(false, now);
            if ((faults_ & (fault::power_on_reset | fault::warm_reset)) == 0) {
                faults_ = 0;
                state_ = ControllerState::idle;
            }
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

std::optional<double> SimController::keepalive_deadline() const {
    if (!session_ || !job_active_ || config_.keepalive_ms == 0) return std::nullopt;
    if (state_ != ControllerState::running && state_ != ControllerState::waiting) return std::nullopt;
    if ((faults_ & fault::host_timeout) != 0) return std::nullopt;
    return last_host_frame_ + config_.keepalive_ms / 1000.0 * options_.keepalive_scale;
}

void SimController::wait_for_data(double now) {
    if (!job_active_ || state_ == ControllerState::waiting) return;
    state_ = ControllerState::waiting;
    set_waiting(true, now);
    if (session_ && ring_free() > free_reported_) ack();  // the host may not know the room
}

void SimController::v2_advance(double t) {
    for (;;) {
        // The earliest of: the op under way ends, the keep-alive runs out, paper arrives.
        std::optional<double> next;
        if (current_) next = op_end_;
        const auto ka = keepalive_deadline();
        if (ka && (!next || *ka < *next)) next = ka;
        if (reload_at_ && (!next || *reload_at_ < *next)) next = reload_at_;
        if (next && *next <= t) {
            now_ = std::max(now_, *next);
            if (current_ && op_end_ <= now_) {
                finish_op();
            } else if (ka && *ka <= now_) {
                // The host went quiet: stop at the next safe point and wait for it.
                faults_ |= fault::host_timeout;
                pause_requested_ = true;
            } else if (reload_at_ && *reload_at_ <= now_) {
                load_paper();
            }
            // Zero-length ops finish at once; run them at this instant, not at t.
            while (!current_ && start_next_op(now_)) {
            }
            continue;
        }
        now_ = std::max(now_, t);
        if (!current_ && start_next_op(now_)) continue;
        break;
    }
}

void SimController::maybe_report_space() {
    // Every further frame's worth of room, and at once when a whole frame first
    // fits: the host holds its next chunk until it knows it fits.
    const std::size_t free = ring_free();
    if (session_ && (free >= free_reported_ + encode::kMaxPayload ||
                     (free >= encode::kMaxPayload && free_reported_ < encode::kMaxPayload)))
        ack();
}

// Starts the op at the head of the ring if the controller may run it. Returns
// whether it did; zero-length ops finish at once.
bool SimController::start_next_op(double now) {
    if (!job_active_ && ring_.empty()) return false;
    if (state_ == ControllerState::paused || state_ == ControllerState::fault) return false;
    std::optional<std::pair<Op, std::size_t>> decoded;
    if (!ring_.empty()) {
        auto d = encode::decode_op(ring_);
        if (!d) {  // cannot happen: ops are checked on receipt
            stop_job(fault::stream_error, now);
            return false;
        }
        decoded = std::move(*d);
    }
    const bool continuation =
        decoded && decoded->first.code == OpCode::move && decoded->first.continuation;
    // A safe point: the carriage is at rest, not between two parts of one move.
    if (pause_requested_ && !continuation) {
        pause_requested_ = false;
        state_ = ControllerState::paused;
        set_waiting(false, now);
        ack();
        return false;
    }
    if (!decoded) {
        wait_for_data(now);
        return false;
    }
    const Op& op = decoded->first;
    // A move starts only once all of it is in the ring (or the ring is full):
    // running short of data stops the carriage at rest, never mid-ramp.
    if (op.code == OpCode::move && !continuation && !move_buffered(decoded->second)) {
        wait_for_data(now);
        return false;
    }
    if (in_move_ && !continuation) in_move_ = false;
    if (!job_active_ && op.code != OpCode::job_begin) {  // ops outside a job: a host bug
        stop_job(fault::stream_error, now);
        return false;
    }
    if (op.code == OpCode::sheet_begin && paper_out_sheet_ && *paper_out_sheet_ == op.id)
        paper_present_ = false;
    if (op.code == OpCode::sheet_begin && !paper_present_) {
        faults_ |= fault::paper_out;
        state_ = ControllerState::fault;
        set_waiting(false, now);
        if (options_.reload_paper_after_s >= 0) reload_at_ = now + options_.reload_paper_after_s;
        ack();
        return false;
    }
    if (op.code == OpCode::strike && skip_ == 0) {
        const std::size_t nth = strike_count_ + 1;
        if (limit_at_ && *limit_at_ == nth) {
            limit_at_.reset();
            homed_ = false;
            stop_job(fault::limit_switch, now);
            return false;
        }
        if (hammer_at_ && *hammer_at_ == nth) {
            hammer_at_.reset();
            stop_job(fault::hammer, now);
            return false;
        }
    }
    if ((op.code == OpCode::strike || (op.code == OpCode::seek && op.axis == encode::Axis::carriage)) &&
        !homed_) {
        stop_job(fault::stream_error, now);  // the host must home before positioning
        return false;
    }
    ring_.erase(ring_.begin(), ring_.begin() + static_cast<std::ptrdiff_t>(decoded->second));
    if (job_active_ && state_ == ControllerState::waiting) {
        if (in_move_ && continuation) ++underruns_;
        state_ = ControllerState::running;
        set_waiting(false, now);
    }
    current_ = op;
    op_start_ = now;
    double duration = 0;
    switch (op.code) {
        case OpCode::job_begin:
            job_id_ = op.id;
            job_active_ = true;
            job_ended_ = false;
            executed_passes_ = op.first_pass;
            strikes_in_pass_ = 0;
            pass_active_ = false;
            state_ = ControllerState::running;
            break;
        case OpCode::job_end: break;
        case OpCode::sheet_begin: duration = options_.instant_motion ? 0 : options_.sheet_load_s; break;
        case OpCode::sheet_end: duration = options_.instant_motion ? 0 : options_.sheet_eject_s; break;
        case OpCode::pass_begin:
            pass_index_ = op.id;
            pass_active_ = true;
            skip_ = op.skip;
            strikes_in_pass_ = op.skip;
            break;
        case OpCode::pass_end: break;
        case OpCode::move:
            duration = ticks_to_s(encode::segment_ticks(op.segments));
            in_move_ = true;
            break;
        case OpCode::strike:
            if (skip_ == 0) {
                // At rest on the dot for the planned settle, then the hammer.
                const double wait = ticks_to_s(op.wait_ticks);
                LoggedStrike l;
                l.sheet = sheet_;
                l.hammer = op.hammer;
                l.side = op.hammer == plan::Hammer::convex ? plan::Side::front : plan::Side::back;
                l.carriage_step = carriage_;
                l.feed_step = feed_;
                l.pass_index = pass_index_;
                l.job_id = job_id_;
                l.time_s = now + wait;
                l.x_mm = carriage_ * 1000.0 / config_.carriage_steps_per_m;
                l.y_mm = feed_ * 1000.0 / config_.feed_steps_per_m;
                log_.push_back(l);
                duration = wait + ticks_to_s(config_.hammer_ticks);
            }
            break;
        case OpCode::home:
            state_ = ControllerState::homing;
            seek_from_ = carriage_;
            duration = ticks_to_s(static_cast<std::uint64_t>(std::abs(carriage_)) *
                                  config_.home_interval_ticks);
            break;
        case OpCode::seek: {
            const std::int32_t from = op.axis == encode::Axis::carriage ? carriage_ : feed_;
            seek_from_ = from;
            duration = ticks_to_s(static_cast<std::uint64_t>(std::abs(op.value - from)) *
                                  config_.home_interval_ticks);
            break;
        }
    }
    op_end_ = now + duration;
    maybe_report_space();
    if (duration <= 0) finish_op();
    return true;
}

void SimController::finish_op() {
    const Op op = *current_;
    current_.reset();
    switch (op.code) {
        case OpCode::job_end:
            job_active_ = false;
            job_ended_ = true;
            state_ = ControllerState::idle;
            set_waiting(false, now_);
            ack();
            break;
        case OpCode::sheet_begin:
            sheet_ = op.id;
            feed_ = op.value;
            break;
        case OpCode::sheet_end: sheet_ = 0; break;
        case OpCode::pass_end:
            executed_passes_ = static_cast<std::uint16_t>(pass_index_ + 1);
            pass_active_ = false;
            strikes_in_pass_ = 0;
            if (mute_after_ && executed_passes_ == *mute_after_) {
                mute_after_.reset();
                muted_ = true;
            }
            if (wedge_after_ && executed_passes_ == *wedge_after_) {
                wedge_after_.reset();
                wedged_ = true;
            }
            ack();  // the host counts a pass only when it is executed
            break;
        case OpCode::move: {
            const auto steps = static_cast<std::int32_t>(encode::segment_steps(op.segments));
            auto& pos = op.axis == encode::Axis::carriage ? carriage_ : feed_;
            pos += op.negative ? -steps : steps;
            if (op.axis == encode::Axis::carriage &&
                (carriage_ < 0 || carriage_ > config_.carriage_travel_steps)) {
                homed_ = false;
                stop_job(fault::limit_switch, now_);
            }
            break;
        }
        case OpCode::strike:
            if (skip_ > 0) {
                --skip_;
                break;
            }
            ++strike_count_;
            ++strikes_in_pass_;
            if (reset_at_ && *reset_at_ == strike_count_) {
                reset_at_.reset();
                ++resets_;
                boot(now_, reset_keeps_ram_);
                return;
            }
            break;
        case OpCode::home:
            carriage_ = 0;
            homed_ = true;
            if (state_ == ControllerState::homing) state_ = ControllerState::running;
            break;
        case OpCode::seek:
            (op.axis == encode::Axis::carriage ? carriage_ : feed_) = op.value;
            break;
        case OpCode::job_begin:
        case OpCode::pass_begin: break;
    }
}

// The op under way is cut short (reset, abort): positions are where the steps
// done so far put them, as the firmware counts each step.
void SimController::interrupt_op(double now) {
    if (!current_) return;
    const Op& op = *current_;
    const double elapsed_ticks = (now - op_start_) * machine::kTickHz;
    if (op.code == OpCode::move) {
        const auto total = encode::segment_steps(op.segments);
        std::uint32_t lo = 0, hi = total;  // largest k with tick_of_step(k) <= elapsed
        while (lo < hi) {
            const std::uint32_t mid = (lo + hi + 1) / 2;
            if (static_cast<double>(encode::tick_of_step(op.segments, mid)) <= elapsed_ticks)
                lo = mid;
            else
                hi = mid - 1;
        }
        const auto steps = static_cast<std::int32_t>(lo);
        (op.axis == encode::Axis::carriage ? carriage_ : feed_) += op.negative ? -steps : steps;
    } else if (op.code == OpCode::seek || op.code == OpCode::home) {
        const std::int32_t target = op.code == OpCode::home ? 0 : op.value;
        auto& pos = (op.code == OpCode::home || op.axis == encode::Axis::carriage) ? carriage_ : feed_;
        const auto done = static_cast<std::int32_t>(elapsed_ticks / config_.home_interval_ticks);
        const std::int32_t dist = target - seek_from_;
        const std::int32_t moved = std::min(std::abs(dist), done);
        pos = seek_from_ + (dist < 0 ? -moved : moved);
    } else if (op.code == OpCode::strike && skip_ == 0) {
        // The hammer already fired when the op started: the strike counts.
        ++strike_count_;
        ++strikes_in_pass_;
    }
    current_.reset();
}

// A fault that ends the buffered stream: the host restarts the job from the
// progress the controller reports (executed passes, strikes in the pass).
void SimController::stop_job(std::uint8_t fault_bits, double now) {
    if (current_) interrupt_op(now);
    faults_ |= fault_bits;
    state_ = ControllerState::fault;
    ring_.clear();
    pause_requested_ = false;
    in_move_ = false;
    set_waiting(false, now);
    if (session_) ack();
}

}  // namespace tactus::controller
