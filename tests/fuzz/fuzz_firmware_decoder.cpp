// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the firmware's link layer, compiled natively from the same C the
// 89C52 runs (firmware/src), in two modes chosen by the first input byte:
//
//  even: the frame decoder alone, differentially against the host's
//        FrameDecoder (core/encode/frame.cpp): the same bytes must give the
//        same frames, in the same order. (The firmware's receive area is
//        sized to the chip; here it is given room for the largest frame, so
//        the two must agree byte for byte.)
//  odd:  the whole link (sessions, window, the job-stream check) with the
//        ring consumed now and then as the executor would: the ring's
//        bounds hold, and every reply is a well-formed frame.
//
// Built by CMake with TACTUS_FUZZ (clang), or alone: make -C firmware fuzz.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#define FW_BUF_CAP 96
extern "C" {
#include "../../firmware/src/crc16.c"
#include "../../firmware/src/decoder.c"
#define fw_frame link_fw_frame
#include "../../firmware/src/link.c"
#undef fw_frame
}

#include "encode/frame.hpp"

namespace {

struct Seen {
    std::uint8_t seq, type;
    std::vector<std::uint8_t> payload;
};
bool link_mode = false;
std::vector<Seen> seen;
std::vector<std::uint8_t> replies;
std::uint8_t paper = 1;

void require(bool ok) {
    if (!ok) std::abort();
}

// Replies are parsed back: SYNC, LEN, SEQ, TYPE, payload, CRC.
void check_replies() {
    std::size_t i = 0;
    while (i < replies.size()) {
        require(replies[i] == FW_SYNC);
        require(i + 6 <= replies.size());
        const std::uint8_t len = replies[i + 1];
        require(i + 6u + len <= replies.size());
        const std::uint16_t c = crc16_block(&replies[i + 1], static_cast<std::uint8_t>(len + 3), 0xFFFF);
        require(replies[i + 4 + len] == (c >> 8) && replies[i + 5 + len] == (c & 0xFF));
        i += 6u + len;
    }
    replies.clear();
}

}  // namespace

extern "C" {
void fw_frame(FW_IDATA uint8_t* f) {
    if (link_mode) {
        link_fw_frame(f);
        return;
    }
    seen.push_back({f[1], f[2], std::vector<std::uint8_t>(f + 3, f + 3 + f[0])});
}
void fw_tx_kick(void) {}
uint8_t fw_paper_present(void) { return paper; }
uint8_t fw_stack_used(void) { return 0; }
const uint8_t fw_table_id[4] = {1, 2, 3, 4};
void exec_abort(void) {}
uint8_t exec_busy(void) { return 0; }
void exec_drop_pass(void) {}
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    link_mode = (data[0] & 1) != 0;
    const std::uint8_t* bytes = data + 1;
    const std::size_t n = size - 1;
    seen.clear();
    replies.clear();
    fw_state = ST_IDLE;
    fw_faults = 0;
    fw_flags = 0;
    fw_link_init(0);
    if (!link_mode) {
        for (std::size_t i = 0; i < n; ++i) fw_rx_byte(bytes[i]);
        tactus::encode::FrameDecoder host;
        std::vector<tactus::encode::Frame> frames;
        host.push(std::span<const std::uint8_t>(bytes, n), frames);
        require(frames.size() == seen.size());
        for (std::size_t i = 0; i < frames.size(); ++i) {
            require(frames[i].seq == seen[i].seq && frames[i].type == seen[i].type);
            require(frames[i].payload == seen[i].payload);
        }
        for (const auto& f : seen) require(f.payload.size() <= FW_WIRE_MAX_PAYLOAD);
        return 0;
    }
    // The link: bytes in; now and then the executor consumes the ring, the
    // paper goes, the ring compacts; every reply is drained and parsed.
    for (std::size_t i = 0; i < n; ++i) {
        fw_rx_byte(bytes[i]);
        require(fw_ops_head <= fw_ops_done && fw_ops_done <= fw_ops_end);
        require(fw_ops_end + fw_rx_fill() <= FW_BUF_CAP);
        require(fw_ring_free() <= FW_RING_BYTES);
        if ((bytes[i] & 0x0F) == 0x0B && fw_ops_head < fw_ops_done) fw_ops_head = fw_ops_done;
        if (bytes[i] == 0x3C) paper = !paper;
        if (fw_ops_head > 0) fw_compact();
        fw_report_room();
        std::int16_t b;
        while ((b = fw_reply_byte()) >= 0) replies.push_back(static_cast<std::uint8_t>(b));
    }
    check_replies();
    return 0;
}
