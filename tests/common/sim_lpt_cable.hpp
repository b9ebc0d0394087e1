// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The C++ simulated controller behind a parallel port, in-process and on
// virtual time: the host's LptPort drives an LptPeripheral (the firmware's
// port poll) whose latched bytes go to a SimController and whose replies come
// back in nibble mode, as the reference firmware's main loop does
// (firmware/src/lpt.c, main.c). Each settle of the lines is a microsecond and
// one pass of that loop; the host's waits run the controller on. The status
// lines show the condition as the firmware does: PError for paper out, nFault
// low while a fault stands, Select while the chip runs.
//
// Faults the tests place: the chip halted (nothing on its side moves, its
// port included) and the cable pulled for a window of time (the host's port
// stays; its status lines float high, read as Busy, and no strobe reaches the
// chip).
#include <algorithm>
#include <memory>
#include <utility>

#include "controller/lpt_peripheral.hpp"
#include "controller/sim_controller.hpp"
#include "transport/lpt_port.hpp"

namespace tactus::test {

class SimLptBench {
public:
    explicit SimLptBench(std::shared_ptr<controller::SimController> c) : ctl_(std::move(c)) { loop(); }

    // A port on this bench (each reopen of the host's port gets a new one).
    Result<std::unique_ptr<transport::LptPort>> open_port(std::string name = "lpt:sim") {
        return transport::LptPort::open(
            [this]() -> Result<std::unique_ptr<transport::ParallelPortLines>> {
                return std::unique_ptr<transport::ParallelPortLines>(std::make_unique<Lines>(*this));
            },
            std::move(name));
    }

    [[nodiscard]] controller::SimController& controller() { return *ctl_; }
    [[nodiscard]] const transport::LptStatus& pins() const { return pins_; }
    [[nodiscard]] double now() const { return now_; }
    // The chip stops (as s51 under SIGSTOP): its port no longer answers.
    void halt() { halted_ = true; }
    // The cable is out for [from, to) (seconds of the bench's clock).
    void pull_cable_between(double from, double to) { pulled_ = {from, to}; }
    [[nodiscard]] bool cable_out() const { return now_ >= pulled_.first && now_ < pulled_.second; }
    // Host-side lines seen while the cable was out (the host kept trying).
    [[nodiscard]] std::size_t reads_while_pulled() const { return reads_while_pulled_; }
    // What a host reading the status lines in compatibility mode (between
    // transfers) saw, counted in passes of the firmware's loop: the condition
    // shown while it stood, and shown while it did not (a wrong line).
    struct ConditionSeen {
        std::size_t fault_on_nfault = 0, nfault_without_fault = 0;
        std::size_t paper_out_on_perror = 0, perror_with_paper = 0;
    };
    [[nodiscard]] const ConditionSeen& condition_seen() const { return seen_; }

private:
    class Lines final : public transport::ParallelPortLines {
    public:
        explicit Lines(SimLptBench& b) : b_(b) {}
        Result<void> write_data(std::uint8_t v) override {
            if (!b_.cable_out()) b_.port_.set_data(v);
            return {};
        }
        Result<void> write_control(const transport::LptControl& c) override {
            if (!b_.cable_out()) {
                b_.port_.set_control(c);
                b_.host_ctl_ = c;
            }
            return {};
        }
        Result<transport::LptStatus> read_status() override {
            if (b_.cable_out()) {
                ++b_.reads_while_pulled_;
                return transport::LptStatus{true, true, true, true, true};  // pull-ups: all high
            }
            return b_.pins_;
        }
        void settle() override { b_.run_to(b_.now_ + 1e-6); }
        [[nodiscard]] std::optional<double> clock() const override { return b_.now_; }
        bool run_for(std::chrono::microseconds d) override {
            b_.run_to(b_.now_ + std::chrono::duration<double>(d).count());
            return true;
        }

    private:
        SimLptBench& b_;
    };

    // Runs the controller to `t`, stopping at each of its own events so its
    // replies reach the port when they are made.
    void run_to(double t) {
        while (true) {
            const auto next = ctl_->next_event();
            const double step = next && *next > now_ && *next < t ? *next : t;
            now_ = std::max(now_, step);
            loop();
            if (now_ >= t) return;
        }
    }
    // One pass of the firmware's main loop: the port poll, the protocol, the
    // executor, the condition on the status lines.
    void loop() {
        if (halted_) return;
        port_.tick();
        const auto in = port_.take_received();
        if (!in.empty()) ctl_->receive(in, now_);
        ctl_->advance(now_);
        const auto out = ctl_->take_output();
        if (!out.empty()) port_.send(out);
        const auto st = ctl_->status();
        port_.set_condition((st.ack.faults & encode::fault::paper_out) != 0,
                            st.ack.state == encode::ControllerState::fault, true);
        pins_ = port_.status();
        if (!host_ctl_.n_select_in) {  // compatibility mode: the lines carry the condition
            const bool fault = st.ack.state == encode::ControllerState::fault;
            const bool paper_out = (st.ack.faults & encode::fault::paper_out) != 0;
            if (fault && !pins_.n_fault) ++seen_.fault_on_nfault;
            if (!fault && !pins_.n_fault) ++seen_.nfault_without_fault;
            if (paper_out && pins_.paper_error) ++seen_.paper_out_on_perror;
            if (!paper_out && pins_.paper_error) ++seen_.perror_with_paper;
        }
    }

    std::shared_ptr<controller::SimController> ctl_;
    controller::LptPeripheral port_;
    transport::LptStatus pins_;
    transport::LptControl host_ctl_;
    ConditionSeen seen_;
    double now_ = 0;
    bool halted_ = false;
    std::pair<double, double> pulled_{-1, -1};
    std::size_t reads_while_pulled_ = 0;
};

}  // namespace tactus::test
