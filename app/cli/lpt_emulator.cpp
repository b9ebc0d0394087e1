// SPDX-License-Identifier: GPL-3.0-or-later
#include "lpt_emulator.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "controller/firmware_trace.hpp"
#include "firmware_emulator.hpp"
#include "platform/channel.hpp"
#include "platform/child_process.hpp"
#include "platform/durable_file.hpp"
#include "platform/program_file.hpp"
#include "platform/sim_endpoint.hpp"
#include "platform/termination.hpp"
#include "profile/profile.hpp"
#include "transport/device.hpp"
#include "transport/lpt_port.hpp"

namespace tactus::cli {
namespace {

namespace fs = std::filesystem;
using transport::LptControl;
using transport::LptStatus;

constexpr double kXtalHz = 11.0592e6;  // s51 -X; its "ticks" are oscillator clocks
// Instructions the chip runs: after the host changed its lines and reads the
// status (the strobe interrupt and the main loop's nibble state machine
// answer within a few hundred), and at most per read while the host keeps
// reading without changing anything (it waits: Busy, a reply, motion).
constexpr long kReactSteps = 400;
constexpr long kMostSteps = 150000;
// The lines held before the next change: a strobe pulse as long as the
// firmware takes to answer it (its interrupt is edge-triggered), so the
// status read after the pulse already shows the answer.
constexpr long kSettleSteps = kReactSteps;
constexpr long kBootSteps = 200000;

Result<void> device_error(const std::string& what) { return fail(ErrorKind::device, what, "lpt:emu"); }

constexpr const char* kWakeLibrary = "tactus-s51-wake.so";

// The library preloaded into s51: beside the program (tactus-cli), else where
// the build made it.
std::optional<fs::path> wake_library() {
    if (const auto self = platform::program_file()) {
        const auto beside = self->parent_path() / kWakeLibrary;
        if (fs::is_regular_file(beside)) return beside;
    }
#ifdef TACTUS_S51_WAKE
    if (fs::is_regular_file(TACTUS_S51_WAKE)) return fs::path(TACTUS_S51_WAKE);
#endif
    return std::nullopt;
}

// s51's console on a pseudo-terminal (-c), its prompts NUL bytes (-P): a
// line out, the answer up to the next prompt back.
class Console {
public:
    // `alive`: whether s51 still runs (the pseudo-terminal's other side is
    // held open here, so its end shows as no answer, not as an end of file).
    Console(platform::Channel& c, std::function<bool()> alive) : ch_(c), alive_(std::move(alive)) {}
    Result<std::string> command(const std::string& line) {
        const std::string out = line + "\n";
        std::span<const std::uint8_t> left(reinterpret_cast<const std::uint8_t*>(out.data()), out.size());
        while (!left.empty()) {
            auto n = ch_.write_some(left);
            if (!n || *n == 0) return fail(ErrorKind::device, "s51 closed its console", "lpt:emu");
            left = left.subspan(*n);
        }
        return answer();
    }
    Result<std::string> answer() {
        for (;;) {
            if (const auto z = buf_.find('\0'); z != std::string::npos) {
                std::string out = buf_.substr(0, z);
                buf_.erase(0, z + 1);
                return out;
            }
            platform::Channel* const chs[] = {&ch_};
            auto ready = platform::wait_readable(chs, std::chrono::seconds(1));
            if (!ready) return fail(ErrorKind::device, "s51's console: " + ready.error().what, "lpt:emu");
            if (!(*ready)[0]) {
                if (!alive_()) return fail(ErrorKind::device, "s51 closed its console", "lpt:emu");
                continue;
            }
            std::array<std::uint8_t, 4096> chunk{};
            auto n = ch_.read_some(chunk);
            if (!n || *n == 0) return fail(ErrorKind::device, "s51 closed its console", "lpt:emu");
            buf_.append(reinterpret_cast<const char*>(chunk.data()), *n);
        }
    }
    // Past the welcome and its prompts, whatever their order: an echo comes back.
    Result<void> sync() {
        auto out = command("echo tactus-ready");
        while (out && out->find("tactus-ready") == std::string::npos) out = answer();
        if (!out) return std::unexpected(out.error());
        return {};
    }
private:
    platform::Channel& ch_;
    std::function<bool()> alive_;
    std::string buf_;
};

// A latch's value in `get sfr` output: "0xa0 P2:   0b11110011 0xf3 ...".
std::optional<unsigned> sfr_value(const std::string& out, const std::string& name) {
    const auto at = out.rfind(name);
    if (at == std::string::npos) return std::nullopt;
    const auto b = out.find("0b", at);
    if (b == std::string::npos) return std::nullopt;
    const auto x = out.find("0x", b);
    if (x == std::string::npos) return std::nullopt;
    return static_cast<unsigned>(std::strtoul(out.c_str() + x + 2, nullptr, 16));
}

struct EmuOptions {
    fs::path ihx;
    std::string log;
    std::string trace;
    bool paper_out = false;
    // With paper_out: the operator loads paper this long (chip time) after
    // the host's side first shows PError in compatibility mode.
    std::optional<double> reload_s;
    // The hammer-home sensor (P3.7) reads low from the Nth strike read from
    // the pins on: a hammer stuck down (0: never).
    std::size_t hammer_at_strike = 0;
    // A warm reset (RST: the SFRs cleared, RAM kept) just after the Nth
    // strike, from an s51 breakpoint on the firmware's strike-fired label.
    std::size_t reset_at_strike = 0;
    // The cable out over [first, second) seconds of chip time: the chip runs
    // on, its input pins float high, the host reads every status line high.
    std::optional<std::pair<double, double>> pull;
};

class EmulatedLptLines final : public transport::ParallelPortLines {
public:
    static Result<std::shared_ptr<EmulatedLptLines>> open(const EmuOptions& o) {
        std::shared_ptr<EmulatedLptLines> l(new EmulatedLptLines(o));
        try {
            if (auto r = l->start(); !r) return std::unexpected(r.error());
        } catch (const CommandFailed& e) {
            return fail(ErrorKind::usage, e.what(), "lpt:emu");
        }
        return l;
    }
    ~EmulatedLptLines() override {
        if (hammer_stuck_) say_condition();
        cmd_.reset();
        s51_.reset();
        drain_trace();
        if (std::getenv("TACTUS_LPT_EMU_STATS"))
            std::fprintf(stderr, "lpt:emu: %ld console lines, %.2f ms a line, %.3f s simulated, %ld instructions, %ld status reads with the cable out\n",
                         lines_, lines_ ? wall_s_ * 1000 / static_cast<double>(lines_) : 0.0, clock_s_, instructions_,
                         reads_while_pulled_);
        std::error_code ec;
        if (!dir_.empty() && !std::getenv("TACTUS_KEEP_EMULATOR_DIR")) fs::remove_all(dir_, ec);
    }

