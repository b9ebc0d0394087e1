// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Frames on the wire (docs/protocol.md):
//   SYNC 0x7E | LEN | SEQ | TYPE | PAYLOAD (LEN bytes) | CRC-16 hi | CRC-16 lo
// The CRC covers LEN..PAYLOAD. There is no byte stuffing: LEN bounds the frame,
// the CRC validates it, and after a bad frame the decoder looks for the next
// SYNC from the byte after the false one, so garbage never hides a good frame.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "encode/messages.hpp"
#include "machine/ram_budget.hpp"

namespace tactus::encode {

inline constexpr std::uint8_t kSync = 0x7E;
inline constexpr std::size_t kHeaderBytes = 4;
inline constexpr std::size_t kCrcBytes = 2;
inline constexpr std::size_t kFrameOverhead = kHeaderBytes + kCrcBytes;
// Largest payload in either direction: what the controller can take into its
// ring in one piece (see machine/ram_budget.hpp).
inline constexpr std::size_t kMaxPayload = machine::ram::kMaxPayload;
inline constexpr std::size_t kMaxFrame = kMaxPayload + kFrameOverhead;

struct Frame {
    std::uint8_t seq = 0;
    std::uint8_t type = 0;  // raw: unknown types are reported, not dropped by the decoder
    std::vector<std::uint8_t> payload;
    bool operator==(const Frame&) const = default;
};

// Appends one frame to `out`. The payload must be at most kMaxPayload bytes.
void append_frame(std::vector<std::uint8_t>& out, std::uint8_t seq, FrameType type,
                  std::span<const std::uint8_t> payload);
[[nodiscard]] std::vector<std::uint8_t> encode_frame(std::uint8_t seq, FrameType type,
                                                     std::span<const std::uint8_t> payload);

struct DecoderStats {
    std::size_t frames = 0;
    std::size_t crc_errors = 0;
    std::size_t oversize = 0;       // LEN above kMaxPayload
    std::size_t garbage_bytes = 0;  // bytes skipped while looking for SYNC
};

// Streaming decoder: bytes in any pieces, complete valid frames out. Memory is
// bounded by one frame.
class FrameDecoder {
public:
    // Decodes `bytes`, appending complete frames to `frames`.
    void push(std::span<const std::uint8_t> bytes, std::vector<Frame>& frames);
    void reset() { buf_.clear(); }
    // The line has been quiet for longer than a frame takes: a partial frame
    // still pending began at a false SYNC (garbage whose LEN promised more), so
    // rescan it. Without this a real frame after such garbage would wait for
    // the next traffic.
    void idle(std::vector<Frame>& frames) {
        if (!buf_.empty()) resync(frames);
    }
    [[nodiscard]] const DecoderStats& stats() const { return stats_; }
    [[nodiscard]] std::size_t pending() const { return buf_.size(); }

private:
    void push_byte(std::uint8_t b, std::vector<Frame>& frames);
    void resync(std::vector<Frame>& frames);
    std::vector<std::uint8_t> buf_;
    DecoderStats stats_;
};

}  // namespace tactus::encode
