// SPDX-License-Identifier: GPL-3.0-or-later
#include "encode/frame.hpp"

#include <cassert>

#include "encode/crc16.hpp"

namespace tactus::encode {

void append_frame(std::vector<std::uint8_t>& out, std::uint8_t seq, FrameType type,
                  std::span<const std::uint8_t> payload) {
    assert(payload.size() <= kMaxPayload);
    const std::size_t start = out.size();
    out.push_back(kSync);
    out.push_back(static_cast<std::uint8_t>(payload.size()));
    out.push_back(seq);
    out.push_back(static_cast<std::uint8_t>(type));
    out.insert(out.end(), payload.begin(), payload.end());
    const auto crc = crc16_ccitt(std::span(out).subspan(start + 1));
    out.push_back(static_cast<std::uint8_t>(crc >> 8));
    out.push_back(static_cast<std::uint8_t>(crc & 0xFF));
}

std::vector<std::uint8_t> encode_frame(std::uint8_t seq, FrameType type,
                                       std::span<const std::uint8_t> payload) {
    std::vector<std::uint8_t> out;
    out.reserve(payload.size() + kFrameOverhead);
    append_frame(out, seq, type, payload);
    return out;
}

void FrameDecoder::push(std::span<const std::uint8_t> bytes, std::vector<Frame>& frames) {
    for (const std::uint8_t b : bytes) push_byte(b, frames);
}

void FrameDecoder::push_byte(std::uint8_t b, std::vector<Frame>& frames) {
    if (buf_.empty()) {
        if (b == kSync) {
            buf_.push_back(b);
        } else {
            ++stats_.garbage_bytes;
        }
        return;
    }
    buf_.push_back(b);
    if (buf_.size() == 2 && buf_[1] > kMaxPayload) {
        ++stats_.oversize;
        resync(frames);
        return;
    }
    if (buf_.size() < kHeaderBytes) return;
    const std::size_t total = kFrameOverhead + buf_[1];
    if (buf_.size() < total) return;
    const auto body = std::span<const std::uint8_t>(buf_).subspan(1, total - 3);
    const auto crc = static_cast<std::uint16_t>((buf_[total - 2] << 8) | buf_[total - 1]);
    if (crc16_ccitt(body) != crc) {
        ++stats_.crc_errors;
        resync(frames);
        return;
    }
    Frame f;
    f.seq = buf_[2];
    f.type = buf_[3];
    f.payload.assign(buf_.begin() + kHeaderBytes, buf_.begin() + static_cast<std::ptrdiff_t>(total - 2));
    buf_.clear();
    ++stats_.frames;
    frames.push_back(std::move(f));
}

// The SYNC at buf_[0] was false: rescan everything after it. Bounded recursion:
// each level drops at least one byte of a buffer no longer than kMaxFrame.
void FrameDecoder::resync(std::vector<Frame>& frames) {
    std::vector<std::uint8_t> rest(buf_.begin() + 1, buf_.end());
    buf_.clear();
    ++stats_.garbage_bytes;
    for (const std::uint8_t b : rest) push_byte(b, frames);
}

}  // namespace tactus::encode
