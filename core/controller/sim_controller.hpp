// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The simulated 89C52: executes the Tactus protocol as the firmware does, with
// the firmware's RAM budget (ram_budget.hpp). Bytes go in, bytes come out, and
// the job stream is executed in simulated time from the step schedule, so a
// test can compare what was struck with what was planned, step for step.
//
// Which protocol it speaks: version 2 (docs/protocol.md, step segments in the
// job stream) unless SimOptions::firmware gives the ramp tables of a reference
// firmware build, when it speaks version 3 exactly as that firmware does
// (docs/protocol.md; firmware/src/link.c and exec.c are the rules it
// follows): HELLO_REPLY with the tables' id, the firmware's ring and window,
// the DATA check, pass records timed from the tables. One version at a time,
// as on the chip: a HELLO for the other is refused (NAK bad payload), so the
// host's link finds the version the way it finds the firmware's.
//
// One class per protocol speaks it (SimControllerV2, SimControllerV3, over the
// shared session layer SimSession); this one is what callers hold: it picks
// the class from SimOptions::firmware and swaps it when another firmware is
// flashed, keeping what the chip keeps.
//
// It is a pure state machine driven by the caller's clock: receive() bytes that
// arrived at time t, advance(t) to execute up to t, take_output() for the reply
// bytes. SimTransport runs it in-process on virtual time; `tactus-cli sim --pty`
// runs it behind a pseudo-terminal on (scaled) wall time.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "controller/line_end.hpp"
#include "controller/sim_controller_v2.hpp"
#include "controller/sim_controller_v3.hpp"
#include "controller/sim_options.hpp"
#include "controller/sim_session.hpp"
#include "machine/firmware_tables.hpp"

namespace tactus::controller {

class SimController final : public LineEnd {
public:
    explicit SimController(SimOptions options = {});

    // Bytes from the host, arriving at simulated time `now` (seconds).
    void receive(std::span<const std::uint8_t> bytes, double now) override { s_->receive(bytes, now); }
    // Runs the executor up to `now`.
    void advance(double now) override { s_->advance(now); }
    // When something next happens on its own (a step, a strike, a timeout), if anything.
    [[nodiscard]] std::optional<double> next_event() const override { return s_->next_event(); }
    // Reply bytes produced so far (and clears them).
    std::vector<std::uint8_t> take_output() override { return s_->take_output(); }

    // Fault injection.
    // Sheet N has no paper when loaded.
    void inject_paper_out_at_sheet(std::uint16_t sheet) { s_->inject_paper_out_at_sheet(sheet); }
    void load_paper() { s_->load_paper(); }  // operator loads paper
    // The feeder runs empty now: the next sheet loaded finds none.
    void remove_paper() { s_->remove_paper(); }
    // The simulated operator's delay from now on (SimOptions::reload_paper_after_s).
    void set_paper_reload(double seconds) { s_->set_paper_reload(seconds); }
    // Trips before the nth strike (1-based).
    void inject_limit_switch_at_strike(std::size_t nth) { s_->inject_limit_switch_at_strike(nth); }
    void inject_hammer_fault_at_strike(std::size_t nth) { s_->inject_hammer_fault_at_strike(nth); }
    // Watchdog/RST: registers reset, RAM (progress) kept.
    void warm_reset(double now) override { s_->warm_reset(now); }
    void power_loss(double now) override { s_->power_loss(now); }  // power cycle: RAM lost
    // Another firmware flashed (other ramp tables, or none: protocol 2), then
    // a power cycle: RAM lost. The app's built-in simulator takes the tables
    // of the printer profile it is connected for.
    void reflash(std::optional<machine::FirmwareTables> firmware, double now);
    [[nodiscard]] const std::optional<machine::FirmwareTables>& firmware() const { return s_->options().firmware; }
    // Reset just after the nth strike.
    void reset_at_strike(std::size_t nth, bool keep_ram) { s_->reset_at_strike(nth, keep_ram); }
    // From the moment the job-wide executed-pass count reaches `executed`, every
    // reply is dropped until a new session (HELLO with a new nonce): the ACK of
    // that pass never reaches the host, as when the host dies with it on the
    // wire. The kill tests place SIGKILLs exactly at this edge.
    void mute_after_pass(std::uint16_t executed) { s_->mute_after_pass(executed); }
    [[nodiscard]] bool muted() const { return s_->muted(); }
    // From the moment the executed-pass count reaches `executed`, the
    // controller takes no more frames, HELLO included: each is answered NAK
    // *out of order* at the sequence number it expected then, as a receive
    // path that has wedged while the rest still talks. The host's silence
    // timeout never fires; only its bounded give-up ends the job. The
    // executor runs on through what is in its ring.
    void wedge_after_pass(std::uint16_t executed) { s_->wedge_after_pass(executed); }

    [[nodiscard]] const std::vector<LoggedStrike>& strike_log() const { return s_->strike_log(); }
    // The protocol version it speaks (2, or 3 with SimOptions::firmware).
    [[nodiscard]] std::uint8_t protocol() const { return s_->protocol(); }
    // DATA frames whose v3 check failed although their frame CRC passed:
    // dropped unanswered, never executed.
    [[nodiscard]] std::size_t data_check_errors() const { return s_->data_check_errors(); }
    [[nodiscard]] encode::Status status() const { return s_->status(); }
    [[nodiscard]] std::size_t ring_used() const { return s_->ring_used(); }
    [[nodiscard]] std::size_t max_ring_used() const { return s_->max_ring_used(); }
    [[nodiscard]] std::size_t frames_accepted() const { return s_->frames_accepted(); }
    [[nodiscard]] std::size_t duplicates() const { return s_->duplicates(); }
    [[nodiscard]] std::size_t crc_errors() const { return s_->crc_errors(); }
    [[nodiscard]] double starved_seconds() const { return s_->starved_seconds(); }
    // Each time the job waited for data at rest: when, how long, and the
    // executed-pass count then (for the benchmark's account of where).
    using Wait = SimSession::Wait;
    [[nodiscard]] const std::vector<Wait>& waits() const { return s_->waits(); }
    [[nodiscard]] std::size_t resets() const { return s_->resets(); }
    [[nodiscard]] const machine::ControllerConfig& config() const { return s_->config(); }
    // A CONFIGURE has been received since the last reset.
    [[nodiscard]] bool configured() const { return s_->configured(); }

private:
    std::unique_ptr<SimSession> s_;
};

}  // namespace tactus::controller
