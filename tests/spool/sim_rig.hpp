// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A printer for runner tests: the simulated 89C52 behind the in-process line
// (virtual time), reachable through a ConnectFn like a real device. The cable
// can be cut (every read and write fails and reopening fails) to stand for a
// pulled plug or a device that vanished.
#include <atomic>
#include <functional>
#include <memory>

#include "controller/sim_controller.hpp"
#include "link/link.hpp"
#include "spool/runner.hpp"
#include "controller/sim_transport.hpp"

namespace tactus::spool::test {

// Forwards to one shared SimTransport, so the controller and the virtual clock
// live on across reconnections.
// While `is_cut` says so, reads, writes and reopening fail.
class SharedLine final : public transport::ByteStream {
public:
    SharedLine(std::shared_ptr<controller::SimTransport> line, std::function<bool()> is_cut)
        : line_(std::move(line)), is_cut_(std::move(is_cut)) {}
    SharedLine(std::shared_ptr<controller::SimTransport> line, std::shared_ptr<std::atomic<bool>> cut)
        : SharedLine(std::move(line), [cut = std::move(cut)] { return cut->load(); }) {}
    Result<void> write(std::span<const std::uint8_t> b) override {
        if (is_cut_()) return fail(ErrorKind::device, "device gone (cable cut)", "sim");
        return line_->write(b);
    }
    Result<std::size_t> read(std::span<std::uint8_t> b, std::chrono::microseconds t) override {
        if (is_cut_()) {
            line_->sleep(t);
            return fail(ErrorKind::device, "device gone (cable cut)", "sim");
        }
        return line_->read(b, t);
    }
    Result<void> reopen() override {
        if (is_cut_()) return fail(ErrorKind::device, "no such device", "sim");
        return line_->reopen();
    }
    [[nodiscard]] double now() const override { return line_->now(); }
    void sleep(std::chrono::microseconds d) override { line_->sleep(d); }
    [[nodiscard]] double bytes_per_second() const override { return line_->bytes_per_second(); }
    [[nodiscard]] std::string describe() const override { return "sim"; }

private:
    std::shared_ptr<controller::SimTransport> line_;
    std::function<bool()> is_cut_;
};

struct SimPrinter {
    explicit SimPrinter(controller::SimOptions options = {})
        : controller(std::make_shared<controller::SimController>(options)),
          line(std::make_shared<controller::SimTransport>(controller, controller::SimLineOptions{})),
          cut(std::make_shared<std::atomic<bool>>(false)) {}

    ConnectFn connect(link::LinkOptions options = {}) {
        return [this, options](const PrinterRecord&) -> Result<link::Link> {
            ++connects;
            if (*cut) return fail(ErrorKind::device, "no such device: sim (unplugged)", "sim");
            return link::Link::over(std::make_unique<SharedLine>(line, cut), options);
        };
    }

    std::shared_ptr<controller::SimController> controller;
    std::shared_ptr<controller::SimTransport> line;
    std::shared_ptr<std::atomic<bool>> cut;
    int connects = 0;
};

}  // namespace tactus::spool::test
