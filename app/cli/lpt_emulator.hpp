// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `lpt:emu?fw=FILE.ihx`: the host's own parallel port (transport::LptPort) on
// the reference firmware's pins in the s51 emulator, with no serial line. The
// cable is s51's command console over TCP (-Z), in lockstep: the host's lines
// are set on the chip's input pins (P0 data, P3.2 nStrobe, P2.4 nAutoFd, P2.5
// nSelectIn), each status read reads its output latches (P2.0-P2.3, P3.5) and
// runs the chip on, and the port's clock is the chip's simulated time, so
// handshakes, the link's timeouts and the waits between polls all run on it
// (docs/transports.md, "The parallel port in the emulator";
// bench/firmware/lpt-bridge.md for why a second console is kept busy).
//
// Options: fw= the emulator build's image (its .map beside it), log= a strike
// log (JSON lines, as `sim --strike-log` writes), trace= keep the pin trace
// (VCD) there, paper=out (the paper sensor low from the start), reload=S
// (with paper=out: paper loaded S seconds of chip time after PError shows).

namespace tactus::cli {

// Registers `lpt:emu` with the transport (transport::register_lpt_cable).
void register_emulated_lpt();

}  // namespace tactus::cli
