// SPDX-License-Identifier: GPL-3.0-or-later
#include "firmware_emulator.hpp"

#include <array>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <random>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "controller/firmware_trace.hpp"
#include "platform/channel.hpp"
#include "platform/child_process.hpp"
#include "platform/durable_file.hpp"
#include "platform/sim_endpoint.hpp"

namespace tactus::cli {
namespace {

namespace fs = std::filesystem;

// Removes the run's folder and stops the emulator, however the run ends.
struct Run {
    fs::path dir;
    std::optional<platform::ChildProcess> s51;
    platform::Channel fifo_in, fifo_out;
    platform::SimEndpoint pty;
    ~Run() {
        s51.reset();
        std::error_code ec;
        if (!dir.empty() && !std::getenv("TACTUS_KEEP_EMULATOR_DIR")) fs::remove_all(dir, ec);
    }
};

// The line between the pty and the emulator's FIFOs: bytes either way, each
// dropped, bit-flipped or duplicated at `noise` (seeded), like sim --pty's.
class Bridge {
public:
    Bridge(platform::Channel& master, platform::Channel& to_chip, platform::Channel& from_chip, double noise,
           std::uint64_t seed)
        : master_(master), to_chip_(to_chip), from_chip_(from_chip), noise_(noise), rng_(seed) {}

