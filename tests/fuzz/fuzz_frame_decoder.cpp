// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the frame decoder and everything behind it: arbitrary bytes in
// arbitrary pieces, every decoded frame's payload through its message decoder,
// and the same bytes into the simulated controller (which must stay within its
// RAM budget and never crash on garbage).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "controller/sim_controller.hpp"
#include "encode/frame.hpp"
#include "encode/messages.hpp"
#include "encode/stream.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tactus;
    const std::span<const std::uint8_t> in(data, size);
    encode::FrameDecoder d;
    std::vector<encode::Frame> frames;
    // The first byte picks the piece size, so splits are explored too.
    const std::size_t piece = size ? 1 + data[0] % 97 : 1;
    for (std::size_t i = 0; i < size; i += piece) d.push(in.subspan(i, std::min(piece, size - i)), frames);
    d.idle(frames);
    if (d.pending() > encode::kMaxFrame) std::abort();
    for (const auto& f : frames) {
        if (f.payload.size() > encode::kMaxPayload) std::abort();
        (void)encode::decode_ack(f.payload);
        (void)encode::decode_nak(f.payload);
        (void)encode::decode_status(f.payload);
        (void)encode::decode_hello(f.payload);
        (void)encode::decode_hello_reply(f.payload);
        (void)encode::decode_config(f.payload);
        std::size_t pos = 0;
        while (pos < f.payload.size()) {
            auto op = encode::decode_op(std::span(f.payload).subspan(pos));
            if (!op) break;
            if (op->second == 0) std::abort();
            // Whatever decodes re-encodes to the same op (segments may come back
            // on a coarser grid, never with other values).
            std::vector<std::uint8_t> again;
            encode::append_op(again, op->first);
            const auto back = encode::decode_op(again);
            if (!back || back->first != op->first || back->second != again.size()) std::abort();
            pos += op->second;
        }
    }
    controller::SimController ctl;
    double t = 0;
    for (std::size_t i = 0; i < size; i += piece) {
        ctl.receive(in.subspan(i, std::min(piece, size - i)), t);
        t += 0.01;
        ctl.advance(t);
        if (ctl.ring_used() > machine::ram::kRingBytes) std::abort();
    }
    ctl.advance(t + 100);
    (void)ctl.take_output();
    return 0;
}
