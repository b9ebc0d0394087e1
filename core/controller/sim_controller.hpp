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
// It is a pure state machine driven by the caller's clock: receive() bytes that
// arrived at time t, advance(t) to execute up to t, take_output() for the reply
// bytes. SimTransport runs it in-process on virtual time; `tactus-cli sim --pty`
// runs it behind a pseudo-terminal on (scaled) wall time.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "controller/line_end.hpp"
#include "machine/firmware_tables.hpp"
#include "machine/reference_firmware.hpp"
#include "machine/ram_budget.hpp"
#include "encode/frame.hpp"
#include "encode/messages.hpp"
#include "encode/stream.hpp"
#include "plan/plan.hpp"

namespace tactus::controller {

// One dot embossed, in the controller's own units.
struct LoggedStrike {
    std::uint16_t sheet = 0;
    plan::Side side = plan::Side::front;
    plan::Hammer hammer = plan::Hammer::convex;
    std::int32_t carriage_step = 0;
    std::int32_t feed_step = 0;
    std::uint16_t pass_index = 0;
    std::uint16_t job_id = 0;  // the controller job (JOB_BEGIN's id) it belongs to
    double time_s = 0;  // simulated time
    double x_mm = 0;    // carriage_step mapped back with the configured steps/mm
    double y_mm = 0;
    // Time (and the job id) are not part of identity: a retried job strikes
    // later and under another id, not differently.
    bool operator==(const LoggedStrike& o) const {
        return sheet == o.sheet && side == o.side && hammer == o.hammer &&
               carriage_step == o.carriage_step && feed_step == o.feed_step;
    }
};

// The strikes a plan asks for, in the form the controller logs them.
std::vector<LoggedStrike> planned_strikes(const plan::JobPlan& plan);

struct SimOptions {
    bool paper_present = true;
    // Scale factor between controller time and keep-alive time (a pty server
    // running motion 20x faster keeps the host's keep-alive in wall time).
    double keepalive_scale = 1.0;
    // Execute motion instantly (link-efficiency benchmark: the link is the only limit).
    bool instant_motion = false;
    // After a paper-out fault, the operator loads paper this many seconds later
    // (negative: never; load_paper() does it).
    double reload_paper_after_s = -1;
    double sheet_load_s = 0.8;  // pick up and position a sheet
    double sheet_eject_s = 0.8;
    // Speak protocol 3 as the reference firmware built with these ramp tables
    // (its build/ramp.json, profile::load_firmware_tables) does; nullopt:
    // protocol 2. The sheet load and eject times above are v2's: the v3
    // firmware loads and ejects in no time, as the emulated chip does.
    std::optional<machine::FirmwareTables> firmware;
};

// The reference firmware's sizes, what a v3 controller reports in HELLO_REPLY.
namespace v3 = machine::reference_firmware;

class SimController final : public LineEnd {
public:
    explicit SimController(SimOptions options = {});

    // Bytes from the host, arriving at simulated time `now` (seconds).
    void receive(std::span<const std::uint8_t> bytes, double now) override;
    // Runs the executor up to `now`.
    void advance(double now) override;
    // When something next happens on its own (a step, a strike, a timeout), if anything.
    [[nodiscard]] std::optional<double> next_event() const override;
    // Reply bytes produced so far (and clears them).
    std::vector<std::uint8_t> take_output() override;

    // Fault injection.
    void inject_paper_out_at_sheet(std::uint16_t sheet);  // sheet N has no paper when loaded
    void load_paper();                                    // operator loads paper
    void remove_paper();  // the feeder runs empty now: the next sheet loaded finds none
    // The simulated operator's delay from now on (SimOptions::reload_paper_after_s).
    void set_paper_reload(double seconds) { options_.reload_paper_after_s = seconds; }
    void inject_limit_switch_at_strike(std::size_t nth);  // trips before the nth strike (1-based)
    void inject_hammer_fault_at_strike(std::size_t nth);
    void warm_reset(double now) override;   // watchdog/RST: registers reset, RAM (progress) kept
    void power_loss(double now) override;   // power cycle: RAM lost
    // Another firmware flashed (other ramp tables, or none: protocol 2), then
    // a power cycle: RAM lost. The app's built-in simulator takes the tables
    // of the printer profile it is connected for.
    void reflash(std::optional<machine::FirmwareTables> firmware, double now);
    [[nodiscard]] const std::optional<machine::FirmwareTables>& firmware() const { return options_.firmware; }
    void reset_at_strike(std::size_t nth, bool keep_ram);  // reset just after the nth strike
    // From the moment the job-wide executed-pass count reaches `executed`, every
    // reply is dropped until a new session (HELLO with a new nonce): the ACK of
    // that pass never reaches the host, as when the host dies with it on the
    // wire. The kill tests place SIGKILLs exactly at this edge.
    void mute_after_pass(std::uint16_t executed) { mute_after_ = executed; }
    [[nodiscard]] bool muted() const { return muted_; }
    // From the moment the executed-pass count reaches `executed`, the
    // controller takes no more frames, HELLO included: each is answered NAK
    // *out of order* at the sequence number it expected then, as a receive
    // path that has wedged while the rest still talks. The host's silence
    // timeout never fires; only its bounded give-up ends the job. The
    // executor runs on through what is in its ring.
    void wedge_after_pass(std::uint16_t executed) { wedge_after_ = executed; }

