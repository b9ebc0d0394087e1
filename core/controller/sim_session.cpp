// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated controller's session layer, shared by both protocols
// (sim_session.hpp): the reply frames and what they report, the checks every
// frame passes, what sessions, RESUME and ABORT do to the job, resets and
// power, the paper.
#include "controller/sim_session.hpp"

#include <utility>

namespace tactus::controller {

using encode::ControllerState;
using encode::FrameType;
using encode::NakReason;
namespace fault = encode::fault;

SimSession::SimSession(SimOptions options) : options_(std::move(options)) {
    paper_present_ = options_.paper_present;
}

double SimSession::ticks_to_s(std::uint64_t ticks) const {
    return options_.instant_motion ? 0.0 : static_cast<double>(ticks) / machine::kTickHz;
}

encode::AckInfo SimSession::ack_info() const {
    encode::AckInfo a;
    a.buffer_free = static_cast<std::uint8_t>(ring_free());
    a.executed_passes = executed_passes_;
    a.state = state_;
    a.faults = faults_;
    a.strikes_in_pass = strikes_in_pass_;
    a.job_id = job_id_;
    return a;
}

encode::Status SimSession::status() const {
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

void SimSession::reply(FrameType type, std::span<const std::uint8_t> payload) {
    if (muted_) return;  // the line back to the host is dead (mute_after_pass)
    encode::append_frame(out_, expected_seq_, type, payload);
    free_reported_ = ring_free();
}

void SimSession::ack() { reply(FrameType::ack, encode::encode_ack(ack_info())); }

void SimSession::nak(NakReason why) { reply(FrameType::nak, encode::encode_nak(why, ack_info())); }

std::vector<std::uint8_t> SimSession::take_output() { return std::exchange(out_, {}); }

void SimSession::reset_link() {
    expected_seq_ = 0;
    session_ = false;
    nonce_ = 0;
    homed_ = false;  // the stepper driver lost power: steps may have slipped
    pause_requested_ = false;
    decoder_.reset();
}

void SimSession::power_on_ram() {
    config_ = {};
    configured_ = false;
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

void SimSession::warm_reset(double now) {
    advance(now);
    ++resets_;
    boot(now, true);
}

void SimSession::power_loss(double now) {
    advance(now);
    ++resets_;
    boot(now, false);
}

void SimSession::flashed(std::optional<machine::FirmwareTables> firmware, double now) {
    options_.firmware = std::move(firmware);
    ++resets_;
    boot(now, false);
}

void SimSession::load_paper() {
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

void SimSession::receive(std::span<const std::uint8_t> bytes, double now) {
    advance(now);
    std::vector<encode::Frame> frames;
    // A gap longer than a frame at the slowest rate: whatever is pending was garbage.
    if (now - last_byte_ > kIdleGap) decoder_.idle(frames);
    last_byte_ = now;
    decoder_.push(bytes, frames);
    for (const auto& f : frames) frame(f, now);
}

bool SimSession::receiving(double now) {
    if (wedged_) {
        nak(NakReason::out_of_order);
        return false;
    }
    last_host_frame_ = now;
    return true;
}

bool SimSession::in_sequence(const encode::Frame& f) {
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

void SimSession::accept() {
    ++expected_seq_;
    ++frames_accepted_;
}

void SimSession::open_session(std::uint16_t nonce, std::uint8_t seq) {
    session_ = true;
    muted_ = false;
    nonce_ = nonce;
    expected_seq_ = static_cast<std::uint8_t>(seq + 1);
    faults_ &= static_cast<std::uint8_t>(~(fault::power_on_reset | fault::warm_reset));
    if (state_ == ControllerState::fault && faults_ == 0)
        state_ = job_active_ ? ControllerState::paused : ControllerState::idle;
}

bool SimSession::job_moving() const {
    return state_ == ControllerState::running || state_ == ControllerState::waiting ||
           state_ == ControllerState::homing;
}

void SimSession::resume_job() {
    pause_requested_ = false;
    faults_ &= static_cast<std::uint8_t>(
        ~(fault::host_timeout | fault::limit_switch | fault::hammer | fault::stream_error | fault::underrun));
    if (paper_present_) faults_ &= static_cast<std::uint8_t>(~fault::paper_out);
    if ((faults_ & (fault::paper_out | fault::power_on_reset | fault::warm_reset)) == 0 &&
        (state_ == ControllerState::paused || state_ == ControllerState::fault))
        state_ = job_active_ ? ControllerState::running : ControllerState::idle;
}

void SimSession::abort_job(double now) {
    if (job_active_) job_ended_ = false;  // an aborted job did not run to its end
    job_active_ = false;
    pass_active_ = false;
    pause_requested_ = false;
    set_waiting(false, now);
    if ((faults_ & (fault::power_on_reset | fault::warm_reset)) == 0) {
        faults_ = 0;
        state_ = ControllerState::idle;
    }
}

void SimSession::pause_here(double now) {
    pause_requested_ = false;
    state_ = ControllerState::paused;
    set_waiting(false, now);
    ack();
}

bool SimSession::paper_for_sheet(std::uint16_t sheet, double now) {
    if (paper_out_sheet_ && *paper_out_sheet_ == sheet) paper_present_ = false;
    if (paper_present_) return true;
    faults_ |= fault::paper_out;
    state_ = ControllerState::fault;
    set_waiting(false, now);
    if (options_.reload_paper_after_s >= 0) reload_at_ = now + options_.reload_paper_after_s;
    ack();
    return false;
}

void SimSession::pass_executed() {
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
}

void SimSession::log_strike(plan::Hammer hammer, double time_s) {
    LoggedStrike l;
    l.sheet = sheet_;
    l.hammer = hammer;
    l.side = hammer == plan::Hammer::convex ? plan::Side::front : plan::Side::back;
    l.carriage_step = carriage_;
    l.feed_step = feed_;
    l.pass_index = pass_index_;
    l.job_id = job_id_;
    l.time_s = time_s;
    l.x_mm = carriage_ * 1000.0 / config_.carriage_steps_per_m;
    l.y_mm = feed_ * 1000.0 / config_.feed_steps_per_m;
    log_.push_back(l);
}

void SimSession::set_waiting(bool waiting, double now) {
    if (waiting && starved_since_ < 0) starved_since_ = now;
    if (!waiting && starved_since_ >= 0) {
        starved_s_ += now - starved_since_;
        if (now > starved_since_ && waits_.size() < 100'000)
            waits_.push_back({starved_since_, now - starved_since_, executed_passes_});
        starved_since_ = -1;
    }
}

void SimSession::wait_for_data(double now) {
    if (!job_active_ || state_ == ControllerState::waiting) return;
    state_ = ControllerState::waiting;
    set_waiting(true, now);
    tell_room();
}

void SimSession::tell_room() {
    if (session_ && ring_free() > free_reported_) ack();  // the host may not know the room
}

void SimSession::report_room(std::size_t max_payload) {
    const std::size_t free = ring_free();
    if (session_ &&
        (free >= free_reported_ + max_payload || (free >= max_payload && free_reported_ < max_payload)))
        ack();
}

}  // namespace tactus::controller