    Result<void> write_data(std::uint8_t value) override {
        if (value != data_) changed_ = true;
        data_ = value;
        return {};
    }
    Result<void> write_control(const LptControl& lines) override {
        if (!(lines == ctl_)) changed_ = control_changed_ = true;
        ctl_ = lines;
        return {};
    }
    Result<LptStatus> read_status() override {
        steps_ = changed_ ? kReactSteps : std::min(kMostSteps, steps_ * 2);
        // The reads come before the step on s51's line: this is the chip as
        // the last exchange left it, the lines just set not yet seen by its code.
        auto out = exchange("get sfr 0xa0;get sfr 0xb0", steps_);
        if (!out) return std::unexpected(out.error());
        const auto p2 = sfr_value(*out, "P2:"), p3 = sfr_value(*out, "P3:");
        if (!p2 || !p3) return fail(ErrorKind::device, "s51 did not show the port latches: " + out->substr(0, 200), "lpt:emu");
        if (cable_out_) {
            ++reads_while_pulled_;
            return LptStatus{.n_ack = true, .busy = true, .paper_error = true, .select = true, .n_fault = true};
        }
        operator_loads_paper(((*p2 >> 2) & 1U) != 0);

        return LptStatus{.n_ack = ((*p3 >> 5) & 1U) != 0,
                         .busy = ((*p2 >> 3) & 1U) != 0,
                         .paper_error = ((*p2 >> 2) & 1U) != 0,
                         .select = ((*p2 >> 1) & 1U) != 0,
                         .n_fault = (*p2 & 1U) != 0};
    }
    void settle() override {
        // New data alone needs no time: s51 sets the data pins before the
        // control pins on the line that carries both (pins()).
        if (control_changed_) (void)exchange("", kSettleSteps);
    }
    [[nodiscard]] std::optional<double> clock() const override { return clock_s_; }
    bool run_for(std::chrono::microseconds d) override {
        const double until = clock_s_ + std::chrono::duration<double>(d).count();
        while (clock_s_ < until) {
            // About 1.3 machine cycles an instruction, 12 clocks a cycle.
            const double left = (until - clock_s_) * kXtalHz / 12 / 1.3;
            if (!exchange("", std::clamp(static_cast<long>(left), 10L, kMostSteps))) break;
        }
        return true;
    }

private:
    explicit EmulatedLptLines(EmuOptions o) : o_(std::move(o)) {
        const auto p = profile::default_profile();
        trace_.emplace(p.carriage.steps_per_mm, p.feed.steps_per_mm);
    }

