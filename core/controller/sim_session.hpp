// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The simulated 89C52's session layer, the same whichever protocol it speaks
// (SimControllerV2, SimControllerV3): frames in and replies out, the session
// (nonce, expected sequence number), the checks every frame passes (a wedged
// receive path, no session, a duplicate, a gap), what a new session, RESUME
// and ABORT do to the job, what ACK and STATUS report, resets and power, the
// paper and the fault injection, and the statistics. Each rule here is
// written once; a protocol class adds only what its own link and executor do.
//
// The state keeps the firmware's split: registers lost on any reset, RAM kept
// by a warm reset and lost by power loss, and beside them what the simulator
// itself keeps across both (fault injection, the strike log, statistics).
// Another firmware flashed (SimController::reflash) carries this whole layer
// to the other protocol's class, as the chip keeps its sockets and paper.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "controller/line_end.hpp"
#include "controller/sim_options.hpp"
#include "encode/frame.hpp"
#include "encode/messages.hpp"
#include "machine/controller_config.hpp"
#include "machine/firmware_tables.hpp"

namespace tactus::controller {

class SimSession : public LineEnd {
public:
    ~SimSession() override = default;

    // Bytes from the host, arriving at simulated time `now` (seconds): each
    // whole frame goes to the protocol's frame().
    void receive(std::span<const std::uint8_t> bytes, double now) final;
    // Reply bytes produced so far (and clears them).
    std::vector<std::uint8_t> take_output() final;
    void warm_reset(double now) final;  // watchdog/RST: registers reset, RAM (progress) kept
    void power_loss(double now) final;  // power cycle: RAM lost
    // Another firmware flashed (SimController::reflash, which has run the
    // old one up to `now` and given this protocol's class), then a power
    // cycle: RAM lost.
    void flashed(std::optional<machine::FirmwareTables> firmware, double now);

    // The protocol version it speaks (2, or 3 with SimOptions::firmware).
    [[nodiscard]] virtual std::uint8_t protocol() const = 0;
    [[nodiscard]] const SimOptions& options() const { return options_; }

    // Fault injection (SimController documents each).
    void inject_paper_out_at_sheet(std::uint16_t sheet) { paper_out_sheet_ = sheet; }
    void load_paper();
    void remove_paper() { paper_present_ = false; }
    void set_paper_reload(double seconds) { options_.reload_paper_after_s = seconds; }
    void inject_limit_switch_at_strike(std::size_t nth) { limit_at_ = nth; }
    void inject_hammer_fault_at_strike(std::size_t nth) { hammer_at_ = nth; }
    void reset_at_strike(std::size_t nth, bool keep_ram) {
        reset_at_ = nth;
        reset_keeps_ram_ = keep_ram;
    }
    void mute_after_pass(std::uint16_t executed) { mute_after_ = executed; }
    void wedge_after_pass(std::uint16_t executed) { wedge_after_ = executed; }

    // What it did (SimController documents each).
    struct Wait {
        double at_s = 0;
        double seconds = 0;
        std::uint16_t executed_passes = 0;
    };
    [[nodiscard]] bool muted() const { return muted_; }
    [[nodiscard]] const std::vector<LoggedStrike>& strike_log() const { return log_; }
    [[nodiscard]] std::size_t data_check_errors() const { return data_check_errors_; }
    [[nodiscard]] encode::Status status() const;
    [[nodiscard]] std::size_t ring_used() const { return ring_.size(); }
    [[nodiscard]] std::size_t max_ring_used() const { return max_ring_used_; }
    [[nodiscard]] std::size_t frames_accepted() const { return frames_accepted_; }
    [[nodiscard]] std::size_t duplicates() const { return duplicates_; }
    [[nodiscard]] std::size_t crc_errors() const { return decoder_.stats().crc_errors; }
    [[nodiscard]] double starved_seconds() const { return starved_s_; }
    [[nodiscard]] const std::vector<Wait>& waits() const { return waits_; }
    [[nodiscard]] std::size_t resets() const { return resets_; }
    [[nodiscard]] const machine::ControllerConfig& config() const { return config_; }
    [[nodiscard]] bool configured() const { return configured_; }

protected:
    explicit SimSession(SimOptions options);
    // The layer carried to another protocol's class (SimController::reflash).
    SimSession(SimSession&&) = default;
    SimSession(const SimSession&) = delete;
    SimSession& operator=(const SimSession&) = delete;
    SimSession& operator=(SimSession&&) = delete;

