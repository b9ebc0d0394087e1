// SPDX-License-Identifier: GPL-3.0-or-later
// One protocol-conformance suite, run against both controllers over a real
// pty: the C++ simulated controller (`tactus-cli sim --pty`, protocol 2) and
// the reference firmware in s51 (`tactus-cli sim --firmware --pty`, protocol
// 3). What the two versions share, frame by frame: sessions, sequence
// numbers, duplicates, out-of-order frames, refusals and silence on a bad
// CRC. Raw frames, no host link: the controllers are tested, not the host.
#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "controller/open_device.hpp"
#include "encode/frame.hpp"
#include "encode/messages.hpp"
#include "transport/byte_stream.hpp"
#include "../common/process.hpp"

namespace tactus {
namespace {

using encode::FrameType;
using encode::NakReason;
using test::Process;

struct Controller {
    std::string name;
    bool firmware = false;
    std::uint8_t protocol = 2;
};

class Conformance : public ::testing::TestWithParam<Controller> {
protected:
    void SetUp() override {
        std::vector<std::string> args{TACTUS_CLI, "sim", "--pty"};
        if (GetParam().firmware) args.insert(args.end(), {"--firmware", TACTUS_FIRMWARE_IHX});
        else args.insert(args.end(), {"--baud", "9600"});
        server_.emplace(args);
        const auto pty = server_->read_line(std::chrono::seconds(30));
        ASSERT_EQ(pty.rfind("/dev/pts/", 0), 0U) << pty;
        auto s = controller::open_device("pty:" + pty + "?baud=9600");
        ASSERT_TRUE(s) << s.error().to_string();
        line_ = std::move(*s);
    }
    void TearDown() override {
        line_.reset();
        if (server_) {
            server_->signal(SIGTERM);
            server_->wait();
        }
    }

    void send(std::uint8_t seq, std::uint8_t type, std::vector<std::uint8_t> payload = {}) {
        std::vector<std::uint8_t> f;
        encode::append_frame(f, seq, static_cast<FrameType>(type), payload);
        ASSERT_TRUE(line_->write(f));
    }
    // The next frame within `timeout`, if any.
    std::optional<encode::Frame> reply(std::chrono::milliseconds timeout = std::chrono::milliseconds(3000)) {
        const double end = line_->now() + static_cast<double>(timeout.count()) / 1000.0;
        while (pending_.empty() && line_->now() < end) {
            std::array<std::uint8_t, 256> buf{};
            auto n = line_->read(buf, std::chrono::milliseconds(50));
            if (!n) return std::nullopt;
            decoder_.push(std::span(buf).first(*n), pending_);
        }
        if (pending_.empty()) return std::nullopt;
        auto f = pending_.front();
        pending_.erase(pending_.begin());
        return f;
    }
    // Opens a session with HELLO SEQ `seq`: the controller then expects seq + 1.
    void hello(std::uint8_t seq, std::uint16_t nonce = 0x1234) {
        send(seq, 0x01, encode::encode_hello({nonce, GetParam().protocol}));
        auto r = reply();
        ASSERT_TRUE(r);
        ASSERT_EQ(r->type, 0x81);
        EXPECT_EQ(r->seq, static_cast<std::uint8_t>(seq + 1));
        auto h = encode::decode_hello_reply(r->payload);
        ASSERT_TRUE(h) << h.error().to_string();
        EXPECT_EQ(h->protocol, GetParam().protocol);
        EXPECT_GE(h->window_frames, 1);
    }
    void expect_nak(NakReason why, std::optional<std::uint8_t> expected_seq) {
        auto r = reply();
        ASSERT_TRUE(r) << "no reply";
        ASSERT_EQ(r->type, 0x83);
        auto n = encode::decode_nak(r->payload);
        ASSERT_TRUE(n) << n.error().to_string();
        EXPECT_EQ(static_cast<int>(n->first), static_cast<int>(why));
        if (expected_seq) {
            EXPECT_EQ(r->seq, *expected_seq);
        }
    }
    void expect_ack(std::uint8_t expected_seq) {
        auto r = reply();
        ASSERT_TRUE(r) << "no reply";
        EXPECT_EQ(r->type, 0x82);
        EXPECT_EQ(r->seq, expected_seq);
        EXPECT_TRUE(encode::decode_ack(r->payload));
    }

    std::optional<Process> server_;
    std::unique_ptr<transport::ByteStream> line_;
    encode::FrameDecoder decoder_;
    std::vector<encode::Frame> pending_;
};

// Before a session the controller expects nothing: its NAK's SEQ is not checked.
TEST_P(Conformance, NothingBeforeASession) {
    send(0, 0x08);  // KEEPALIVE
    expect_nak(NakReason::no_session, std::nullopt);
}

TEST_P(Conformance, AnotherProtocolVersionIsRefused) {
    send(0, 0x01, encode::encode_hello({0x4321, 99}));
    expect_nak(NakReason::bad_payload, std::nullopt);
}

TEST_P(Conformance, SequenceDuplicatesAndGaps) {
    hello(10);
    send(11, 0x08);
    expect_ack(12);
    // The same frame again (its ACK was lost): acknowledged, the sequence stays.
    send(11, 0x08);
    expect_ack(12);
    // A frame ahead of the expected one: a frame was lost.
    send(14, 0x08);
    expect_nak(NakReason::out_of_order, 12);
    send(12, 0x07);  // STATUS
    auto r = reply();
    ASSERT_TRUE(r);
    EXPECT_EQ(r->type, 0x84);
    EXPECT_EQ(r->seq, 13);
    EXPECT_TRUE(encode::decode_status(r->payload));
}

TEST_P(Conformance, UnknownTypeIsRefused) {
    hello(0);
    send(1, 0x09);
    expect_nak(NakReason::unknown_type, 1);
}

TEST_P(Conformance, ACorruptFrameIsNeverAnswered) {
    hello(0);
    std::vector<std::uint8_t> f;
    encode::append_frame(f, 1, FrameType::keepalive, {});
    f.back() ^= 0x01;  // the CRC's low byte
    ASSERT_TRUE(line_->write(f));
    EXPECT_FALSE(reply(std::chrono::milliseconds(600)));
    send(1, 0x08);  // the next good frame is answered
    expect_ack(2);
}

TEST_P(Conformance, ARepeatedHelloOfTheSameSessionChangesNothing) {
    hello(5, 0x7777);
    send(6, 0x08);
    expect_ack(7);
    // A stale duplicate of the session's HELLO must not rewind the sequence.
    send(5, 0x01, encode::encode_hello({0x7777, GetParam().protocol}));
    auto r = reply();
    ASSERT_TRUE(r);
    EXPECT_EQ(r->type, 0x81);
    send(7, 0x08);
    expect_ack(8);
}

INSTANTIATE_TEST_SUITE_P(BothControllers, Conformance,
                         ::testing::Values(Controller{"cpp_simulator", false, 2}, Controller{"firmware_in_s51", true, 3}),
                         [](const auto& p) { return p.param.name; });

}  // namespace
}  // namespace tactus
