// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `tactus-cli sim --firmware FILE.ihx --pty`: the reference firmware in the
// s51 emulator (an 8052 at 11.0592 MHz, `-t C52`), its UART bridged to a
// pseudo-terminal, and its port pins traced, so the strikes it fires come
// back as the strike log the C++ simulated controller writes. The recipe is
// firmware/tools/run-s51.sh's (docs/emulator.md): two FIFOs for the
// emulator's serial port (s51's TCP and tty options are not binary-clean),
// bridged to a raw pty; here this process is the bridge (where
// run-s51.sh uses socat), so it can also put noise on the line.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include "controller/sim_controller.hpp"

namespace tactus::cli {

struct FirmwareEmulatorOptions {
    std::string ihx;           // the emulator build (make -C firmware emu): build-emu/tactus-fw.ihx
    bool paper_out = false;    // hold the paper sensor (P3.6) low
    double carriage_steps_per_mm = 80;  // for the log's millimetres
    double feed_steps_per_mm = 40;
    double noise = 0;          // per byte either way: dropped, flipped, duplicated, each at this rate
    std::uint64_t seed = 1;
    std::string pin_trace;     // keep the port-1 trace (VCD) here; a temporary file when empty
    // A warm reset of the chip just after its Nth strike (1-based; 0: none),
    // from an s51 breakpoint on the firmware's strike-fired label.
    std::size_t reset_at_strike = 0;
    // With paper_out: the operator loads paper (P3.6 goes high) once the
    // firmware has read its paper sensor this many times (0: never), from an
    // s51 breakpoint on fw_paper_present. While *paper out* stands the
    // firmware reads the sensor once per main-loop pass, so this is a delay
    // counted in passes (s51 has no timed breakpoint).
    std::size_t paper_reload_reads = 0;
};

// Starts s51 (niced), prints the pty path on stdout's first line,
// and runs until `stop` is set or the emulator ends; each strike read from the
// pin trace goes to `on_strike` as it is fired. Throws CommandFailed with what
// is missing (the image, its .map, s51) and the exit code.
void run_firmware_emulator(const FirmwareEmulatorOptions& o, const std::atomic<bool>& stop,
                           const std::function<void(const controller::LoggedStrike&)>& on_strike);

// A symbol's address from the linker's map beside the image (make -C
// firmware emu writes it): where the firmware keeps its sheet number, the
// labels a breakpoint goes on. Throws CommandFailed naming what is missing.
unsigned firmware_map_symbol(const std::filesystem::path& map, const std::string& symbol);

// One strike as a JSON line, flushed: a reader sees every strike at once. The
// same format for the C++ controller and the firmware in the emulator
// (`sim --strike-log`, `lpt:emu?log=`).
void write_strike_json(std::ostream& log, const controller::LoggedStrike& s);

}  // namespace tactus::cli