    Result<void> start() {
        if (o_.ihx.empty()) return device_error("lpt:emu needs fw=FILE.ihx, the emulator build (make -C firmware emu)");
        o_.ihx = fs::absolute(o_.ihx);
        if (!fs::is_regular_file(o_.ihx))
            return device_error(o_.ihx.string() + ": no such firmware image (build it with make -C firmware emu)");
        const unsigned sheet_at = firmware_map_symbol(fs::path(o_.ihx).replace_extension(".map"), "_fw_sheet");
        if (!platform::find_in_path("s51")) return device_error("s51 not found (apt-get install sdcc-ucsim)");
        if (!o_.log.empty()) {
            log_.open(o_.log, std::ios::app);
            if (!log_) return fail(ErrorKind::usage, o_.log + ": cannot write the strike log", "lpt:emu");
        }
        platform::ignore_broken_pipe();  // s51 may end while a line is written
        auto dir = platform::make_private_dir("tactus-lpt-s51");
        if (!dir) return device_error("cannot make a temporary folder");
        dir_ = *dir;
        vcd_path_ = o_.trace.empty() ? dir_ / "pins.vcd" : fs::absolute(o_.trace);
        {
            std::ofstream cmds(dir_ / "cmds");
            cmds << "file \"" << o_.ihx.string() << "\"\n"
                 << "set hw vcd[0] output \"" << vcd_path_.string() << "\"\n"
                 << "set hw vcd[0] add port_1_cfg 2\n"
                 << "set hw vcd[0] add iram 0x" << std::hex << sheet_at << "\n"
                 << "set hw vcd[0] add iram 0x" << sheet_at + 1 << std::dec << "\n"
                 << "set hw vcd[0] start\n";
            if (o_.reset_at_strike > 0) {
                // Its Nth hit stops the chip just after the Nth strike (the
                // head at rest), removes itself and resets: the step it ended
                // says "Breakpoint" (exchange()).
                const unsigned fired = firmware_map_symbol(fs::path(o_.ihx).replace_extension(".map"), "_fw_strike_fired");
                cmds << "break 0x" << std::hex << fired << std::dec << " " << o_.reset_at_strike << "\n"
                     << "commands 1 delete 1 ; reset\n";
            }
        }
        // The console on a pseudo-terminal: no TCP segments to wait for, one
        // read a line. s51 naps 100 ms whenever it finds no command waiting
        // while the chip is stopped, and in lockstep nearly every line waits
        // for a nap; the wake library turns the nap into a wait for the next
        // line (firmware/tools/s51_wake.c, bench/firmware/lpt-bridge.md).
        auto pty = platform::SimEndpoint::open(false);
        if (!pty) return device_error("no pseudo-terminal for s51's console: " + pty.error().what);
        console_pty_.emplace(std::move(*pty));
        std::vector<std::string> args{"s51", "-t", "C52", "-X", "11.0592M", "-b", "-P",
                                      "-c", console_pty_->path(), "-C", "cmds"};
        if (const auto wake = wake_library())
            args.insert(args.begin(), {"env", "LD_PRELOAD=" + wake->string()});
        else
            std::fprintf(stderr, "lpt:emu: %s is not beside the program: s51 naps 100 ms on every console line\n",
                         kWakeLibrary);
        auto s51 = platform::ChildProcess::spawn(
            {.args = args, .dir = dir_, .log = dir_ / "s51.log", .idle_input = true, .lower_priority = true});
        if (!s51) return device_error("cannot start s51: " + s51.error().what);
        s51_.emplace(std::move(*s51));
        cmd_.emplace(console_pty_->line(), [this] { return s51_->running(); });
        if (auto r = cmd_->sync(); !r) return device_error(r.error().message + ": " + log_tail());
        changed_ = true;  // the host's idle lines on the pins before the chip boots
        if (auto r = exchange("", kBootSteps); !r) return std::unexpected(r.error());
        return {};
    }

    // What the status lines show in compatibility mode once the host has left
    // the chip alone (its last reply read): a stuck hammer's fault on nFault.
    void say_condition() {
        if (ctl_.n_select_in || !exchange("", kReactSteps * 10)) return;
        const auto out = exchange("get sfr 0xa0", 10);
        const auto p2 = out ? sfr_value(*out, "P2:") : std::nullopt;
        if (p2)
            std::fprintf(stderr, "lpt:emu: at the end nFault is %s, PError %s\n", (*p2 & 1U) ? "high" : "low (a fault stands)",
                         (*p2 & 4U) ? "high" : "low");
    }

