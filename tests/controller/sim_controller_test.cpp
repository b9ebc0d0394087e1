// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated 89C52 driven frame by frame: sessions, sequence numbers,
// duplicates, the RAM budget, and execution in simulated time.
#include <gtest/gtest.h>

#include "controller/sim_controller.hpp"
#include "encode/frame.hpp"
#include "encode/stream.hpp"
#include "../common/test_plans.hpp"

namespace tactus::controller {
namespace {

using encode::FrameType;

struct Driver {
    SimController ctl;
    encode::FrameDecoder dec;
    double t = 0;
    std::vector<encode::Frame> send(std::uint8_t seq, FrameType type, std::vector<std::uint8_t> payload = {}) {
        ctl.receive(encode::encode_frame(seq, type, payload), t);
        std::vector<encode::Frame> out;
        dec.push(ctl.take_output(), out);
        return out;
    }
    encode::AckInfo last_ack(const std::vector<encode::Frame>& f) {
        const auto& last = f.back();
        if (last.type == 0x83) return encode::decode_nak(last.payload)->second;
        return *encode::decode_ack(last.payload);
    }
};

TEST(Controller, RefusesEverythingBeforeHello) {
    Driver d;
    auto r = d.send(0, FrameType::status);
    ASSERT_EQ(r.size(), 1U);
    EXPECT_EQ(r[0].type, 0x83);
    EXPECT_EQ(encode::decode_nak(r[0].payload)->first, encode::NakReason::no_session);
    EXPECT_EQ(d.last_ack(r).faults & encode::fault::power_on_reset, encode::fault::power_on_reset);
}

TEST(Controller, HelloAdvertisesTheRamBudget) {
    Driver d;
    auto r = d.send(40, FrameType::hello, encode::encode_hello({77, encode::kProtocolVersion}));
    ASSERT_EQ(r.size(), 1U);
    EXPECT_EQ(r[0].seq, 41);  // next expected
    const auto h = encode::decode_hello_reply(r[0].payload);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->ring_bytes, machine::ram::kRingBytes);
    EXPECT_EQ(h->max_payload, encode::kMaxPayload);
}

TEST(Controller, StaleDuplicateHelloDoesNotRewindTheSequence) {
    Driver d;
    d.send(0, FrameType::hello, encode::encode_hello({5, encode::kProtocolVersion}));
    d.send(1, FrameType::keepalive);
    d.send(2, FrameType::keepalive);
    auto r = d.send(0, FrameType::hello, encode::encode_hello({5, encode::kProtocolVersion}));  // the same session's HELLO again
    EXPECT_EQ(r.back().seq, 3);
}

machine::ControllerConfig no_keepalive() {
    machine::ControllerConfig c;
    c.keepalive_ms = 0;  // these tests let simulated time jump
    return c;
}

TEST(Controller, DuplicatesAreAcknowledgedButNeverExecuted) {
    Driver d;
    d.send(0, FrameType::hello, encode::encode_hello({1, encode::kProtocolVersion}));
    d.send(1, FrameType::configure, encode::encode_config(no_keepalive()));
    const auto plan = test::make_plan(1, 1, 3);
    auto stream = encode::encode_job(plan, 9, {});
    ASSERT_TRUE(stream);
    const auto chunks = encode::chunk_stream(*stream, encode::kMaxPayload);
    std::uint8_t seq = 2;
    for (const auto& [b, e] : chunks) {
        const std::vector<std::uint8_t> p(stream->bytes.begin() + static_cast<std::ptrdiff_t>(b),
                                          stream->bytes.begin() + static_cast<std::ptrdiff_t>(e));
        auto r = d.send(seq, FrameType::data, p);
        EXPECT_EQ(r.back().type, 0x82);
        // The same frame again, as after a lost ACK: acknowledged, not buffered.
        auto again = d.send(seq, FrameType::data, p);
        EXPECT_EQ(again.back().type, 0x82);
        EXPECT_EQ(again.back().seq, static_cast<std::uint8_t>(seq + 1));
        ++seq;
        d.t += 10;
        d.ctl.advance(d.t);
    }
    EXPECT_EQ(d.ctl.duplicates(), chunks.size());
    EXPECT_EQ(d.ctl.strike_log(), planned_strikes(plan));
}

TEST(Controller, OutOfOrderFrameIsNakedWithTheExpectedSequence) {
    Driver d;
    d.send(0, FrameType::hello, encode::encode_hello({1, encode::kProtocolVersion}));
    auto r = d.send(3, FrameType::keepalive);
    ASSERT_EQ(r.back().type, 0x83);
    EXPECT_EQ(r.back().seq, 1);
    EXPECT_EQ(encode::decode_nak(r.back().payload)->first, encode::NakReason::out_of_order);
}

TEST(Controller, UnknownTypesAndBadPayloadsAreRefused) {
    Driver d;
    d.send(0, FrameType::hello, encode::encode_hello({1, encode::kProtocolVersion}));
    auto r = d.send(1, static_cast<FrameType>(0x3C));
    EXPECT_EQ(encode::decode_nak(r.back().payload)->first, encode::NakReason::unknown_type);
    r = d.send(1, FrameType::data, {0x99, 0x00});  // not an op
    EXPECT_EQ(encode::decode_nak(r.back().payload)->first, encode::NakReason::bad_payload);
    r = d.send(1, FrameType::configure, {1, 2, 3});
    EXPECT_EQ(encode::decode_nak(r.back().payload)->first, encode::NakReason::bad_payload);
    EXPECT_EQ(d.ctl.frames_accepted(), 0U);
}

TEST(Controller, NeverBuffersMoreThanTheRamAllows) {
    Driver d;
    d.send(0, FrameType::hello, encode::encode_hello({1, encode::kProtocolVersion}));
    // A job held by paper-out at its first sheet fills up: strikes are one-byte ops.
    d.ctl.inject_paper_out_at_sheet(1);
    std::vector<std::uint8_t> start;
    encode::Op op;
    op.code = encode::OpCode::job_begin;
    encode::append_op(start, op);
    op.code = encode::OpCode::sheet_begin;
    op.id = 1;
    encode::append_op(start, op);
    d.send(1, FrameType::data, start);
    EXPECT_EQ(d.ctl.status().ack.faults, encode::fault::paper_out);
    const std::vector<std::uint8_t> strikes(encode::kMaxPayload, 0x30);
    std::uint8_t seq = 2;
    std::size_t accepted = 0;
    for (int i = 0; i < 4; ++i) {
        d.ctl.receive(encode::encode_frame(seq, FrameType::data, strikes), d.t);
        std::vector<encode::Frame> out;
        d.dec.push(d.ctl.take_output(), out);
        if (out.back().type == 0x82) {
            ++accepted;
            ++seq;
        } else {
            EXPECT_EQ(encode::decode_nak(out.back().payload)->first, encode::NakReason::no_space);
        }
    }
    EXPECT_EQ(accepted, (machine::ram::kRingBytes - start.size()) / encode::kMaxPayload);
    EXPECT_LE(d.ctl.max_ring_used(), machine::ram::kRingBytes);
}

TEST(Controller, ExecutesInSimulatedTimeFromTheStepSchedule) {
    Driver d;
    d.send(0, FrameType::hello, encode::encode_hello({1, encode::kProtocolVersion}));
    d.send(1, FrameType::configure, encode::encode_config(no_keepalive()));
    const auto plan = test::make_plan(1, 1, 1);
    auto stream = encode::encode_job(plan, 9, {});
    ASSERT_TRUE(stream);
    std::uint8_t seq = 2;
    for (const auto& [b, e] : encode::chunk_stream(*stream, encode::kMaxPayload))
        d.send(seq++, FrameType::data,
               {stream->bytes.begin() + static_cast<std::ptrdiff_t>(b),
                stream->bytes.begin() + static_cast<std::ptrdiff_t>(e)});
    d.ctl.advance(100);
    ASSERT_EQ(d.ctl.strike_log().size(), 1U);
    const auto& pass = plan.sheets[0].passes[0];
    // Load, home (already at 0), feed, carriage move: then the hammer fires.
    const double expected = 0.8 + pass.feed.duration_s + pass.moves[0].duration_s;
    EXPECT_NEAR(d.ctl.strike_log()[0].time_s, expected, 1e-9);
    EXPECT_NEAR(d.ctl.strike_log()[0].x_mm, pass.strikes[0].carriage_step / 80.0, 1e-12);
    EXPECT_EQ(d.ctl.status().ack.executed_passes, 1);
    EXPECT_EQ(d.ctl.status().ack.state, encode::ControllerState::idle);
}


// Ops by hand: a pass with one carriage move of 300 steps (cruise at 300 ticks a
// step) in two parts, and a strike that waits `settle` ticks at rest.
std::vector<std::uint8_t> ops_of(std::initializer_list<encode::Op> ops) {
    std::vector<std::uint8_t> b;
    for (const auto& o : ops) encode::append_op(b, o);
    return b;
}
encode::Op simple(encode::OpCode c, std::uint16_t id = 0) {
    encode::Op o;
    o.code = c;
    o.id = id;
    return o;
}
encode::Op move_part(bool continuation) {
    encode::Op o;
    o.code = encode::OpCode::move;
    o.continuation = continuation;
    o.segments = {{300U << 16, 150, 0}};
    return o;
}

TEST(Controller, StartsAMoveOnlyWhenAllOfItIsBuffered) {
    Driver d;
    d.send(0, FrameType::hello, encode::encode_hello({1, encode::kProtocolVersion}));
    d.send(1, FrameType::configure, encode::encode_config(no_keepalive()));
    encode::Op strike;
    strike.code = encode::OpCode::strike;
    strike.wait_ticks = 9216;  // 10 ms
    d.send(2, FrameType::data,
           ops_of({simple(encode::OpCode::job_begin, 5), simple(encode::OpCode::home),
                   simple(encode::OpCode::sheet_begin, 1), simple(encode::OpCode::pass_begin, 0), move_part(false)}));
    d.t = 5;
    d.ctl.advance(d.t);
    // Half a move in the ring: the carriage stays at rest, waiting for the rest.
    EXPECT_EQ(d.ctl.status().carriage_step, 0);
    EXPECT_EQ(d.ctl.status().ack.state, encode::ControllerState::waiting);
    d.send(3, FrameType::data,
           ops_of({move_part(true), strike, simple(encode::OpCode::pass_end), simple(encode::OpCode::sheet_end),
                   simple(encode::OpCode::job_end)}));
    d.ctl.advance(d.t + 10);
    ASSERT_EQ(d.ctl.strike_log().size(), 1U);
    EXPECT_EQ(d.ctl.strike_log()[0].carriage_step, 300);
    EXPECT_EQ(d.ctl.status().underruns, 0U);
    // Both parts back to back from t = 5 s, then the settle, then the hammer.
    const double move_s = 300 * 300 / machine::kTickHz;
    EXPECT_NEAR(d.ctl.strike_log()[0].time_s, 5 + move_s + 9216 / machine::kTickHz, 1e-9);
    EXPECT_EQ(d.ctl.status().ack.executed_passes, 1);
}

TEST(Controller, SettleComesFromThePlan) {
    // The planner's moves carry the rest before the strike; the controller waits it out.
    auto plan = test::make_plan(1, 1, 1);
    plan.sheets[0].passes[0].moves[0].settle_ticks = 7373;
    auto stream = encode::encode_job(plan, 9, {});
    ASSERT_TRUE(stream);
    std::size_t pos = 0;
    bool seen = false;
    while (pos < stream->bytes.size()) {
        const auto op = encode::decode_op(std::span(stream->bytes).subspan(pos));
        ASSERT_TRUE(op);
        if (op->first.code == encode::OpCode::strike) {
            EXPECT_EQ(op->first.wait_ticks, 7373U);
            seen = true;
        }
        pos += op->second;
    }
    EXPECT_TRUE(seen);
}

}  // namespace
}  // namespace tactus::controller