    // Moves what is waiting, for up to `ms` milliseconds.
    void pump(int ms) {
        platform::Channel* const lines[] = {&master_, &from_chip_};
        const auto ready = platform::wait_readable(lines, std::chrono::milliseconds(ms));
        if (!ready) return;
        std::array<std::uint8_t, 512> buf{};
        if ((*ready)[0]) {
            const auto n = master_.read_some(buf);
            if (n && *n > 0) forward(to_chip_, std::span(buf).first(*n));
        }
        if ((*ready)[1]) {
            const auto n = from_chip_.read_some(buf);
            if (n && *n > 0) forward(master_, std::span(buf).first(*n));
        }
    }
    [[nodiscard]] std::size_t corrupted() const { return corrupted_; }

private:
    void forward(platform::Channel& to, std::span<const std::uint8_t> in) {
        std::vector<std::uint8_t> out;
        std::uniform_real_distribution<double> u(0, 1);
        for (std::uint8_t b : in) {
            if (noise_ > 0 && u(rng_) < noise_) {
                ++corrupted_;
                continue;  // dropped
            }
            if (noise_ > 0 && u(rng_) < noise_) {
                ++corrupted_;
                b = static_cast<std::uint8_t>(b ^ (1U << (rng_() % 8)));
            }
            out.push_back(b);
            if (noise_ > 0 && u(rng_) < noise_) {
                ++corrupted_;
                out.push_back(b);  // duplicated
            }
        }
        for (std::size_t done = 0; done < out.size();) {
            const auto n = to.write_some(std::span(out).subspan(done));
            if (!n || *n == 0) return;  // the client went away: the line loses the bytes
            done += *n;
        }
    }
    platform::Channel& master_;
    platform::Channel& to_chip_;
    platform::Channel& from_chip_;
    double noise_;
    std::mt19937_64 rng_;
    std::size_t corrupted_ = 0;
};

}  // namespace

// A symbol's address from the linker's map next to the image: the firmware's
// sheet number in internal RAM (the pin trace says where the carriage and the
// paper are, the sheet only the firmware knows), and the strike-fired label
// the reset breakpoint goes on.
unsigned firmware_map_symbol(const std::filesystem::path& map, const std::string& symbol) {
    std::ifstream in(map);
    if (!in)
        throw CommandFailed(exit_bad_input, map.string() + ": the linker map of the firmware image is missing "
                                                           "(it is written beside the .ihx by make -C firmware emu)");
    for (std::string line; std::getline(in, line);) {
        std::istringstream w(line);
        std::string addr, name;
        if (w >> addr && addr.ends_with(':')) w >> addr;  // a code symbol's "C:" area mark
        if (w >> name && name == symbol) return static_cast<unsigned>(std::stoul(addr, nullptr, 16));
    }
    throw CommandFailed(exit_bad_input, map.string() + ": no " + symbol + ": not a Tactus firmware map" +
                                            (symbol == "_fw_strike_fired" ? " of the emulator build (make -C firmware emu)"
                                                                          : ""));
}

void run_firmware_emulator(const FirmwareEmulatorOptions& o, const std::atomic<bool>& stop,
                           const std::function<void(const controller::LoggedStrike&)>& on_strike) {
    const fs::path ihx = fs::absolute(o.ihx);
    if (!fs::is_regular_file(ihx))
        throw CommandFailed(exit_bad_input, o.ihx + ": no such firmware image (build it with make -C firmware emu)");
    const auto map = fs::path(ihx).replace_extension(".map");
    const unsigned sheet_at = firmware_map_symbol(map, "_fw_sheet");
    const unsigned strike_fired = o.reset_at_strike > 0 ? firmware_map_symbol(map, "_fw_strike_fired") : 0;
    const bool reload = o.paper_out && o.paper_reload_reads > 0;
    const unsigned paper_read = reload ? firmware_map_symbol(map, "_fw_paper_present") : 0;
    if (!platform::find_in_path("s51"))
        throw CommandFailed(exit_device, "sim --firmware: s51 not found (apt-get install sdcc-ucsim)");
    Run run;
    auto dir = platform::make_private_dir("tactus-s51");
    if (!dir) throw CommandFailed(exit_failure, "sim --firmware: cannot make a temporary folder");
    run.dir = *dir;
    const auto h2t = run.dir / "h2t", t2h = run.dir / "t2h";
    const auto vcd = o.pin_trace.empty() ? run.dir / "pins.vcd" : fs::absolute(o.pin_trace);
    // Held open on both ends here (this process is the bridge), so s51's opens never wait.
    auto fifo_in = platform::open_fifo(h2t);
    auto fifo_out = platform::open_fifo(t2h);
    if (!fifo_in || !fifo_out)
        throw CommandFailed(exit_failure, "sim --firmware: cannot make the emulator's FIFOs in " + run.dir.string());
    run.fifo_in = std::move(*fifo_in);
    run.fifo_out = std::move(*fifo_out);
    {
        // A command file runs before a hex file named on the command line is
        // loaded, so it loads the image itself.
        std::ofstream cmds(run.dir / "cmds");
        cmds << "file \"" << ihx.string() << "\"\n";
        if (o.paper_out) cmds << "set memory port_3_cfg 1 0xbf\n";  // P3.6, the paper sensor, low
        cmds << "set hw vcd[0] output \"" << vcd.string() << "\"\n"
             << "set hw vcd[0] add port_1_cfg 2\n"
             << "set hw vcd[0] add iram 0x" << std::hex << sheet_at << "\n"
             << "set hw vcd[0] add iram 0x" << sheet_at + 1 << std::dec << "\n"
             << "set hw vcd[0] start\n";
        int breakpoint = 0;  // s51 numbers them from 1 as they are set
        if (o.reset_at_strike > 0) {
            // A warm reset (RST: the SFRs cleared, RAM kept) just after the
            // Nth strike fired: the breakpoint stops the chip on its Nth hit,
            // removes itself, resets and runs on.
            ++breakpoint;
            cmds << "break 0x" << std::hex << strike_fired << std::dec << " " << o.reset_at_strike << "\n"
                 << "commands " << breakpoint << " delete " << breakpoint << " ; reset ; run\n";
        }
        if (reload) {
            // The operator loads paper: at the Nth read of the sensor the
            // breakpoint raises P3.6, removes itself and runs on.
            ++breakpoint;
            cmds << "break 0x" << std::hex << paper_read << std::dec << " " << o.paper_reload_reads << "\n"
                 << "commands " << breakpoint << " delete " << breakpoint
                 << " ; set memory port_3_cfg 1 0xff ; run\n";
        }
        // `run` returns when the chip stops by itself (a stack overflow, an
        // invalid instruction); `kill` then ends s51, which the loop below
        // sees as the chip's own end.
        cmds << "run\nkill\n";
    }
    // s51's console on stdin: a pipe held open and never written, so it
    // reads no command and never sees an end of file. With /dev/null there,
    // s51 at times (under load, in CI) went on to read its own log as
    // commands once the chip stopped, and its real stop reason scrolled out
    // of the log's tail behind the parser errors.
    auto s51 = platform::ChildProcess::spawn(
        {.args = {"s51", "-t", "C52", "-X", "11.0592M", "-S", "in=h2t,out=t2h", "-e", "uart0_check_often=1", "-b",
                  "-C", "cmds"},
         .dir = run.dir,
         .log = run.dir / "s51.log",
         .idle_input = true,
         .lower_priority = true});
    if (!s51) throw CommandFailed(exit_failure, "sim --firmware: cannot start s51: " + s51.error().what);
    run.s51.emplace(std::move(*s51));
    // The pty a host opens; its slave is held open so the pty outlives a
    // client that closes it. Raw: every byte value passes.
    auto pty = platform::SimEndpoint::open(false);
    if (!pty) throw CommandFailed(exit_device, "sim --firmware: cannot make a pseudo-terminal: " + pty.error().what);
    run.pty = std::move(*pty);
    const std::string pts = run.pty.path();
    Bridge line(run.pty.line(), run.fifo_in, run.fifo_out, o.noise, o.seed);
    std::cout << pts << std::endl;

    controller::FirmwareTrace trace(o.carriage_steps_per_mm, o.feed_steps_per_mm);
    std::ifstream pins;
    std::size_t fired = 0;
    std::vector<controller::LoggedStrike> strikes;
    auto drain = [&] {
        if (!pins.is_open()) pins.open(vcd, std::ios::binary);
        if (!pins.is_open()) return;
        std::string chunk(1 << 16, '\0');
        for (;;) {
            pins.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
            const auto n = static_cast<std::size_t>(pins.gcount());
            if (n == 0) break;
            strikes.clear();
            if (auto r = trace.push(std::string_view(chunk).substr(0, n), strikes); !r) fail_with(r.error());
            for (const auto& s : strikes) on_strike(s);
            fired += strikes.size();
        }
        pins.clear();  // at the end for now: the emulator appends more
    };
    bool ended = false;
    auto last_drain = std::chrono::steady_clock::now();
    while (!stop.load() && !ended) {
        line.pump(20);
        if (std::chrono::steady_clock::now() - last_drain < std::chrono::milliseconds(50)) continue;
        last_drain = std::chrono::steady_clock::now();
        drain();
        if (!run.s51->running()) ended = true;
    }
    run.s51.reset();
    drain();  // what s51 wrote as it stopped
    std::cerr << "sim: " << fired << " strikes fired by the firmware (read from its pins), " << line.corrupted()
              << " bytes dropped, flipped or duplicated on the line"
              << (ended ? "; the emulator ended by itself" : "") << "\n";
    if (ended) {
        // Why: s51's first stop reason once the chip ran ("Stack overflow,
        // PC=...", an invalid instruction or address, an error), looked for
        // in the whole log; its end is shown as well.
        std::ifstream log(run.dir / "s51.log");
        std::vector<std::string> lines;
        for (std::string l; std::getline(log, l);) lines.push_back(l);
        std::string why;
        bool running = false;
        for (const auto& l : lines) {
            if (l.starts_with("Simulation started")) running = true;
            if (running && why.empty() &&
                (l.find("overflow") != std::string::npos || l.find("rror") != std::string::npos ||
                 l.find("nvalid") != std::string::npos))
                why = l;
        }
        for (std::size_t i = lines.size() > 12 ? lines.size() - 12 : 0; i < lines.size(); ++i)
            std::cerr << "sim: s51: " << lines[i] << "\n";
        // A chip that stops by itself crashed (the firmware never ends its
        // own run): that is a failure, never a quiet end (a stack overflow
        // must not look like a run that just ended).
        throw CommandFailed(exit_failure, "sim --firmware: the emulated chip stopped by itself after " +
                                              std::to_string(fired) + " strikes: " +
                                              (why.empty() ? "s51 gave no reason" : why));
    }
}

void write_strike_json(std::ostream& log, const controller::LoggedStrike& s) {
    if (!log) return;
    log << nlohmann::json{{"sheet", s.sheet},
                          {"side", s.side == plan::Side::front ? "front" : "back"},
                          {"hammer", s.hammer == plan::Hammer::convex ? "convex" : "concave"},
                          {"carriage_step", s.carriage_step},
                          {"feed_step", s.feed_step},
                          {"x_mm", s.x_mm},
                          {"y_mm", s.y_mm},
                          {"time_s", s.time_s}}
               .dump()
        << '\n'
        << std::flush;
}

}  // namespace tactus::cli