    [[nodiscard]] const std::vector<LoggedStrike>& strike_log() const { return log_; }
    // The protocol version it speaks (2, or 3 with SimOptions::firmware).
    [[nodiscard]] std::uint8_t protocol() const {
        return options_.firmware ? encode::kProtocolV3 : encode::kProtocolVersion;
    }
    // DATA frames whose v3 check failed although their frame CRC passed:
    // dropped unanswered, never executed.
    [[nodiscard]] std::size_t data_check_errors() const { return data_check_errors_; }
    [[nodiscard]] encode::Status status() const;
    [[nodiscard]] std::size_t ring_used() const { return ring_.size(); }
    [[nodiscard]] std::size_t max_ring_used() const { return max_ring_used_; }
    [[nodiscard]] std::size_t frames_accepted() const { return frames_accepted_; }
    [[nodiscard]] std::size_t duplicates() const { return duplicates_; }
    [[nodiscard]] std::size_t crc_errors() const { return decoder_.stats().crc_errors; }
    [[nodiscard]] double starved_seconds() const { return starved_s_; }
    // Each time the job waited for data at rest: when, how long, and the
    // executed-pass count then (for the benchmark's account of where).
    struct Wait {
        double at_s = 0;
        double seconds = 0;
        std::uint16_t executed_passes = 0;
    };
    [[nodiscard]] const std::vector<Wait>& waits() const { return waits_; }
    [[nodiscard]] std::size_t resets() const { return resets_; }
    [[nodiscard]] const machine::ControllerConfig& config() const { return config_; }
    // A CONFIGURE has been received since the last reset.
    [[nodiscard]] bool configured() const { return configured_; }

private:
    // --- the session layer, both protocols (sim_controller.cpp)
    void reply(encode::FrameType type, std::span<const std::uint8_t> payload);
    void ack();
    void nak(encode::NakReason why);
    // A wedged receive path answers NAK out of order; false then.
    [[nodiscard]] bool receiving(double now);
    // No session, a duplicate, a gap: answered here; true for the frame expected next.
    [[nodiscard]] bool in_sequence(const encode::Frame& f);
    void boot(double now, bool keep_ram);
    void power_on_ram();
    void set_waiting(bool waiting, double now);
    [[nodiscard]] double ticks_to_s(std::uint64_t ticks) const;
    [[nodiscard]] encode::AckInfo ack_info() const;
    [[nodiscard]] std::size_t ring_free() const;

    // --- protocol 2 (sim_controller_v2.cpp): its frames, reset and executor
    void v2_frame(const encode::Frame& f, double now);
    void v2_boot(double now, bool keep_ram);
    void v2_advance(double t);
    void immediate(const encode::Frame& f, double now);
    bool start_next_op(double now);
    void finish_op();
    void interrupt_op(double now);
    void stop_job(std::uint8_t fault_bits, double now);
    void maybe_report_space();
    [[nodiscard]] std::optional<double> keepalive_deadline() const;

    static constexpr double kIdleGap = 0.1;  // s; one 86-byte frame at 9600 baud
    SimOptions options_;
    encode::FrameDecoder decoder_;
    double last_byte_ = 0;
    std::vector<std::uint8_t> out_;
    double now_ = 0;

    // --- SFRs and registers: lost on any reset
    std::uint8_t expected_seq_ = 0;
    bool session_ = false;
    std::uint16_t nonce_ = 0;
    bool homed_ = false;
    double last_host_frame_ = 0;
    std::size_t free_reported_ = 0;

    // --- RAM: kept by a warm reset, lost by power loss
    machine::ControllerConfig config_{};
    bool configured_ = false;
    encode::ControllerState state_ = encode::ControllerState::idle;
    std::uint8_t faults_ = 0;
    std::vector<std::uint8_t> ring_;  // job-stream ring, at most ram::kRingBytes
    // Out of data mid-job: wait at rest, and tell the host of any room it has not heard of.
    void wait_for_data(double now);
    // Whether the move whose first op (of this size) heads the ring is whole in it.
    [[nodiscard]] bool move_buffered(std::size_t first_op_size) const;
    std::uint16_t job_id_ = 0;
    bool job_active_ = false;
    bool job_ended_ = false;  // job_id_ ran to its JOB_END
    std::uint16_t sheet_ = 0;
    std::uint16_t pass_index_ = 0;
    bool pass_active_ = false;
    std::uint8_t skip_ = 0;
    std::uint16_t executed_passes_ = 0;
    std::uint8_t strikes_in_pass_ = 0;
    std::int32_t carriage_ = 0;
    std::int32_t feed_ = 0;
    std::uint16_t underruns_ = 0;
    bool pause_requested_ = false;
    bool in_move_ = false;  // the last op was a move whose continuation may follow

