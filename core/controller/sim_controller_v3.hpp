// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The simulated controller speaking protocol 3 exactly as the reference
// firmware built with SimOptions::firmware's ramp tables does
// (docs/protocol.md; firmware/src/link.c and exec.c are the rules it
// follows): HELLO_REPLY with the tables' id, the firmware's ring and window
// (machine/reference_firmware.hpp), the DATA check, pass records timed from
// the tables. Its link is in sim_controller_v3.cpp, its executor in
// sim_controller_v3_exec.cpp, both after the shared session checks
// (sim_session.hpp), in the same RAM / register split.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "controller/sim_session.hpp"
#include "machine/reference_firmware.hpp"

namespace tactus::controller {

// The reference firmware's sizes, what a v3 controller reports in HELLO_REPLY.
namespace v3 = machine::reference_firmware;

class SimControllerV3 final : public SimSession {
public:
    // `options.firmware` must hold the tables.
    explicit SimControllerV3(SimOptions options);
    // The session layer of a controller that spoke protocol 2 until reflashed.
    explicit SimControllerV3(SimSession&& carried) : SimSession(std::move(carried)) {}

    void advance(double now) override;
    [[nodiscard]] std::optional<double> next_event() const override;
    [[nodiscard]] std::uint8_t protocol() const override { return encode::kProtocolV3; }

private:
    void frame(const encode::Frame& f, double now) override;
    void boot(double now, bool keep_ram) override;
    [[nodiscard]] std::size_t ring_free() const override;

    // --- the link (link.c, sim_controller_v3.cpp)
    void hello(const encode::Frame& f, double now);
    void data(const encode::Frame& f, double now);
    void control(const encode::Frame& f, double now);
    [[nodiscard]] bool check_ops(std::span<const std::uint8_t> ops);
    void flush();

    // --- the executor (exec.c, sim_controller_v3_exec.cpp)
    [[nodiscard]] bool poll(double now);
    [[nodiscard]] bool fetch(double now);
    void pass_begin(double now);
    void strike_move(double now);
    void pass_end();
    void stop_on_fault(std::uint8_t bits, double now);
    void abort_motion();
    // A timed phase (a move, a settle, a pulse): its first event comes
    // `first_ticks` after the last event before it (or after `now` when the
    // executor comes to it late: it waited for data or a RESUME), its last
    // `total_ticks` after that same point.
    void phase(double now, std::uint64_t first_ticks, std::uint64_t total_ticks);
    void carriage(std::uint32_t steps, bool neg, double now);
    [[nodiscard]] std::uint8_t at(std::size_t i) const { return ring_[i]; }
    [[nodiscard]] std::uint32_t uvar(std::size_t& i) const;
    [[nodiscard]] std::int32_t svar(std::size_t& i) const;
    // Leaves a dropped pass at a safe point; whether it did.
    [[nodiscard]] bool dropped();
    // The executor may run in the middle of something (a phase, a pass).
    [[nodiscard]] bool busy() const { return xs_ != X::fetch || phase_busy_; }

    enum class X : std::uint8_t { fetch, home, seek, feed, move, settle, dwell, next };
    // The job-stream check's state across frames (link.c's vstate).
    struct Check {
        std::uint8_t st = 0, n = 0, flags = 0, skip = 0;
    };
    Check check_;
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
    bool fired_ = false;   // the strike under way was fired (not a skipped one)
    bool p_drop_ = false;  // a new session dropped the rest of the pass (exec_drop_pass)
};

}  // namespace tactus::controller
