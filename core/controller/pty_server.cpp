// SPDX-License-Identifier: GPL-3.0-or-later
#include "controller/pty_server.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <random>

namespace tactus::controller {
namespace {

double wall_now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

Result<PtyServer> PtyServer::open(const PtyServerOptions& options) {
    if (options.baud < 300) return fail(ErrorKind::usage, "baud rate below 300", "--baud");
    if (options.time_scale <= 0) return fail(ErrorKind::usage, "time scale must be positive", "--time-scale");
    PtyServer s(options);
    s.ctl_ = SimController([&] {
        SimOptions o = options.sim;
        o.keepalive_scale = options.time_scale;  // keep-alive stays in wall time
        return o;
    }());
    auto endpoint = platform::SimEndpoint::open(true);
    if (!endpoint) return fail(ErrorKind::device, endpoint.error().what, "pty");
    s.endpoint_ = std::move(*endpoint);
    return s;
}

PtyServer::PtyServer(PtyServer&& o) noexcept
    : options_(o.options_), ctl_(std::move(o.ctl_)), endpoint_(std::move(o.endpoint_)) {}

PtyServer::~PtyServer() = default;

Result<void> PtyServer::serve(const std::atomic<bool>& stop,
                              const std::function<void(const LoggedStrike&)>& on_strike,
                              const std::function<void(const SimController&)>& on_tick) {
    struct Timed {
        double at;  // wall time the byte has fully crossed the line
        std::uint8_t byte;
    };
    std::deque<Timed> inbound, outbound;
    const double char_time = 10.0 / options_.baud;
    double in_free = 0, out_free = 0;
    const double t0 = wall_now();
    auto sim_time = [&](double wall) { return (wall - t0) * options_.time_scale; };
    auto wall_of = [&](double sim) { return t0 + sim / options_.time_scale; };
    std::mt19937_64 rng(options_.seed);
    std::uniform_real_distribution<double> u(0, 1);
    // The pulled cable is timed from the host's first byte, not from our start:
    // a host that starts slowly (a loaded machine, a sanitizer build) must still
    // meet the cut in the middle of its job, not before its HELLO.
    double first_byte = -1;
    auto line_dead = [&](double wall) {
        if (first_byte < 0) return false;
        const double t = wall - first_byte;
        return options_.disconnect_at_s >= 0 && t >= options_.disconnect_at_s &&
               t < options_.disconnect_at_s + options_.disconnect_for_s;
    };
    // Puts bytes on one direction of the line with the noise model.
    auto put = [&](std::deque<Timed>& q, double& line_free, double now, std::uint8_t b) {
        line_free = std::max(line_free, now) + char_time;
        if (line_dead(line_free)) return;
        if (options_.noise > 0) {
            if (u(rng) < options_.noise) return;
            if (u(rng) < options_.noise) b = static_cast<std::uint8_t>(b ^ (1U << (rng() % 8)));
            if (u(rng) < options_.noise) {
                q.push_back({line_free, b});
                line_free += char_time;
            }
        }
        q.push_back({line_free, b});
    };
    std::size_t logged = 0;
    std::vector<std::uint8_t> buf(4096);
    platform::Channel& line = endpoint_.line();
    platform::Channel* const lines[] = {&line};
    while (!stop.load()) {
        const double now = wall_now();
        // Host -> controller: bytes that have crossed the line by now.
        while (!inbound.empty() && inbound.front().at <= now) {
            const Timed t = inbound.front();
            inbound.pop_front();
            ctl_.receive(std::span(&t.byte, 1), sim_time(t.at));
        }
        ctl_.advance(sim_time(now));
        for (const std::uint8_t b : ctl_.take_output()) put(outbound, out_free, now, b);
        // Controller -> host: write what has crossed the line.
        std::vector<std::uint8_t> due;
        while (!outbound.empty() && outbound.front().at <= now) {
            due.push_back(outbound.front().byte);
            outbound.pop_front();
        }
        if (!due.empty()) {
            std::size_t done = 0;
            while (done < due.size()) {
                const auto n = line.write_some(std::span(due).subspan(done));
                if (!n) return fail(ErrorKind::device, n.error().what, path());
                if (*n == 0) break;  // no reader: the bytes are lost, as on a wire
                done += *n;
            }
        }
        const auto& log = ctl_.strike_log();
        for (; logged < log.size(); ++logged)
            if (on_strike) on_strike(log[logged]);
        if (on_tick) on_tick(ctl_);

        double next = now + 0.05;
        if (!inbound.empty()) next = std::min(next, inbound.front().at);
        // Reply bytes go out when the whole burst has crossed the line: the host
        // acts on whole frames only, and one write per burst keeps the loop idle.
        if (!outbound.empty()) next = std::min(next, outbound.back().at);
        if (const auto e = ctl_.next_event()) next = std::min(next, wall_of(*e));
        // Microsecond wake-ups: at 115200 baud a byte takes 87 us.
        const double wait = std::max(0.0, next - wall_now());
        const auto ready = platform::wait_readable(
            lines, std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(wait)));
        if (!ready) return fail(ErrorKind::device, ready.error().what, path());
        if ((*ready)[0]) {
            const auto n = line.read_some(buf);
            const double at = wall_now();
            const std::size_t got = n ? *n : 0;
            if (got > 0 && first_byte < 0) first_byte = at;
            for (std::size_t i = 0; i < got; ++i) put(inbound, in_free, at, buf[i]);
        }
    }
    return {};
}

}  // namespace tactus::controller