    // --- what each protocol does
    // One whole frame from the host.
    virtual void frame(const encode::Frame& f, double now) = 0;
    // Power-on or reset. The 8051 clears its SFRs on reset but not its RAM;
    // only a power cycle loses RAM, and the firmware tells the two apart by a
    // signature.
    virtual void boot(double now, bool keep_ram) = 0;
    // The ring's room, as ACK reports it.
    [[nodiscard]] virtual std::size_t ring_free() const = 0;

    // --- replies
    void reply(encode::FrameType type, std::span<const std::uint8_t> payload);
    void ack();
    void nak(encode::NakReason why);
    [[nodiscard]] encode::AckInfo ack_info() const;

    // --- the checks every frame passes (link.c), in this order
    // A wedged receive path answers NAK out of order; false then. Otherwise
    // the host has been heard from now.
    [[nodiscard]] bool receiving(double now);
    // After HELLO: no session, a duplicate, a gap are answered here; true for
    // the frame expected next.
    [[nodiscard]] bool in_sequence(const encode::Frame& f);
    // A frame taken: the sequence moves on.
    void accept();

    // --- what both protocols do to the session and the job
    // A HELLO with this nonce opens a new session (a repeated HELLO of the
    // same session is answered but changes nothing: a stale duplicate must
    // never rewind the sequence).
    [[nodiscard]] bool new_session(std::uint16_t nonce) const { return !session_ || nonce != nonce_; }
    // Opens the session HELLO `seq` with `nonce` asked for: the line back
    // works again, the reset faults are cleared, a job held by them pauses.
    void open_session(std::uint16_t nonce, std::uint8_t seq);
    // The job moves (running, waiting for data, homing): PAUSE and a new
    // session hold it.
    [[nodiscard]] bool job_moving() const;
    // RESUME: every fault the host can clear is cleared (paper out only with
    // paper in), and a job no reset holds runs again.
    void resume_job();
    // ABORT, once the protocol has stopped its executor and dropped the ring:
    // no job, and no fault but a reset's.
    void abort_job(double now);
    // A safe point (at rest) reached with a pause asked for: the job holds
    // still until RESUME, and the host is told.
    void pause_here(double now);
    // SHEET_BEGIN: whether the sheet found paper. Without it the job stops
    // with paper out, the op kept to run again once paper is in, and the
    // simulated operator loads paper after SimOptions::reload_paper_after_s.
    [[nodiscard]] bool paper_for_sheet(std::uint16_t sheet, double now);
    // A pass executed: the host counts it from this ACK. The mute and wedge
    // injections take effect here.
    void pass_executed();
    // A dot struck now with this hammer, at the executor's position.
    void log_strike(plan::Hammer hammer, double time_s);
    // The register part of any reset: no session, not homed, nothing pending.
    void reset_link();
    // A cold start (RAM lost), both protocols: nothing configured, no job, no place.
    void power_on_ram();

    // --- the executor's waiting for data
    void set_waiting(bool waiting, double now);
    // Out of data mid-job: wait at rest, and tell the host of any room it has not heard of.
    void wait_for_data(double now);
    // Room the host has not heard of: an ACK tells it.
    void tell_room();
    // Every further frame's worth of room, and at once when a whole frame first
    // fits: the host holds its next chunk until it knows it fits.
    void report_room(std::size_t max_payload);

    [[nodiscard]] double ticks_to_s(std::uint64_t ticks) const;

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
    bool pause_requested_ = false;

    // --- RAM: kept by a warm reset, lost by power loss
    machine::ControllerConfig config_{};
    bool configured_ = false;
    encode::ControllerState state_ = encode::ControllerState::idle;
    std::uint8_t faults_ = 0;
    std::vector<std::uint8_t> ring_;  // the job-stream ring
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
    std::size_t data_check_errors_ = 0;
};

}  // namespace tactus::controller