    // PError in compatibility mode is paper out (in nibble mode it is a data
    // bit): the operator sees it and, reload_s later, loads paper.
    void operator_loads_paper(bool perror) {
        if (!o_.paper_out || !o_.reload_s) return;
        if (perror && !ctl_.n_select_in && !perror_seen_s_) perror_seen_s_ = clock_s_;
        if (perror_seen_s_ && clock_s_ >= *perror_seen_s_ + *o_.reload_s) {
            o_.paper_out = false;
            changed_ = true;
        }
    }

    std::string log_tail() const {
        std::ifstream in(dir_ / "s51.log");
        std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        return all.size() > 400 ? all.substr(all.size() - 400) : all;
    }

    std::string pins() const {
        // Every pin the host does not drive reads high (the 8051's pull-ups).
        unsigned p2 = 0xFF, p3 = 0xFF;
        if (!ctl_.n_auto_fd) p2 &= ~0x10U;
        if (!ctl_.n_select_in) p2 &= ~0x20U;
        if (!ctl_.n_strobe) p3 &= ~0x04U;
        unsigned data = data_;
        if (cable_out_) p2 = 0xFF, p3 = 0xFF, data = 0xFF;  // the host's lines gone: pulled up
        if (o_.paper_out) p3 &= ~0x40U;  // the paper sensor
        if (hammer_stuck_) p3 &= ~0x80U;  // the hammer-home sensor: not back
        char b[160];
        std::snprintf(b, sizeof b, "set memory port_0_cfg 1 0x%02x;set memory port_2_cfg 1 0x%02x;set memory port_3_cfg 1 0x%02x",
                      data, p2, p3);
        return b;
    }

    // One console line: the host's lines when they changed, then `reads`, then
    // `steps` instructions (s51 does a line's other commands before its step).
    Result<std::string> exchange(const std::string& reads, long steps) {
        if (failed_) return std::unexpected(*failed_);
        if (const bool out = o_.pull && clock_s_ >= o_.pull->first && clock_s_ < o_.pull->second; out != cable_out_) {
            cable_out_ = out;
            changed_ = true;
            if (!out)
                std::fprintf(stderr, "lpt:emu: the cable is back in (%.3f s) after %ld status reads with it out\n",
                             clock_s_, reads_while_pulled_);
        }
        std::string line;
        if (changed_) line = pins() + ";";
        changed_ = control_changed_ = false;
        if (!reads.empty()) line += reads + ";";
        line += "step " + std::to_string(steps);
        const auto t0 = std::chrono::steady_clock::now();
        auto out = cmd_->command(line);
        wall_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        ++lines_;
        instructions_ += steps;
        if (!out) return remember(out.error());
        // A step that ran out says "stepped N ticks"; one the reset's
        // breakpoint ended (it has reset the chip) "Simulated N ticks".
        auto at = out->find("stepped ");
        std::size_t skip = 8;
        if (at == std::string::npos && out->find("Breakpoint") != std::string::npos) {
            at = out->find("Simulated ");
            skip = 10;
        }
        if (at == std::string::npos) {
            const auto stop = out->find("Stop at");
            return remember(Error{"the emulated chip stopped by itself: " +
                                      (stop == std::string::npos ? out->substr(0, 300) : out->substr(stop, 200)),
                                  "lpt:emu", ErrorKind::device});
        }
        clock_s_ += static_cast<double>(std::strtoull(out->c_str() + at + skip, nullptr, 10)) / kXtalHz;
        drain_trace();
        return out;
    }

    std::unexpected<Error> remember(Error e) {
        failed_ = e;
        return std::unexpected(std::move(e));
    }

    // The strikes fired so far, read from the pin trace s51 appends to.
    void drain_trace() {
        if (!vcd_.is_open()) vcd_.open(vcd_path_, std::ios::binary);
        if (!vcd_.is_open()) return;
        std::string chunk(1 << 16, '\0');
        std::vector<controller::LoggedStrike> strikes;
        for (;;) {
            vcd_.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
            const auto n = static_cast<std::size_t>(vcd_.gcount());
            if (n == 0) break;
            strikes.clear();
            if (auto r = trace_->push(std::string_view(chunk).substr(0, n), strikes); !r) {
                failed_ = r.error();
                break;
            }
            for (const auto& s : strikes) {
                write_strike_json(log_, s);
                if (++strikes_ == o_.hammer_at_strike) {
                    hammer_stuck_ = true;
                    changed_ = true;
                }
            }
        }
        vcd_.clear();  // at its end for now: the emulator appends more
    }