    // --- executor: the op under way
    std::optional<encode::Op> current_;
    double op_start_ = 0;
    double op_end_ = 0;
    std::int32_t seek_from_ = 0;

    // --- fault injection and statistics
    bool paper_present_ = true;
    std::optional<std::uint16_t> paper_out_sheet_;
    std::optional<double> reload_at_;
    std::size_t strike_count_ = 0;
    std::optional<std::size_t> limit_at_, hammer_at_, reset_at_;
    bool reset_keeps_ram_ = true;
    std::optional<std::uint16_t> mute_after_;
    bool muted_ = false;
    std::optional<std::uint16_t> wedge_after_;
    bool wedged_ = false;
    std::vector<LoggedStrike> log_;
    std::size_t max_ring_used_ = 0;
    std::size_t frames_accepted_ = 0;
    std::size_t duplicates_ = 0;
    std::size_t resets_ = 0;
    double starved_since_ = -1;
    double starved_s_ = 0;
    std::vector<Wait> waits_;

    // --- protocol 3: the reference firmware's link (firmware/src/link.c,
    // sim_controller_v3.cpp) and executor (exec.c, sim_controller_v3_exec.cpp),
    // in the same RAM / register split as above.
    [[nodiscard]] bool v3_mode() const { return options_.firmware.has_value(); }
    void v3_frame(const encode::Frame& f, double now);
    void v3_hello(const encode::Frame& f, double now);
    void v3_data(const encode::Frame& f, double now);
    void v3_control(const encode::Frame& f, double now);
    [[nodiscard]] bool v3_check_ops(std::span<const std::uint8_t> ops);
    void v3_advance(double t);
    [[nodiscard]] bool v3_poll(double now);
    [[nodiscard]] bool v3_fetch(double now);
    void v3_pass_begin(double now);
    void v3_strike_move(double now);
    void v3_pass_end();
    void v3_fault(std::uint8_t bits, double now);
    void v3_abort_motion();
    void v3_flush();
    void v3_boot(double now, bool keep_ram);
    void v3_report_room();
    void v3_starved();
    // A timed phase (a move, a settle, a pulse): its first event comes
    // `first_ticks` after the last event before it (or after `now` when the
    // executor comes to it late: it waited for data or a RESUME), its last
    // `total_ticks` after that same point.
    void v3_phase(double now, std::uint64_t first_ticks, std::uint64_t total_ticks);
    void v3_carriage(std::uint32_t steps, bool neg, double now);
    [[nodiscard]] std::uint8_t v3_at(std::size_t i) const { return ring_[i]; }
    [[nodiscard]] std::uint32_t v3_uvar(std::size_t& i) const;
    [[nodiscard]] std::int32_t v3_svar(std::size_t& i) const;
    [[nodiscard]] std::size_t v3_ring_free() const;

    enum class X : std::uint8_t { fetch, home, seek, feed, move, settle, dwell, next };
    // The job-stream check's state across frames (link.c's vstate).
    struct V3Check {
        std::uint8_t st = 0, n = 0, flags = 0, skip = 0;
    };
    V3Check v3c_;
    std::size_t ops_done_ = 0;  // ring_[0, ops_done_) is whole and may be executed
    // configuration (CONFIGURE v3)
    std::uint16_t cfg_travel_ = 0, cfg_home_iv_ = 0, cfg_hammer_ = 0, cfg_settle_ = 0;
    // executor (registers: reset on any boot)
    X xs_ = X::fetch;
    bool phase_busy_ = false;  // !mv_done
    double phase_end_ = 0;     // the phase's last event
    double last_event_ = 0;    // the last timer event made
    std::uint8_t p_flags_ = 0, p_left_ = 0;
    std::uint32_t p_first_ = 0;
    bool c_neg_ = false, f_neg_ = false, ham_ccv_ = false, p_is_first_ = false;
    bool fired_ = false;  // the strike under way was fired (not a skipped one)
    bool p_drop_ = false; // a new session dropped the rest of the pass (exec_drop_pass)
    [[nodiscard]] bool v3_dropped();
    std::size_t data_check_errors_ = 0;
};

}  // namespace tactus::controller
