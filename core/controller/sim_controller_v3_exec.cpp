// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated controller's executor in protocol 3, as the reference
// firmware's firmware/src/exec.c runs it: pass records streamed entry by
// entry, table moves, settle and hammer pulse, backlash on a reversal,
// faults. Its link (link.c: sessions, the DATA check) is in
// sim_controller_v3.cpp.
//
// Times follow the firmware's timer schedule (docs/protocol.md, "Timing"): every
// phase is scheduled from the last timer event before it, a move's first step
// start_gap + T[0] after it, the hammer the settle after the last step, up the
// pulse later; a phase the executor comes to late (it waited for data or for
// RESUME) starts from when it is given.
#include <algorithm>
#include <cstdlib>

#include "controller/sim_controller_v3.hpp"
#include "encode/stream_v3.hpp"

namespace tactus::controller {

using encode::ControllerState;
using encode::FrameType;
using encode::NakReason;
namespace fault = encode::fault;
namespace op3 = encode::v3;
namespace pf = encode::v3::pass_flag;

namespace {

constexpr std::uint64_t kMinTimerGap = 64;  // motion.c start(): timer_go never closer than 64 cycles

}  // namespace

// --- the executor (exec.c)

// Leaves a dropped pass at a safe point (at rest): it stays active, with its
// strike count, and the job holds still until RESUME.
bool SimControllerV3::dropped() {
    if (!p_drop_) return false;
    p_drop_ = false;
    xs_ = X::fetch;
    pause_here(now_);
    return true;
}

void SimControllerV3::phase(double now, std::uint64_t first_ticks, std::uint64_t total_ticks) {
    if (first_ticks < kMinTimerGap) {
        total_ticks += kMinTimerGap - first_ticks;
        first_ticks = kMinTimerGap;
    }
    if (options_.instant_motion) {
        phase_end_ = now;
    } else {
        const double on_time = last_event_ + static_cast<double>(first_ticks) / machine::kTickHz;
        const double base = now <= on_time ? last_event_ : now;
        phase_end_ = base + static_cast<double>(total_ticks) / machine::kTickHz;
    }
    phase_busy_ = true;
}

void SimControllerV3::abort_motion() {
    // A move cut short leaves the counter at its target, not where the steps
    // got to: the position is no longer known until the next HOME.
    if (phase_busy_) {
        homed_ = false;
        last_event_ = now_ - 1;
    }
    phase_busy_ = false;
    xs_ = X::fetch;
    // The pass stays active: strikes in pass counts what it struck, and the
    // host's restart skips exactly those (ABORT clears the flag itself).
}

void SimControllerV3::stop_on_fault(std::uint8_t bits, double now) {
    abort_motion();
    faults_ |= bits;
    state_ = ControllerState::fault;
    flush();
    set_waiting(false, now);
    ack();
}

std::uint32_t SimControllerV3::uvar(std::size_t& i) const {
    const std::uint8_t b = at(i++);
    if (!(b & 0x80)) return b;
    return (static_cast<std::uint32_t>(b & 0x7F) << 8) | at(i++);
}

std::int32_t SimControllerV3::svar(std::size_t& i) const {
    const bool two = (at(i) & 0x80) != 0;
    const auto u = static_cast<std::int32_t>(uvar(i));
    if (two) return (u & 0x4000) ? u - 0x8000 : u;
    return (u & 0x40) ? u - 128 : u;
}

// A carriage move of `steps` toward home when `neg`; a reversal adds the
// backlash to the motor's move (the sources' rule), counted in the position.
void SimControllerV3::carriage(std::uint32_t steps, bool neg, double now) {
    if (steps == 0) return;
    const auto& t = options_.firmware->carriage;
    std::uint32_t motor = steps;
    if (neg != c_neg_) motor += t.backlash_steps;
    c_neg_ = neg;
    carriage_ += neg ? -static_cast<std::int32_t>(motor) : static_cast<std::int32_t>(motor);
    const auto gap = options_.firmware->start_gap_ticks;
    phase(now, gap + t.interval(1, motor), gap + t.move_ticks(motor));
}

void SimControllerV3::pass_begin(double now) {
    std::size_t i = 1;
    p_flags_ = at(i++);
    skip_ = 0;
    if (p_flags_ & pf::skip) skip_ = at(i++);
    const std::int32_t feed = svar(i);
    p_first_ = uvar(i);
    p_left_ = at(i++);
    ring_.erase(ring_.begin(), ring_.begin() + static_cast<std::ptrdiff_t>(i));
    ops_done_ -= i;
    strikes_in_pass_ = skip_;
    pass_active_ = true;
    xs_ = X::feed;
    if (!(p_flags_ & pf::no_feed) && feed != 0) {
        const bool neg = feed < 0;
        const auto& t = options_.firmware->feed;
        std::uint32_t steps = static_cast<std::uint32_t>(std::abs(feed)) * t.grid_steps;
        if (neg != f_neg_) steps += t.backlash_steps;
        f_neg_ = neg;
        feed_ += neg ? -static_cast<std::int32_t>(steps) : static_cast<std::int32_t>(steps);
        const auto gap = options_.firmware->start_gap_ticks;
        phase(now, gap + t.interval(1, steps), gap + t.move_ticks(steps));
    }
}

void SimControllerV3::strike_move(double now) {
    const std::uint8_t e = at(0);
    ham_ccv_ = (e & op3::entry::concave) != 0;
    const auto grid = options_.firmware->carriage.grid_steps;
    if (p_is_first_) {
        carriage(p_first_ * grid, (p_flags_ & pf::first_neg) != 0, now);
    } else {
        std::uint32_t d = e & op3::entry::dist;
        if (e & op3::entry::ext) d = (d << 8) | at(1);
        carriage(d * grid, (p_flags_ & pf::sweep_neg) != 0, now);
    }
    xs_ = X::move;
}

void SimControllerV3::pass_end() {
    ++pass_index_;
    executed_passes_ = pass_index_;
    xs_ = X::fetch;
    pass_executed();
}

// exec.c fetch(): the next op at the head of the ring. Returns whether
// anything changed (the main loop polls again at once).
bool SimControllerV3::fetch(double now) {
    if (state_ == ControllerState::paused || state_ == ControllerState::fault) return false;
    if (ops_done_ == 0) {
        wait_for_data(now);
        return false;
    }
    if (pause_requested_) {
        pause_here(now);
        return true;
    }
    const std::uint8_t op = at(0);
    if (!job_active_ && op != op3::op_job_begin) {
        stop_on_fault(fault::stream_error, now);  // ops outside a job: a host bug
        return true;
    }
    if (state_ == ControllerState::waiting) {
        state_ = ControllerState::running;
        set_waiting(false, now);
    }
    auto be16 = [&](std::size_t i) { return static_cast<std::uint16_t>((at(i) << 8) | at(i + 1)); };
    auto consume = [&](std::size_t n) {
        ring_.erase(ring_.begin(), ring_.begin() + static_cast<std::ptrdiff_t>(n));
        ops_done_ -= n;
    };
    switch (op) {
        case op3::op_job_begin:
            job_id_ = be16(1);
            pass_index_ = be16(3);
            executed_passes_ = pass_index_;
            strikes_in_pass_ = 0;
            job_active_ = true;
            job_ended_ = false;
            state_ = ControllerState::running;
            consume(5);
            ack();
            break;
        case op3::op_job_end:
            consume(1);
            job_active_ = false;
            job_ended_ = true;
            state_ = ControllerState::idle;
            set_waiting(false, now);
            ack();
            break;
        case op3::op_sheet_begin:
            // Nothing is dropped without paper: the op runs again once paper is in.
            if (!paper_for_sheet(be16(1), now)) return true;
            sheet_ = be16(1);
            feed_ = 0;  // the sheet's top edge is the feed origin
            consume(3);
            break;
        case op3::op_sheet_end:
            sheet_ = 0;
            consume(1);
            break;
        case op3::op_home: {
            consume(1);
            state_ = ControllerState::homing;
            c_neg_ = true;
            xs_ = X::home;
            // As the emulated chip: the carriage reaches the switch after
            // exactly its counted steps, at the homing interval.
            if (carriage_ > 0) {
                const std::uint64_t gap = options_.firmware->start_gap_ticks;
                const auto n = static_cast<std::uint64_t>(carriage_);
                phase(now, gap + cfg_home_iv_, gap + n * cfg_home_iv_);
            }
            break;
        }
        case op3::op_seek_carriage:
        case op3::op_seek_feed: {
            const auto target = static_cast<std::int16_t>(be16(1));
            const bool feed = op == op3::op_seek_feed;
            const std::int32_t from = feed ? feed_ : carriage_;
            const std::int32_t d = target - from;
            consume(3);
            if (!feed && (!homed_ || target < 0 || target > cfg_travel_)) {
                stop_on_fault(fault::stream_error, now);
                return true;
            }
            if (d == 0) break;
            if (feed) {
                f_neg_ = d < 0;
                feed_ = target;
            } else {
                c_neg_ = d < 0;
                carriage_ = target;
            }
            const std::uint64_t gap = options_.firmware->start_gap_ticks;
            phase(now, gap + cfg_home_iv_, gap + static_cast<std::uint64_t>(std::abs(d)) * cfg_home_iv_);
            xs_ = X::seek;
            break;
        }
        case op3::op_pass:
            if (!homed_) {
                stop_on_fault(fault::stream_error, now);  // the host must home before positioning
                return true;
            }
            pass_begin(now);
            break;
        default: stop_on_fault(fault::stream_error, now); break;  // checked on receipt: cannot happen
    }
    return true;
}

// exec.c exec_poll(), once the phase under way (if any) is done.
bool SimControllerV3::poll(double now) {
    if (phase_busy_) return false;
    switch (xs_) {
        case X::fetch: return fetch(now);
        case X::home:
            carriage_ = 0;
            homed_ = true;
            state_ = ControllerState::running;
            xs_ = X::fetch;
            return true;
        case X::seek: xs_ = X::fetch; return true;
        case X::feed:
            if (dropped()) return true;
            if (p_left_ == 0) {
                pass_end();
                return true;
            }
            p_is_first_ = true;
            xs_ = X::next;
            return true;
        case X::move:
            if (carriage_ < 0 || carriage_ > cfg_travel_ ||
                (skip_ == 0 && limit_at_ && *limit_at_ == strike_count_ + 1)) {
                if (skip_ == 0 && limit_at_ && *limit_at_ == strike_count_ + 1) limit_at_.reset();
                homed_ = false;
                stop_on_fault(fault::limit_switch, now);
                return true;
            }
            // The hammer comes down at the settle's end, from the timer.
            xs_ = X::settle;
            fired_ = skip_ == 0;
            phase(now, cfg_settle_, cfg_settle_);
            return true;
        case X::settle:
            xs_ = X::dwell;
            if (skip_ > 0) {
                --skip_;  // made before the reset: passed over at the same pace
            } else {
                ++strikes_in_pass_;
                ++strike_count_;
                log_strike(ham_ccv_ ? plan::Hammer::concave : plan::Hammer::convex, now);
            }
            phase(now, cfg_hammer_, cfg_hammer_);
            return true;
        case X::dwell:
            // Both hammers must be back before the head moves on.
            if (fired_ && hammer_at_ && *hammer_at_ == strike_count_) {
                hammer_at_.reset();
                stop_on_fault(fault::hammer, now);
                return true;
            }
            // A reset just after the strike, the head at rest (the emulator's
            // breakpoint on fw_strike_fired is here).
            if (fired_ && reset_at_ && *reset_at_ == strike_count_) {
                fired_ = false;
                reset_at_.reset();
                ++resets_;
                boot(now, reset_keeps_ram_);
                return true;
            }
            fired_ = false;
            if (dropped()) return true;  // the entry went with the ring
            {
                const std::size_t n = (at(0) & op3::entry::ext) ? 2 : 1;
                ring_.erase(ring_.begin(), ring_.begin() + static_cast<std::ptrdiff_t>(n));
                ops_done_ -= n;
            }
            if (--p_left_ == 0) {
                pass_end();
                return true;
            }
            p_is_first_ = false;
            xs_ = X::next;
            if (pause_requested_) {
                // A safe point: at rest between two strikes.
                pause_requested_ = false;
                state_ = ControllerState::paused;
                ack();
            }
            return true;
        case X::next:
            if (dropped()) return true;
            if (state_ == ControllerState::paused || state_ == ControllerState::fault) return false;
            if (ops_done_ == 0) {
                // The next strike's entry has not arrived: wait at rest.
                if (state_ != ControllerState::waiting) {
                    state_ = ControllerState::waiting;
                    set_waiting(true, now);
                    tell_room();
                }
                return false;
            }
            if (state_ == ControllerState::waiting) {
                state_ = ControllerState::running;
                set_waiting(false, now);
            }
            strike_move(now);
            return true;
    }
    return false;
}

std::optional<double> SimControllerV3::next_event() const {
    std::optional<double> t;
    auto consider = [&](std::optional<double> v) {
        if (v && (!t || *v < *t)) t = v;
    };
    if (phase_busy_) consider(phase_end_);
    consider(reload_at_);
    return t;
}

void SimControllerV3::advance(double t) {
    for (;;) {
        // The earliest of: the phase under way ends, the operator loads paper.
        std::optional<double> next;
        if (phase_busy_) next = phase_end_;
        if (reload_at_ && (!next || *reload_at_ < *next)) next = reload_at_;
        if (next && *next <= t) {
            now_ = std::max(now_, *next);
            if (phase_busy_ && phase_end_ <= now_) {
                phase_busy_ = false;
                last_event_ = phase_end_;
            } else if (reload_at_ && *reload_at_ <= now_) {
                load_paper();
            }
        } else {
            now_ = std::max(now_, t);
        }
        // The main loop: poll the executor until it waits for something.
        bool progressed = false;
        while (!phase_busy_ && poll(now_)) progressed = true;
        report_room(v3::kMaxPayload);
        if (next && *next <= t) continue;
        if (!progressed) break;
    }
}

}  // namespace tactus::controller
