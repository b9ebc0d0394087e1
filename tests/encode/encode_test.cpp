// SPDX-License-Identifier: GPL-3.0-or-later
// The codec: CRC, frames, the streaming decoder under garbage, varints,
// messages and job-stream ops, and plans the controller could not run.
#include <gtest/gtest.h>

#include <random>
#include <string_view>

#include "encode/crc16.hpp"
#include "encode/frame.hpp"
#include "encode/messages.hpp"
#include "plan/plan_file.hpp"
#include "profile/profile.hpp"
#include "encode/stream.hpp"
#include "encode/varint.hpp"
#include "../common/test_plans.hpp"

namespace tactus::encode {
namespace {

std::vector<std::uint8_t> bytes(std::string_view s) { return {s.begin(), s.end()}; }

TEST(Crc16, CcittFalseCheckValue) {
    // The catalogue check value of CRC-16/CCITT-FALSE for "123456789".
    EXPECT_EQ(crc16_ccitt(bytes("123456789")), 0x29B1);
    EXPECT_EQ(crc16_ccitt({}), 0xFFFF);
}

TEST(Frame, LayoutOnTheWire) {
    const std::vector<std::uint8_t> payload{0xAA, 0x7E};
    const auto f = encode_frame(5, FrameType::data, payload);
    ASSERT_EQ(f.size(), payload.size() + kFrameOverhead);
    EXPECT_EQ(f[0], kSync);
    EXPECT_EQ(f[1], 2);
    EXPECT_EQ(f[2], 5);
    EXPECT_EQ(f[3], 0x03);
    const auto crc = crc16_ccitt(std::span(f).subspan(1, 5));
    EXPECT_EQ(f[6], crc >> 8);
    EXPECT_EQ(f[7], crc & 0xFF);
}

TEST(Frame, DecodesAcrossArbitrarySplits) {
    std::vector<std::uint8_t> wire;
    std::vector<Frame> sent;
    for (std::uint8_t i = 0; i < 20; ++i) {
        std::vector<std::uint8_t> p(i * 4U % (kMaxPayload + 1), static_cast<std::uint8_t>(0x7E + i));
        append_frame(wire, i, FrameType::data, p);
        sent.push_back({i, 0x03, p});
    }
    for (std::size_t piece : {1U, 2U, 7U, 64U, 1000U}) {
        FrameDecoder d;
        std::vector<Frame> got;
        for (std::size_t i = 0; i < wire.size(); i += piece)
            d.push(std::span(wire).subspan(i, std::min(piece, wire.size() - i)), got);
        EXPECT_EQ(got, sent) << "piece " << piece;
    }
}

TEST(Frame, GarbageAndFalseSyncNeverHideAGoodFrame) {
    // Garbage full of SYNC bytes and plausible lengths, then a real frame.
    std::vector<std::uint8_t> wire{0x7E, 0x03, 0x7E, 0x7E, 0x50, 0x7E, 0xFF, 0x00, 0x7E};
    const std::vector<std::uint8_t> payload{1, 2, 3};
    append_frame(wire, 9, FrameType::keepalive, payload);
    FrameDecoder d;
    std::vector<Frame> got;
    d.push(wire, got);
    // A false SYNC here promised 80 bytes: the frame inside is found as soon as
    // the line goes quiet.
    EXPECT_TRUE(got.empty());
    d.idle(got);
    ASSERT_EQ(got.size(), 1U);
    EXPECT_EQ(got[0].seq, 9);
    EXPECT_EQ(got[0].payload, payload);
}

TEST(Frame, OversizedLengthIsRejected) {
    std::vector<std::uint8_t> wire{kSync, static_cast<std::uint8_t>(kMaxPayload + 1), 0, 3};
    wire.resize(200, 0x55);
    FrameDecoder d;
    std::vector<Frame> got;
    d.push(wire, got);
    EXPECT_TRUE(got.empty());
    EXPECT_EQ(d.stats().oversize, 1U);
    EXPECT_LE(d.pending(), kMaxFrame);
}

TEST(Frame, EverySingleBitFlipIsCaught) {
    const std::vector<std::uint8_t> payload{0x10, 0x00, 0x07, 0x00, 0x00, 0x40, 0x30};
    const auto f = encode_frame(3, FrameType::data, payload);
    for (std::size_t byte = 1; byte < f.size(); ++byte) {
        for (int bit = 0; bit < 8; ++bit) {
            auto g = f;
            g[byte] = static_cast<std::uint8_t>(g[byte] ^ (1U << bit));
            FrameDecoder d;
            std::vector<Frame> got;
            d.push(g, got);
            EXPECT_TRUE(got.empty()) << "byte " << byte << " bit " << bit;
        }
    }
}

TEST(Frame, WrongBaudGarbageYieldsNoFrames) {
    // What a UART at the wrong rate delivers: random bytes. Bounded memory, no frame.
    std::mt19937 rng(4);
    std::vector<std::uint8_t> junk(100000);
    for (auto& b : junk) b = static_cast<std::uint8_t>(rng());
    FrameDecoder d;
    std::vector<Frame> got;
    d.push(junk, got);
    EXPECT_TRUE(got.empty());  // a random 16-bit CRC match is possible but not with this seed
    EXPECT_LE(d.pending(), kMaxFrame);
}

TEST(Varint, RoundTripsAndBounds) {
    for (std::int32_t v : {0, 1, -1, 63, -64, 64, 127, 128, 300, -300, 65535, -32768,
                           std::numeric_limits<std::int32_t>::max(), std::numeric_limits<std::int32_t>::min()}) {
        std::vector<std::uint8_t> b;
        put_svar(b, v);
        std::size_t pos = 0;
        EXPECT_EQ(get_svar(b, pos), v);
        EXPECT_EQ(pos, b.size());
    }
    std::vector<std::uint8_t> b;
    put_uvar(b, 127);
    EXPECT_EQ(b.size(), 1U);  // the common step interval fits one byte
    const std::vector<std::uint8_t> unterminated{0x80, 0x80, 0x80, 0x80, 0x80, 0x80};
    std::size_t pos = 0;
    EXPECT_FALSE(get_uvar(unterminated, pos));
    const std::vector<std::uint8_t> too_big{0xFF, 0xFF, 0x7F};
    pos = 0;
    EXPECT_FALSE(get_uvar(too_big, pos, 0xFFFF, 3));
}

TEST(Messages, RoundTrip) {
    Status s;
    s.ack = {0x1234, 17, 4096, ControllerState::paused, fault::paper_out | fault::host_timeout, 9};
    s.flags = flag::homed | flag::job_active;
    s.job_id = 0x1234;
    s.sheet = 3;
    s.pass_index = 4095;
    s.carriage_step = -12;
    s.feed_step = 123456;
    s.underruns = 2;
    EXPECT_EQ(decode_status(encode_status(s)), s);
    EXPECT_EQ(decode_ack(encode_ack(s.ack)), s.ack);
    const auto nak = decode_nak(encode_nak(NakReason::out_of_order, s.ack));
    ASSERT_TRUE(nak);
    EXPECT_EQ(nak->first, NakReason::out_of_order);
    machine::ControllerConfig c;
    c.carriage_travel_steps = 99999;
    EXPECT_EQ(decode_config(encode_config(c)), c);
    HelloReply h{1, 1, 2, 3, 160, 80, 4};
    EXPECT_EQ(decode_hello_reply(encode_hello_reply(h)), h);
}

TEST(Messages, MalformedPayloadsAreErrors) {
    EXPECT_FALSE(decode_ack(std::vector<std::uint8_t>(5)));
    auto bad_state = encode_ack({});
    bad_state[3] = 99;
    EXPECT_FALSE(decode_ack(bad_state));
    auto cfg = encode_config({});
    std::fill(cfg.begin(), cfg.begin() + 4, 0);  // zero steps per metre
    EXPECT_FALSE(decode_config(cfg));
    EXPECT_FALSE(decode_hello_reply(std::vector<std::uint8_t>{1, 1, 0, 0, 10, 80, 4}));  // ring < payload
    EXPECT_EQ(fault_names(fault::paper_out | fault::hammer), "paper out, hammer fault");
}

TEST(Stream, OpsRoundTrip) {
    std::vector<Op> ops;
    Op o;
    o.code = OpCode::job_begin;
    o.id = 7;
    o.first_pass = 300;
    ops.push_back(o);
    o = {};
    o.code = OpCode::sheet_begin;
    o.id = 2;
    o.value = -400;
    ops.push_back(o);
    o = {};
    o.code = OpCode::pass_begin;
    o.id = 301;
    o.flags = pass_flag::back_side | pass_flag::no_feed;
    o.skip = 12;
    ops.push_back(o);
    o = {};
    o.code = OpCode::move;
    o.axis = Axis::feed;
    o.negative = true;
    o.continuation = true;
    o.segments = {{400U << 16, 20, -8 << 16}, {0xFFFFFFFFU, 65535, INT32_MIN}, {1U << 16, 1, INT32_MAX},
                  {(240U << 16) + 16384, 7, 3}, {70000, 1, 0}, {1U << 16, 2, -1}};
    ops.push_back(o);
    o = {};
    o.code = OpCode::strike;
    o.hammer = plan::Hammer::concave;
    o.wait_ticks = 7373;  // 8 ms of settle
    ops.push_back(o);
    o = {};
    o.code = OpCode::move;  // segments on coarse grids, as the planner makes them
    o.segments = {{0x07218000U, 3, -47906816}, {0x01790000U, 8, -2260992}, {0x002e3000U, 159, 0},
                  {0x01ad8000U, 2, 5963776}, {0x035b0000U, 1, 0}};
    ops.push_back(o);
    o = {};
    o.code = OpCode::seek;
    o.axis = Axis::carriage;
    o.value = 17000;
    ops.push_back(o);
    std::vector<std::uint8_t> b;
    for (const auto& op : ops) append_op(b, op);
    std::size_t pos = 0;
    for (const auto& op : ops) {
        auto d = decode_op(std::span(b).subspan(pos));
        ASSERT_TRUE(d) << d.error().to_string();
        EXPECT_EQ(d->first, op);
        pos += d->second;
    }
    EXPECT_EQ(pos, b.size());
}

TEST(Stream, RejectsMalformedOps) {
    EXPECT_FALSE(decode_op(std::vector<std::uint8_t>{0x99}));        // unknown code
    EXPECT_FALSE(decode_op(std::vector<std::uint8_t>{0x14, 0x00}));  // truncated pass
    EXPECT_FALSE(decode_op(std::vector<std::uint8_t>{0x20, 0x00}));  // move with no segments
    EXPECT_FALSE(decode_op(std::vector<std::uint8_t>{0x20, kMaxSegmentsPerOp + 1}));  // too many segments
    EXPECT_FALSE(decode_op(std::vector<std::uint8_t>{0x30}));  // strike without its settle
    // Count 1 on grid 2^15 with an interval of 2^17 grid units: beyond 32 bits.
    EXPECT_FALSE(decode_op(std::vector<std::uint8_t>{0x20, 1, 0x1F, 0x80, 0x80, 0x10, 0}));
    EXPECT_FALSE(decode_op(std::vector<std::uint8_t>{0x20, 1, 0x00, 0x02, 0}));  // count 0
    EXPECT_FALSE(decode_op(std::vector<std::uint8_t>{0x14, 0, 1, 0x80, 0}));  // unknown pass flag
}

TEST(Stream, CoarseGridSegmentsTakeFewBytes) {
    // The planner's 480-step move (6 mm, jerk-limited, half-interval tolerance):
    // 13 segments on grids of 2^8..2^15 Q16.16 units.
    Op o;
    o.code = OpCode::move;
    o.segments = {{0x07218000U, 3, -47906816}, {0x01790000U, 8, -2260992}, {0x00a88000U, 17, -327680},
                  {0x00648000U, 29, -81920},   {0x0043e000U, 47, -24576}, {0x00328c00U, 77, -5120},
                  {0x002e3000U, 159, 0},       {0x002ea000U, 62, 10240},  {0x003a1800U, 44, 38912},
                  {0x005c8000U, 22, 131072},   {0x00a00000U, 9, 983040},  {0x01ad8000U, 2, 5963776},
                  {0x035b0000U, 1, 0}};
    std::vector<std::uint8_t> b;
    append_op(b, o);
    auto d = decode_op(b);
    ASSERT_TRUE(d) << d.error().to_string();
    EXPECT_EQ(d->first, o);
    EXPECT_EQ(d->second, b.size());
    // Full-precision fields would take 12 bytes a segment; these take under 5.
    EXPECT_LE(b.size(), 2 + 5 * o.segments.size()) << b.size();
    // The same values off the grid (one low bit set) cost more: the grid is what saves.
    for (auto& seg : o.segments) seg.interval_q16 |= 1;
    std::vector<std::uint8_t> fine;
    append_op(fine, o);
    EXPECT_GT(fine.size(), b.size() + o.segments.size());
    EXPECT_EQ(decode_op(fine)->first, o);
}

TEST(Stream, LongMovesSplitIntoContinuationOpsThatFitAPayload) {
    auto plan = test::make_plan(1, 1, 1);
    auto& move = plan.sheets[0].passes[0].moves[0];
    // 40 full-precision segments: far more than one op's 64 bytes.
    move.segments.clear();
    std::uint32_t steps = 0;
    for (std::uint32_t i = 0; i < 40; ++i) {
        move.segments.push_back({(300U << 16) + 12345 * i + 1, static_cast<std::uint16_t>(3 + i), -7777});
        steps += 3 + i;
    }
    move.steps = static_cast<std::int32_t>(steps);
    plan.sheets[0].passes[0].strikes[0].carriage_step = move.steps;  // from 0
    auto s = encode_job(plan, 1, {});
    ASSERT_TRUE(s) << s.error().to_string();
    std::vector<motion::StepSegment> back;
    std::size_t pos = 0, ops = 0, begin = 0;
    for (const auto end : s->op_ends) {
        auto d = decode_op(std::span(s->bytes).subspan(begin, end - begin));
        ASSERT_TRUE(d);
        if (d->first.code == OpCode::move && d->first.axis == Axis::carriage) {
            EXPECT_LE(end - begin, kMaxMoveOpBytes);
            EXPECT_EQ(d->first.continuation, ops > 0);
            back.insert(back.end(), d->first.segments.begin(), d->first.segments.end());
            ++ops;
        }
        begin = end;
        pos = end;
    }
    EXPECT_EQ(pos, s->bytes.size());
    EXPECT_GE(ops, 3U);
    EXPECT_EQ(back, move.segments);
}

TEST(Stream, SegmentTimingIsTheControllersArithmetic) {
    // Whole-tick values: the closed form 20*400 - 8*20*19/2 + 100*240.
    const std::vector<motion::StepSegment> segs{{400U << 16, 20, -8 << 16}, {240U << 16, 100, 0}};
    EXPECT_EQ(segment_steps(segs), 120U);
    EXPECT_EQ(segment_ticks(segs), 20U * 400 - 8U * 190 + 24000);
    EXPECT_EQ(tick_of_step(segs, 1), 400U);
    EXPECT_EQ(tick_of_step(segs, 2), 400U + 392);
    EXPECT_EQ(tick_of_step(segs, 120), segment_ticks(segs));
    // A quarter-tick fraction: the carry makes every fourth interval one tick longer.
    const std::vector<motion::StepSegment> q{{(240U << 16) + (1U << 14), 8, 0}};
    EXPECT_EQ(segment_ticks(q), 8U * 240 + 2);
}

TEST(Stream, WholeOpsPerChunkWithinThePayload) {
    const auto plan = test::make_plan(2, 5, 20);
    const auto s = encode_job(plan, 1, {});
    ASSERT_TRUE(s) << s.error().to_string();
    const auto chunks = chunk_stream(*s, kMaxPayload);
    std::size_t covered = 0;
    for (const auto& [b, e] : chunks) {
        EXPECT_EQ(b, covered);
        EXPECT_LE(e - b, kMaxPayload);
        EXPECT_TRUE(std::find(s->op_ends.begin(), s->op_ends.end(), e) != s->op_ends.end());
        covered = e;
    }
    EXPECT_EQ(covered, s->bytes.size());
}

TEST(Stream, PlansTheControllerCannotRunAreRefusedWithTheirPlace) {
    auto plan = test::make_plan(1, 3, 5);
    plan.sheets[0].passes[1].moves[0].steps += 1;  // segments no longer add up
    auto s = encode_job(plan, 1, {});
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().where, "sheet 1 pass 2 strike 1");
    plan = test::make_plan(1, 3, 5);
    plan.sheets[0].passes[0].feed.segments[0].add_q16 = -1000 << 16;  // interval would go negative
    s = encode_job(plan, 1, {});
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().message.find("16-bit timer"), std::string::npos);
}

// The segment list of a move in a plan file is checked as the encoder reads it.
TEST(PlanJson, AMalformedSegmentNamesItsPath) {
    const auto plan = test::make_plan(2, 3, 6);
    auto j = plan::plan_to_json({plan, profile::default_profile(), kProtocolVersion});
    j["sheets"][0]["passes"][1]["strikes"][0]["move"]["segments"][0] = {1, 2};
    const auto bad = plan::plan_from_json(j);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().where, "plan.sheets[0].passes[1].strikes[0].move.segments[0]");
}

}  // namespace
}  // namespace tactus::encode
