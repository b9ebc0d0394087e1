// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated controller's session layer, shared by both protocols: the
// reply frames and what they report, the checks every frame passes (a wedged
// receive path, no session, a duplicate, a gap), resets and power, the paper
// and fault injection, and the dispatch to the protocol spoken:
// sim_controller_v2.cpp (protocol 2) or sim_controller_v3.cpp (protocol 3,
// the reference firmware's).
#include "controller/sim_controller.hpp"

#include <algorithm>
#include <cstdlib>

namespace tactus::controller {

using encode::ControllerState;
using encode::FrameType;
using encode::NakReason;
using encode::Op;
using encode::OpCode;
namespace fault = encode::fault;

std::vector<LoggedStrike> planned_strikes(const plan::JobPlan& plan) {
    std::vector<LoggedStrike> out;
    std::uint16_t index = 0;
    for (const auto& sheet : plan.sheets) {
        for (const auto& pass : sheet.passes) {
            for (const auto& s : pass.strikes) {
                LoggedStrike l;
                l.sheet = static_cast<std::uint16_t>(sheet.index);
                l.side = s.side;
                l.hammer = s.hammer;
                l.carriage_step = s.carriage_step;
                l.feed_step = pass.feed_step;
                l.pass_index = index;
                l.time_s = s.time_s;
                l.x_mm = s.x_mm;
                l.y_mm = s.y_mm;
                out.push_back(l);
            }
            ++index;
        }
    }
    return out;
}

SimController::SimController(SimOptions options) : options_(options) {
    paper_present_ = options_.paper_present;
    boot(0, false);
}

double SimController::ticks_to_s(std::uint64_t ticks) const {
    return options_.instant_motion ? 0.0 : static_cast<double>(ticks) / machine::kTickHz;
}

std::size_t SimController::ring_free() const {
    if (v3_mode()) return v3_ring_free();
    return machine::ram::kRingBytes - ring_.size();
}

encode::AckInfo SimController::ack_info() const {
    encode::AckInfo a;
    a.buffer_free = static_cast<std::uint8_t>(ring_free());
    a.executed_passes = executed_passes_;
    a.state = state_;
    a.faults = faults_;
    a.strikes_in_pass = strikes_in_pass_;
    a.job_id = job_id_;
    return a;
}

encode::Status SimController::status() const {
    encode::Status s;
    s.ack = ack_info();
    s.flags = static_cast<std::uint8_t>(
        (configured_ ? encode::flag::configured : 0) | (homed_ ? encode::flag::homed : 0) |
        (pass_active_ ? encode::flag::pass_active : 0) |
        (paper_present_ ? encode::flag::paper_present : 0) |
        (job_active_ ? encode::flag::job_active : 0) | (job_ended_ ? encode::flag::job_ended : 0));
    s.job_id = job_id_;
    s.sheet = sheet_;
    s.pass_index = pass_index_;
    s.carriage_step = carriage_;
    s.feed_step = feed_;
    s.underruns = underruns_;
    return s;
}

void SimController::reply(FrameType type, std::span<const std::uint8_t> payload) {
    if (muted_) return;  // the line back to the host is dead (mute_after_pass)
    encode::append_frame(out_, expected_seq_, type, payload);
    free_reported_ = ring_free();
}

void SimController::ack() { reply(FrameType::ack, encode::encode_ack(ack_info())); }

void SimController::nak(NakReason why) {
    reply(FrameType::nak, encode::encode_nak(why, ack_info()));
}

std::vector<std::uint8_t> SimController::take_output() { return std::exchange(out_, {}); }

// Power-on or reset. The 8051 clears its SFRs on reset but not its RAM; only a
// power cycle loses RAM, and the firmware tells the two apart by a signature.
void SimController::boot(double now, bool keep_ram) {
    if (v3_mode())
        v3_boot(now, keep_ram);
    else
        v2_boot(now, keep_ram);
}

// A cold start (RAM lost), both protocols: nothing configured, no job, no place.
void SimController::power_on_ram() {
    config_ = {};
    configured_ = false;
    cfg_travel_ = cfg_home_iv_ = cfg_hammer_ = cfg_settle_ = 0;
    state_ = ControllerState::idle;
    faults_ = fault::power_on_reset;
    job_id_ = 0;
    job_active_ = false;
    job_ended_ = false;
    sheet_ = 0;
    pass_index_ = 0;
    pass_active_ = false;
    skip_ = 0;
    executed_passes_ = 0;
    strikes_in_pass_ = 0;
    carriage_ = 0;
    feed_ = 0;
    underruns_ = 0;
}

void SimController::warm_reset(double now) {
    advance(now);
    ++resets_;
    boot(now, true);
}

void SimController::power_loss(double now) {
    advance(now);
    ++resets_;
    boot(now, false);
}

void SimController::reflash(std::optional<machine::FirmwareTables> firmware, double now) {
    advance(now);
    options_.firmware = std::move(firmware);
    ++resets_;
    boot(now, false);
}

void SimController::inject_paper_out_at_sheet(std::uint16_t sheet) { paper_out_sheet_ = sheet; }
void SimController::inject_limit_switch_at_strike(std::size_t nth) { limit_at_ = nth; }
void SimController::inject_hammer_fault_at_strike(std::size_t nth) { hammer_at_ = nth; }
void SimController::reset_at_strike(std::size_t nth, bool keep_ram) {
    reset_at_ = nth;
    reset_keeps_ram_ = keep_ram;
}

void SimController::remove_paper() { paper_present_ = false; }

void SimController::load_paper() {
    paper_present_ = true;
    paper_out_sheet_.reset();
    reload_at_.reset();
    if ((faults_ & fault::paper_out) != 0) {
        faults_ &= static_cast<std::uint8_t>(~fault::paper_out);
        if (state_ == ControllerState::fault && (faults_ & ~fault::host_timeout) == 0)
            state_ = ControllerState::paused;
        if (session_) ack();
    }
}

void SimController::receive(std::span<const std::uint8_t> bytes, double now) {
    advance(now);
    std::vector<encode::Frame> frames;
    // A gap longer than a frame at the slowest rate: whatever is pending was garbage.
    if (now - last_byte_ > kIdleGap) decoder_.idle(frames);
    last_byte_ = now;
    decoder_.push(bytes, frames);
    for (const auto& f : frames) {
        if (v3_mode())
            v3_frame(f, now);
        else
            v2_frame(f, now);
    }
}

// Both protocols' first check (link.c): a receive path that has wedged
// (wedge_after_pass) answers every frame NAK out of order; otherwise the host
// has been heard from now.
bool SimController::receiving(double now) {
    if (wedged_) {
        nak(NakReason::out_of_order);
        return false;
    }
    last_host_frame_ = now;
    return true;
}

// Both protocols' session checks after HELLO (link.c): a frame outside a
// session, a duplicate, a gap. Returns whether it is the frame expected next.
bool SimController::in_sequence(const encode::Frame& f) {
    if (!session_) {
        nak(NakReason::no_session);
        return false;
    }
    const auto diff = static_cast<std::uint8_t>(f.seq - expected_seq_);
    if (diff >= 128) {
        // Already accepted: its ACK was lost. Acknowledge again, execute nothing.
        ++duplicates_;
        ack();
        return false;
    }
    if (diff != 0) {
        nak(NakReason::out_of_order);
        return false;
    }
    return true;
}

std::optional<double> SimController::next_event() const {
    std::optional<double> t;
    auto consider = [&](std::optional<double> v) {
        if (v && (!t || *v < *t)) t = v;
    };
    if (v3_mode()) {
        if (phase_busy_) consider(phase_end_);
        consider(reload_at_);
        return t;
    }
    if (current_) consider(op_end_);
    consider(keepalive_deadline());
    consider(reload_at_);
    return t;
}

void SimController::set_waiting(bool waiting, double now) {
    if (waiting && starved_since_ < 0) starved_since_ = now;
    if (!waiting && starved_since_ >= 0) {
        starved_s_ += now - starved_since_;
        if (now > starved_since_ && waits_.size() < 100'000)
            waits_.push_back({starved_since_, now - starved_since_, executed_passes_});
        starved_since_ = -1;
    }
}

void SimController::advance(double t) {
    if (v3_mode())
        v3_advance(t);
    else
        v2_advance(t);
}

}  // namespace tactus::controller