    EmuOptions o_;
    fs::path dir_, vcd_path_;
    std::optional<platform::SimEndpoint> console_pty_;
    std::optional<platform::ChildProcess> s51_;
    std::optional<Console> cmd_;
    std::optional<controller::FirmwareTrace> trace_;
    std::ifstream vcd_;
    std::ofstream log_;
    std::optional<Error> failed_;
    LptControl ctl_{};
    std::uint8_t data_ = 0;
    bool changed_ = true;
    bool control_changed_ = false;
    long steps_ = kReactSteps;
    double clock_s_ = 0;
    std::optional<double> perror_seen_s_;
    bool cable_out_ = false;
    bool hammer_stuck_ = false;
    std::size_t strikes_ = 0;
    long lines_ = 0, instructions_ = 0, reads_while_pulled_ = 0;  // for TACTUS_LPT_EMU_STATS
    double wall_s_ = 0;
};

// "FROM:TO", seconds with 0 <= FROM < TO.
std::optional<std::pair<double, double>> seconds_span(const std::string& v) {
    const auto colon = v.find(':');
    if (colon == std::string::npos) return std::nullopt;
    const auto from = transport::option_number(v.substr(0, colon)), to = transport::option_number(v.substr(colon + 1));
    if (!from || !to || *from < 0 || *to <= *from) return std::nullopt;
    return std::pair{*from, *to};
}

// The host's end of the cable: the port closes it when it reopens (the
// link's reconnect), and the chip behind it runs on.
class CableEnd final : public transport::ParallelPortLines {
public:
    explicit CableEnd(std::shared_ptr<EmulatedLptLines> chip) : chip_(std::move(chip)) {}
    Result<void> write_data(std::uint8_t v) override { return chip_->write_data(v); }
    Result<void> write_control(const LptControl& c) override { return chip_->write_control(c); }
    Result<LptStatus> read_status() override { return chip_->read_status(); }
    void settle() override { chip_->settle(); }
    [[nodiscard]] std::optional<double> clock() const override { return chip_->clock(); }
    bool run_for(std::chrono::microseconds d) override { return chip_->run_for(d); }

private:
    std::shared_ptr<EmulatedLptLines> chip_;
};

// One chip per device string for the life of the program: opening the same
// string again (a reconnect) finds the chip where the cable left it, running,
// its RAM and job intact, as a cable put back would.
std::map<std::string, std::shared_ptr<EmulatedLptLines>>& chips() {
    static std::map<std::string, std::shared_ptr<EmulatedLptLines>> all;
    return all;
}

Result<std::unique_ptr<transport::ParallelPortLines>> open_emulated(const transport::DeviceSpec& spec) {
    EmuOptions o;
    std::string key = spec.path;
    for (const auto& [k, v] : spec.options) {
        const auto number = transport::option_number(v);
        key += "&" + k + "=" + v;
        if (k == "fw") o.ihx = v;
        else if (k == "log") o.log = v;
        else if (k == "trace") o.trace = v;
        else if (k == "paper" && (v == "out" || v == "in")) o.paper_out = v == "out";
        else if (k == "reload" && number && *number >= 0)
            o.reload_s = *number;
        else if ((k == "hammer" || k == "reset") && number && *number >= 1 && *number == std::floor(*number))
            (k == "hammer" ? o.hammer_at_strike : o.reset_at_strike) = static_cast<std::size_t>(*number);
        else if (const auto span = k == "pull" ? seconds_span(v) : std::nullopt)
            o.pull = span;
        else
            return fail(ErrorKind::usage,
                        "unknown option \"" + k + "=" + v +
                            "\" (lpt:emu takes fw=, log=, trace=, paper=in|out, reload=SECONDS, hammer=N, reset=N, pull=FROM:TO)",
                        "lpt:emu");
    }
    auto& chip = chips()[key];
    if (!chip) {
        auto c = EmulatedLptLines::open(o);
        if (!c) {
            chips().erase(key);
            return std::unexpected(c.error());
        }
        chip = *c;
    }
    return std::make_unique<CableEnd>(chip);
}

}  // namespace

void close_emulated_lpt() { chips().clear(); }

void register_emulated_lpt() {
    transport::LptTimings t;
    // On the chip's clock: each poll that finds no reply lets it run this long
    // (its motion goes on meanwhile), as a real host's keep-alive would.
    t.poll_interval = std::chrono::milliseconds(150);
    transport::register_lpt_cable("emu", {.open = open_emulated, .timings = t});
}

}  // namespace tactus::cli
