// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The simulated controller speaking protocol 2, the legacy one
// (docs/protocol.md, step segments in the job stream): its frames after the
// shared session checks (sim_session.hpp), its reset (sim_controller_v2.cpp),
// and the executor that runs the ring's ops in simulated time
// (sim_controller_v2_exec.cpp). The ring holds at most ram::kRingBytes.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "controller/sim_session.hpp"
#include "encode/stream.hpp"

namespace tactus::controller {

class SimControllerV2 final : public SimSession {
public:
    explicit SimControllerV2(SimOptions options);
    // The session layer of a controller that spoke protocol 3 until reflashed.
    explicit SimControllerV2(SimSession&& carried) : SimSession(std::move(carried)) {}

    void advance(double now) override;
    [[nodiscard]] std::optional<double> next_event() const override;
    [[nodiscard]] std::uint8_t protocol() const override { return encode::kProtocolVersion; }

private:
    void frame(const encode::Frame& f, double now) override;
    void boot(double now, bool keep_ram) override;
    [[nodiscard]] std::size_t ring_free() const override;

    void hello(const encode::Frame& f, double now);
    void data(const encode::Frame& f, double now);
    void immediate(const encode::Frame& f, double now);
    bool start_next_op(double now);
    void finish_op();
    void interrupt_op(double now);
    void stop_job(std::uint8_t fault_bits, double now);
    [[nodiscard]] std::optional<double> keepalive_deadline() const;
    // Whether the move whose first op (of this size) heads the ring is whole in it.
    [[nodiscard]] bool move_buffered(std::size_t first_op_size) const;

    bool in_move_ = false;  // the last op was a move whose continuation may follow (a register)

    // --- executor: the op under way
    std::optional<encode::Op> current_;
    double op_start_ = 0;
    double op_end_ = 0;
    std::int32_t seek_from_ = 0;
};

}  // namespace tactus::controller
