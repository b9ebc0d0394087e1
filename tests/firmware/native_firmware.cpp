// SPDX-License-Identifier: GPL-3.0-or-later
// The reference firmware's C on virtual time (native_firmware.hpp): the
// platform under it (pins, motion, the UART's transmitter) and main.c's loop.
#include "native_firmware.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

#include "machine/limits.hpp"

extern "C" {
#include "8052.h"  // firmware/native: the pins as variables, __bit as a byte
#include "board.h"
#include "decoder.h"
#include "exec.h"
#include "link.h"
#include "motion.h"
#include "ramp.h"

void exec_init(void);
void exec_poll(void);

volatile uint8_t P1_0, P1_1, P1_2, P1_3, P1_4, P1_5, P1_6, P1_7;
volatile union native_port native_p2;
volatile uint8_t P0;
volatile uint8_t P3_2, P3_3, P3_4, P3_5, P3_6, P3_7;
volatile uint8_t mv_done, mv_limit;
}

namespace {

tactus::test::NativeFirmware* g_fw = nullptr;  // the firmware's state is global: one at a time
constexpr std::uint64_t kMinTimerGap = 64;     // motion.c start(): timer_go never closer

std::uint64_t gap() { return g_fw->tables().start_gap_ticks; }

}  // namespace

// --- the platform the link and the executor call (link.h, motion.h)
extern "C" {
void fw_tx_kick(void) { g_fw->tx_kick(); }
uint8_t fw_paper_present(void) { return PAPER; }
uint8_t fw_stack_used(void) { return 0; }

void motion_init(void) { mv_done = 1; }
void motion_stop(void) { g_fw->stop(); }

// A table move: its first step start_gap + T[0] after the last timer event,
// its last step the table's move time after the start.
void move_table(uint8_t feed, uint16_t n) {
    const auto& t = feed ? g_fw->tables().feed : g_fw->tables().carriage;
    g_fw->phase(gap() + t.interval(1, n), gap() + t.move_ticks(n));
}
// n steps at CONFIGURE's homing interval (a seek).
void move_constant(uint8_t pin, uint16_t n) {
    (void)pin;
    g_fw->phase(gap() + cfg_home_iv, gap() + static_cast<std::uint64_t>(n) * cfg_home_iv);
}
// Toward home at the homing interval: the switch closes at step 0, after the
// steps the carriage counts (the emulator build's rule; it loses none).
void move_home(uint16_t n) {
    (void)n;
    if (fw_carriage > 0)
        g_fw->phase(gap() + cfg_home_iv, gap() + static_cast<std::uint64_t>(fw_carriage) * cfg_home_iv);
    mv_limit = 1;
}
void hammer_down_after_settle(uint8_t pins) {
    g_fw->phase(cfg_settle, cfg_settle);
    g_fw->hammer_down(pins);
}
void hammer_up_after_pulse(void) {
    HAM_CVX = 0;
    HAM_CCV = 0;
    g_fw->phase(cfg_hammer, cfg_hammer);
}
}

