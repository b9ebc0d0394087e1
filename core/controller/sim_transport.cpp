// SPDX-License-Identifier: GPL-3.0-or-later
#include "controller/sim_transport.hpp"

#include <algorithm>
#include <limits>
#include <thread>

namespace tactus::controller {

SimTransport::SimTransport(std::shared_ptr<controller::SimController> controller,
                           SimLineOptions options)
    : controller_(controller), sim_(controller.get()), options_(options), rng_(options.noise.seed) {}

SimTransport::SimTransport(std::shared_ptr<LineEnd> end, SimLineOptions options)
    : controller_(std::move(end)), options_(options), rng_(options.noise.seed) {}

double SimTransport::bytes_per_second() const { return options_.baud / options_.bits_per_byte; }

// Puts bytes on one direction of the line: each takes one character time after
// the previous one, and the noise model may lose, flip or repeat it.
void SimTransport::send_line(std::deque<Timed>& line, double& line_free, double from,
                             std::span<const std::uint8_t> bytes) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double char_time = 1.0 / bytes_per_second();
    const auto& n = options_.noise;
    for (std::uint8_t b : bytes) {
        line_free = std::max(line_free, from) + char_time;
        if (in(silent_, line_free) || in(unplugged_, line_free)) continue;
        if (n.drop > 0 && u(rng_) < n.drop) {
            ++corrupted_;
            continue;
        }
        if (n.flip > 0 && u(rng_) < n.flip) {
            b = static_cast<std::uint8_t>(b ^ (1U << (rng_() % 8)));
            ++corrupted_;
        }
        line.push_back({line_free, b});
        if (n.dup > 0 && u(rng_) < n.dup) {
            line_free += char_time;
            line.push_back({line_free, b});
            ++corrupted_;
        }
    }
}

void SimTransport::collect_output(double at) {
    const auto out = controller_->take_output();
    if (!out.empty()) send_line(to_host_, rx_free_, at, out);
}

// Runs the far end up to time t: bytes reach the controller at their arrival
// times, the controller executes, its replies go onto the return line.
void SimTransport::run_until(double t) {
    for (int guard = 0; guard < 10'000'000; ++guard) {
        const double inf = std::numeric_limits<double>::infinity();
        const double t_in = to_controller_.empty() ? inf : to_controller_.front().at;
        const double t_ctrl = controller_->next_event().value_or(inf);
        const double t_reset = reset_ ? reset_->first : inf;
        const double next = std::min({t_in, t_ctrl, t_reset});
        if (next > t) break;
        if (next == t_reset) {
            controller_->advance(t_reset);
            collect_output(t_reset);
            if (reset_->second)
                controller_->warm_reset(t_reset);
            else
                controller_->power_loss(t_reset);
            reset_.reset();
        } else if (next == t_in) {
            // Every byte already on the wire by then arrives in order.
            std::vector<std::uint8_t> batch;
            const double at = t_in;
            while (!to_controller_.empty() && to_controller_.front().at <= at) {
                batch.push_back(to_controller_.front().byte);
                to_controller_.pop_front();
            }
            controller_->receive(batch, at);
            collect_output(at);
            continue;
        } else {
            controller_->advance(t_ctrl);
        }
        collect_output(next);
    }
    controller_->advance(t);
    collect_output(t);
}

Result<void> SimTransport::write(std::span<const std::uint8_t> bytes) {
    if (in(unplugged_, now_)) return fail(ErrorKind::device, "device disconnected (simulated unplug)", "sim");
    tx_count_ += bytes.size();
    send_line(to_controller_, tx_free_, now_, bytes);
    return {};
}

Result<std::size_t> SimTransport::read(std::span<std::uint8_t> buffer,
                                       std::chrono::microseconds timeout) {
    const double deadline = now_ + std::chrono::duration<double>(timeout).count();
    for (;;) {
        if (in(unplugged_, now_)) {
            to_host_.clear();
            return fail(ErrorKind::device, "device disconnected (simulated unplug)", "sim");
        }
        std::size_t n = 0;
        while (n < buffer.size() && !to_host_.empty() && to_host_.front().at <= now_) {
            buffer[n++] = to_host_.front().byte;
            to_host_.pop_front();
        }
        if (n > 0) {
            pace();
            return n;
        }
        const double inf = std::numeric_limits<double>::infinity();
        double next = to_host_.empty() ? inf : to_host_.front().at;
        if (!to_controller_.empty()) next = std::min(next, to_controller_.front().at);
        next = std::min(next, controller_->next_event().value_or(inf));
        if (reset_) next = std::min(next, reset_->first);
        if (unplugged_.first > now_) next = std::min(next, unplugged_.first);
        if (next > deadline) {
            run_until(deadline);
            now_ = deadline;
            if (!to_host_.empty() && to_host_.front().at <= now_) continue;
            pace();
            return std::size_t{0};
        }
        next = std::max(next, now_);
        run_until(next);
        // Guard against an event that does not move time forward.
        now_ = next > now_ ? next : std::nextafter(now_, inf);
    }
}

Result<void> SimTransport::reopen() {
    if (in(unplugged_, now_)) return fail(ErrorKind::device, "no such device (simulated unplug)", "sim");
    to_host_.clear();
    return {};
}

void SimTransport::sleep(std::chrono::microseconds duration) {
    now_ += std::chrono::duration<double>(duration).count();
    run_until(now_);
    pace();
}

void SimTransport::set_speed(double speed) {
    options_.speed = speed;
    anchor_wall_ = std::chrono::steady_clock::now();
    anchor_sim_ = now_;
}

std::optional<std::chrono::steady_clock::time_point> SimTransport::due() {
    if (options_.speed <= 0) return std::nullopt;
    using namespace std::chrono;
    const auto at = anchor_wall_ + duration_cast<steady_clock::duration>(
                                       duration<double>((now_ - anchor_sim_) / options_.speed));
    const auto wall = steady_clock::now();
    if (wall - at > milliseconds(100)) {
        // Behind: from here on, simulated time runs at the speed again.
        anchor_wall_ = wall;
        anchor_sim_ = now_;
        return wall;
    }
    return at;
}

void SimTransport::pace() {
    if (!self_paced_) return;
    if (const auto at = due()) std::this_thread::sleep_until(*at);
}

SimLineOptions line_options(const transport::SimSettings& settings) {
    SimLineOptions line;
    line.baud = settings.baud;
    line.noise.drop = line.noise.flip = line.noise.dup = settings.noise;
    line.noise.seed = settings.seed;
    line.speed = settings.speed;
    return line;
}

}  // namespace tactus::controller
