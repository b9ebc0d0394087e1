// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated controller's executor in protocol 2: the ring's ops run in
// simulated time, a move only once all of it is buffered, faults and pauses
// at safe points. Its frames are in sim_controller_v2.cpp.
#include <algorithm>
#include <cstdlib>

#include "controller/sim_controller_v2.hpp"

namespace tactus::controller {

using encode::ControllerState;
using encode::Op;
using encode::OpCode;
namespace fault = encode::fault;

bool SimControllerV2::move_buffered(std::size_t first_op_size) const {
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

std::optional<double> SimControllerV2::next_event() const {
    std::optional<double> t;
    auto consider = [&](std::optional<double> v) {
        if (v && (!t || *v < *t)) t = v;
    };
    if (current_) consider(op_end_);
    consider(keepalive_deadline());
    consider(reload_at_);
    return t;
}

void SimControllerV2::advance(double t) {
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

// Starts the op at the head of the ring if the controller may run it. Returns
// whether it did; zero-length ops finish at once.
bool SimControllerV2::start_next_op(double now) {
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
        pause_here(now);
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
    if (op.code == OpCode::sheet_begin && !paper_for_sheet(op.id, now)) return false;
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
                log_strike(op.hammer, now + wait);
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
    report_room(encode::kMaxPayload);
    if (duration <= 0) finish_op();
    return true;
}

void SimControllerV2::finish_op() {
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
            pass_executed();
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
void SimControllerV2::interrupt_op(double now) {
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
void SimControllerV2::stop_job(std::uint8_t fault_bits, double now) {
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