namespace tactus::test {

NativeFirmware::NativeFirmware(NativeFirmwareOptions options) : options_(std::move(options)) {
    if (g_fw != nullptr) std::abort();  // one firmware per process at a time
    g_fw = this;
    boot(false);
}

NativeFirmware::~NativeFirmware() { g_fw = nullptr; }

// main.c main(): a cold start sets every variable (cold_state), a warm one
// keeps the progress and reports the reset.
void NativeFirmware::boot(bool warm) {
    phase_busy_ = false;
    tx_busy_ = false;  // the UART's SFRs are reset: a reply on the line is cut
    last_event_ = now_ - 1;
    for (volatile std::uint8_t* p : {&P1_0, &P1_1, &P1_2, &P1_3, &P1_4, &P1_5, &P1_6}) *p = 0;
    P1_7 = 1;
    P3_3 = 1;  // the limit switch open
    P3_6 = options_.paper_present ? 1 : 0;
    P3_7 = 1;  // both hammers home
    fw_pause_req = 0;
    if (warm) {
        fw_faults |= F_WARM_RESET;
        fw_flags &= static_cast<std::uint8_t>(~FL_HOMED);
        fw_state = (fw_flags & FL_JOB_ACTIVE) ? ST_FAULT : ST_IDLE;
    } else {
        fw_state = ST_IDLE;
        fw_faults = F_POWER_ON;
        fw_flags = 0;
        fw_job_id = 0;
        fw_executed = 0;
        fw_pass_index = 0;
        fw_sheet = 0;
        fw_strikes_in_pass = 0;
        fw_skip = 0;
        fw_carriage = 0;
        fw_feed = 0;
        cfg_travel = cfg_home_iv = cfg_hammer = cfg_settle = 0;
    }
    fw_link_init(warm ? 1 : 0);
    exec_init();
    motion_init();
}

void NativeFirmware::warm_reset(double now) {
    now_ = std::max(now_, now);
    boot(true);
}

void NativeFirmware::power_loss(double now) {
    now_ = std::max(now_, now);
    boot(false);
}

// One phase on the timer, scheduled from its last event (SimControllerV3::phase).
void NativeFirmware::phase(std::uint64_t first_ticks, std::uint64_t total_ticks) {
    if (first_ticks < kMinTimerGap) {
        total_ticks += kMinTimerGap - first_ticks;
        first_ticks = kMinTimerGap;
    }
    const double on_time = last_event_ + static_cast<double>(first_ticks) / machine::kTickHz;
    const double base = now_ <= on_time ? last_event_ : now_;
    phase_end_ = options_.instant_motion ? now_ : base + static_cast<double>(total_ticks) / machine::kTickHz;
    phase_busy_ = true;
    mv_done = 0;
    mv_limit = 0;
}

void NativeFirmware::hammer_down(std::uint8_t pins) {
    if (pins == 0) return;  // a strike made before a reset: passed over
    controller::LoggedStrike l;
    const bool ccv = (pins & PIN_CCV) != 0;
    l.sheet = fw_sheet;
    l.hammer = ccv ? plan::Hammer::concave : plan::Hammer::convex;
    l.side = ccv ? plan::Side::back : plan::Side::front;
    l.carriage_step = fw_carriage;
    l.feed_step = fw_feed;
    l.pass_index = fw_pass_index;
    l.job_id = fw_job_id;
    l.time_s = phase_end_;  // the hammer comes down at the settle's end
    log_.push_back(l);
}

void NativeFirmware::stop() {
    if (phase_busy_) last_event_ = now_ - 1;
    phase_busy_ = false;
    mv_done = 1;
}

void NativeFirmware::tx_kick() {
    if (tx_busy_) return;
    tx_busy_ = true;
    tx_next_ = now_;
}

// main.c's loop after a byte or an event. Each pass makes one step of the
// executor's work; at most 64 (more than the ops a 47-byte ring holds) or
// until a phase is under way.
void NativeFirmware::main_loop() {
    for (int pass = 0; pass < 64; ++pass) {
        if (fw_ops_head > 0) fw_compact();
        exec_poll();
        fw_poll_paper();
        fw_report_room();
        if (!mv_done) break;
    }
    const bool waiting = fw_state == ST_WAITING;
    if (waiting && waiting_since_ < 0) waiting_since_ = now_;
    if (!waiting && waiting_since_ >= 0) {
        waits_.push_back({waiting_since_, now_ - waiting_since_, fw_executed});
        waiting_since_ = -1;
    }
}

void NativeFirmware::receive(std::span<const std::uint8_t> bytes, double now) {
    advance(now);
    for (const std::uint8_t b : bytes) {
        fw_rx_byte(b);
        main_loop();
    }
}

void NativeFirmware::advance(double now) {
    const double inf = std::numeric_limits<double>::infinity();
    for (;;) {
        const double t_phase = phase_busy_ ? phase_end_ : inf;
        const double t_tx = tx_busy_ ? tx_next_ : inf;
        const double next = std::min(t_phase, t_tx);
        if (next > now) break;
        now_ = std::max(now_, next);
        if (t_tx <= t_phase) {
            // The serial interrupt: the next reply byte, built as it goes out.
            const std::int16_t b = fw_reply_byte();
            if (b < 0) {
                tx_busy_ = false;
            } else {
                out_.push_back(static_cast<std::uint8_t>(b));
                tx_next_ = now_ + 10.0 / options_.baud;
            }
        } else {
            phase_busy_ = false;
            last_event_ = phase_end_;
            mv_done = 1;
        }
        main_loop();
    }
    now_ = std::max(now_, now);
}

std::optional<double> NativeFirmware::next_event() const {
    std::optional<double> t;
    if (phase_busy_) t = phase_end_;
    if (tx_busy_) t = t ? std::min(*t, tx_next_) : tx_next_;
    return t;
}

std::vector<std::uint8_t> NativeFirmware::take_output() { return std::exchange(out_, {}); }

}  // namespace tactus::test
