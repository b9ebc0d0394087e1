// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `lpt:emu?fw=FILE.ihx`: the host's own parallel port (transport::LptPort) on
// the reference firmware's pins in the s51 emulator, with no serial line. The
// cable is s51's command console on a pseudo-terminal (-c), in lockstep: the host's lines
// are set on the chip's input pins (P0 data, P3.2 nStrobe, P2.4 nAutoFd, P2.5
// nSelectIn), each status read reads its output latches (P2.0-P2.3, P3.5) and
// runs the chip on, and the port's clock is the chip's simulated time, so
// handshakes, the link's timeouts and the waits between polls all run on it
// (docs/transports.md, "The parallel port in the emulator";
// bench/firmware/lpt-bridge.md for what a console line costs and why s51 is
// given firmware/tools/s51_wake.c).
//
// Options: fw= the emulator build's image (its .map beside it), log= a strike
// log (JSON lines, as `sim --strike-log` writes), trace= keep the pin trace
// (VCD) there, paper=out (the paper sensor low from the start), reload=S
// (with paper=out: paper loaded S seconds of chip time after PError shows),
// hammer=N (the hammer-home sensor low from the Nth strike on: a hammer
// stuck down), reset=N (a warm reset just after the Nth strike), pull=A:B
// (the cable out from A to B seconds of chip time).

namespace tactus::cli {

// Registers `lpt:emu` with the transport (transport::register_lpt_cable).
// One chip serves a device string until the program ends: reopening the
// string (the link's reconnect) finds it running, as a cable put back would.
void register_emulated_lpt();

// Ends every chip the cable started (their s51 stop): the next open of a
// device string powers a new chip up. For a program that runs several jobs
// each on a fresh chip (the conformance suite's cases).
void close_emulated_lpt();

}  // namespace tactus::cli
