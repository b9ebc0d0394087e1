// SPDX-License-Identifier: GPL-3.0-or-later
#include "controller/builtin_sim.hpp"

#include <thread>

#include "controller/open_device.hpp"
#include "common/try.hpp"
#include <type_traits>

namespace tactus::controller {

// A connection: forwards to the one line under the simulator's mutex. Closing
// it (the link dropped) leaves the controller and the line as they are.
class BuiltInSimulator::Stream final : public transport::ByteStream {
public:
    explicit Stream(BuiltInSimulator& sim) : sim_(sim) {}
    Result<void> write(std::span<const std::uint8_t> bytes) override {
        return paced([&] { return sim_.line_.write(bytes); });
    }
    Result<std::size_t> read(std::span<std::uint8_t> buffer, std::chrono::microseconds timeout) override {
        return paced([&] { return sim_.line_.read(buffer, timeout); });
    }
    Result<void> reopen() override {
        std::lock_guard lock(sim_.mutex_);
        sim_.apply_pending();
        return sim_.line_.reopen();
    }
    [[nodiscard]] double now() const override {
        std::lock_guard lock(sim_.mutex_);
        return sim_.line_.now();
    }
    void sleep(std::chrono::microseconds duration) override {
        paced([&] {
            sim_.line_.sleep(duration);
            return 0;
        });
    }
    [[nodiscard]] double bytes_per_second() const override { return sim_.line_.bytes_per_second(); }
    [[nodiscard]] std::string describe() const override { return "sim"; }

private:
    // Runs `op` on the line under the lock, then waits for the wall clock
    // without it (SimTransport::due).
    template <class Op>
    std::invoke_result_t<Op> paced(Op op) {
        std::optional<std::chrono::steady_clock::time_point> due;
        auto result = [&] {
            std::lock_guard lock(sim_.mutex_);
            sim_.apply_pending();
            auto r = op();
            due = sim_.line_.due();
            return r;
        }();
        if (due) std::this_thread::sleep_until(*due);
        return result;
    }

    BuiltInSimulator& sim_;
};

SimOptions BuiltInSimulator::default_options() {
    SimOptions o;
    o.reload_paper_after_s = 5;
    return o;
}

BuiltInSimulator::BuiltInSimulator(SimOptions options, SimLineOptions line)
    : controller_(std::make_shared<SimController>(options)), line_(controller_, line), base_noise_(line.noise),
      paper_reload_s_(options.reload_paper_after_s) {
    line_.set_self_paced(false);  // Stream waits for the wall clock, outside the mutex
}

std::unique_ptr<transport::ByteStream> BuiltInSimulator::connect(const transport::SimSettings& settings) {
    std::lock_guard lock(mutex_);
    (void)line_.reopen();  // replies meant for the previous connection are gone with it
    const auto line = line_options(settings);
    line_.set_baud(line.baud);
    base_noise_ = line.noise;
    if (noise_until_ < 0) line_.set_noise(base_noise_);
    line_.set_speed(line.speed);
    controller_->set_paper_reload(settings.paper_reload_s.value_or(paper_reload_s_));
    return std::make_unique<Stream>(*this);
}

Result<std::unique_ptr<transport::ByteStream>> BuiltInSimulator::connect(
    const transport::SimSettings& settings, const std::optional<machine::FirmwareTables>& tables) {
    TACTUS_TRY(firmware, sim_firmware_for(settings, tables));
    {
        std::lock_guard lock(mutex_);
        if (controller_->firmware() != firmware) controller_->reflash(std::move(firmware), line_.now());
    }
    return connect(settings);
}

std::uint8_t BuiltInSimulator::protocol() const {
    std::lock_guard lock(mutex_);
    return controller_->protocol();
}

std::optional<machine::FirmwareTables> BuiltInSimulator::firmware() const {
    std::lock_guard lock(mutex_);
    return controller_->firmware();
}

void BuiltInSimulator::paper_out() {
    std::lock_guard lock(mutex_);
    pending_.paper_out = true;
}
void BuiltInSimulator::pull_cable(double seconds) {
    std::lock_guard lock(mutex_);
    pending_.unplug_s = seconds;
}
void BuiltInSimulator::noise(double seconds, double per_byte) {
    std::lock_guard lock(mutex_);
    pending_.noise = std::pair{seconds, per_byte};
}
void BuiltInSimulator::reset_controller() {
    std::lock_guard lock(mutex_);
    pending_.reset = true;
}

void BuiltInSimulator::apply_pending() {
    const double now = line_.now();
    if (noise_until_ >= 0 && now >= noise_until_) {
        line_.set_noise(base_noise_);
        noise_until_ = -1;
    }
    if (pending_.paper_out) controller_->remove_paper();
    if (pending_.unplug_s) line_.unplug_between(now, now + *pending_.unplug_s);
    if (pending_.noise) {
        const auto [seconds, rate] = *pending_.noise;
        line_.set_noise({.drop = rate, .flip = rate, .dup = rate});
        noise_until_ = now + seconds;
    }
    if (pending_.reset) line_.reset_controller_at(now, true);
    pending_ = {};
}

std::vector<LoggedStrike> BuiltInSimulator::strikes() const {
    std::lock_guard lock(mutex_);
    return controller_->strike_log();
}

machine::ControllerConfig BuiltInSimulator::config() const {
    std::lock_guard lock(mutex_);
    return controller_->config();
}

double BuiltInSimulator::now() const {
    std::lock_guard lock(mutex_);
    return line_.now();
}

encode::Status BuiltInSimulator::status() const {
    std::lock_guard lock(mutex_);
    return controller_->status();
}

}  // namespace tactus::controller
