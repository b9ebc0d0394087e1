// SPDX-License-Identifier: GPL-3.0-or-later
#include "encode/messages.hpp"
#include "common/try.hpp"
#include "encode/big_endian.hpp"

#include <algorithm>
#include <string>

namespace tactus::encode {
namespace {

Result<void> need(std::span<const std::uint8_t> p, std::size_t n, const char* what) {
    if (p.size() != n)
        return fail(ErrorKind::protocol, std::string(what) + " payload is " + std::to_string(p.size()) +
                        " bytes, expected " + std::to_string(n),
                    what);
    return {};
}

constexpr std::size_t kAckBytes = 8;
constexpr std::size_t kStatusBytes = kAckBytes + 1 + 2 + 2 + 2 + 4 + 4 + 2;

void put_ack(std::vector<std::uint8_t>& o, const AckInfo& a) {
    o.push_back(a.buffer_free);
    put16(o, a.executed_passes);
    o.push_back(static_cast<std::uint8_t>(a.state));
    o.push_back(a.faults);
    o.push_back(a.strikes_in_pass);
    put16(o, a.job_id);
}
Result<AckInfo> get_ack(std::span<const std::uint8_t> p) {
    AckInfo a;
    a.buffer_free = p[0];
    a.executed_passes = get16(p, 1);
    if (p[3] > static_cast<std::uint8_t>(ControllerState::homing))
        return fail(ErrorKind::protocol, "unknown controller state " + std::to_string(p[3]), "status.state");
    a.state = static_cast<ControllerState>(p[3]);
    a.faults = p[4];
    a.strikes_in_pass = p[5];
    a.job_id = get16(p, 6);
    return a;
}
}  // namespace

bool is_known_type(std::uint8_t t) {
    return (t >= 0x01 && t <= 0x08) || (t >= 0x81 && t <= 0x84);
}

const char* state_name(ControllerState s) {
    switch (s) {
        case ControllerState::idle: return "idle";
        case ControllerState::running: return "running";
        case ControllerState::waiting: return "waiting for data";
        case ControllerState::paused: return "paused";
        case ControllerState::fault: return "fault";
        case ControllerState::homing: return "homing";
    }
    return "?";
}

std::string fault_names(std::uint8_t f) {
    static constexpr std::pair<std::uint8_t, const char*> names[] = {
        {fault::paper_out, "paper out"},
        {fault::limit_switch, "limit switch"},
        {fault::hammer, "hammer fault"},
        {fault::power_on_reset, "power-on reset"},
        {fault::warm_reset, "watchdog reset"},
        {fault::host_timeout, "host keep-alive lost"},
        {fault::underrun, "buffer underrun"},
        {fault::stream_error, "malformed job stream"},
    };
    std::string out;
    for (const auto& [bit, name] : names) {
        if ((f & bit) == 0) continue;
        if (!out.empty()) out += ", ";
        out += name;
    }
    return out;
}

std::vector<std::uint8_t> encode_hello(const Hello& h) {
    std::vector<std::uint8_t> o;
    put16(o, h.nonce);
    o.push_back(h.protocol);
    return o;
}
Result<Hello> decode_hello(std::span<const std::uint8_t> p) {
    TACTUS_TRY_VOID(need(p, 3, "HELLO"));
    return Hello{get16(p, 0), p[2]};
}

std::vector<std::uint8_t> encode_hello_reply(const HelloReply& h) {
    std::vector<std::uint8_t> o{h.protocol,   h.firmware_major, h.firmware_minor, h.capabilities,
                                h.ring_bytes, h.max_payload,    h.window_frames};
    if (h.protocol == kProtocolV3) {
        put32(o, h.table_id);
        put16(o, 0);  // reserved
    }
    return o;
}
Result<HelloReply> decode_hello_reply(std::span<const std::uint8_t> p) {
    // The protocol byte comes first in every version: it says how long the rest is.
    const bool v3 = !p.empty() && p[0] == kProtocolV3;
    TACTUS_TRY_VOID(need(p, v3 ? 13 : 7, "HELLO_REPLY"));
    HelloReply h{p[0], p[1], p[2], p[3], p[4], p[5], p[6], v3 ? get32(p, 7) : 0U};
    if (h.max_payload == 0 || h.ring_bytes < h.max_payload || h.window_frames == 0 ||
        h.window_frames > 127)
        return fail(ErrorKind::protocol, "controller reports an impossible buffer (ring " +
                        std::to_string(h.ring_bytes) + ", payload " +
                        std::to_string(h.max_payload) + ")",
                    "HELLO_REPLY");
    return h;
}

std::vector<std::uint8_t> encode_config(const machine::ControllerConfig& c) {
    std::vector<std::uint8_t> o;
    put32(o, c.carriage_steps_per_m);
    put32(o, c.feed_steps_per_m);
    put32(o, static_cast<std::uint32_t>(c.carriage_travel_steps));
    put16(o, c.home_interval_ticks);
    put16(o, c.hammer_ticks);
    put16(o, c.keepalive_ms);
    return o;
}
std::vector<std::uint8_t> encode_config_v3(const machine::ControllerConfig& c, std::uint16_t settle_ticks) {
    std::vector<std::uint8_t> o;
    put16(o, static_cast<std::uint16_t>(std::clamp<std::int32_t>(c.carriage_travel_steps, 1, 0xFFFF)));
    // The firmware's step interrupt needs at least 64 cycles a homing step.
    put16(o, std::max<std::uint16_t>(c.home_interval_ticks, 64));
    put16(o, c.hammer_ticks);
    put16(o, settle_ticks);
    put16(o, c.keepalive_ms);
    return o;
}

Result<machine::ControllerConfig> decode_config(std::span<const std::uint8_t> p) {
    TACTUS_TRY_VOID(need(p, 18, "CONFIGURE"));
    machine::ControllerConfig c;
    c.carriage_steps_per_m = get32(p, 0);
    c.feed_steps_per_m = get32(p, 4);
    c.carriage_travel_steps = static_cast<std::int32_t>(get32(p, 8));
    c.home_interval_ticks = get16(p, 12);
    c.hammer_ticks = get16(p, 14);
    c.keepalive_ms = get16(p, 16);
    if (c.carriage_steps_per_m == 0 || c.feed_steps_per_m == 0)
        return fail(ErrorKind::protocol, "steps per metre must be positive", "CONFIGURE.steps_per_m");
    if (c.carriage_travel_steps <= 0)
        return fail(ErrorKind::protocol, "carriage travel must be positive", "CONFIGURE.travel");
    if (c.home_interval_ticks == 0) return fail(ErrorKind::protocol, "homing rate must be positive", "CONFIGURE.home");
    return c;
}

std::vector<std::uint8_t> encode_ack(const AckInfo& a) {
    std::vector<std::uint8_t> o;
    put_ack(o, a);
    return o;
}
Result<AckInfo> decode_ack(std::span<const std::uint8_t> p) {
    TACTUS_TRY_VOID(need(p, kAckBytes, "ACK"));
    return get_ack(p);
}

std::vector<std::uint8_t> encode_nak(NakReason why, const AckInfo& a) {
    std::vector<std::uint8_t> o{static_cast<std::uint8_t>(why)};
    put_ack(o, a);
    return o;
}
Result<std::pair<NakReason, AckInfo>> decode_nak(std::span<const std::uint8_t> p) {
    TACTUS_TRY_VOID(need(p, kAckBytes + 1, "NAK"));
    if (p[0] < 1 || p[0] > 5) return fail(ErrorKind::protocol, "unknown NAK reason " + std::to_string(p[0]), "NAK");
    TACTUS_TRY(a, get_ack(p.subspan(1)));
    return std::pair{static_cast<NakReason>(p[0]), a};
}

std::vector<std::uint8_t> encode_status(const Status& s) {
    std::vector<std::uint8_t> o;
    put_ack(o, s.ack);
    o.push_back(s.flags);
    put16(o, s.job_id);
    put16(o, s.sheet);
    put16(o, s.pass_index);
    put32(o, static_cast<std::uint32_t>(s.carriage_step));
    put32(o, static_cast<std::uint32_t>(s.feed_step));
    put16(o, s.underruns);
    return o;
}
Result<Status> decode_status(std::span<const std::uint8_t> p) {
    TACTUS_TRY_VOID(need(p, kStatusBytes, "STATUS_REPLY"));
    Status s;
    TACTUS_TRY(a, get_ack(p));
    s.ack = a;
    std::size_t at = kAckBytes;
    s.flags = p[at++];
    s.job_id = get16(p, at);
    s.sheet = get16(p, at + 2);
    s.pass_index = get16(p, at + 4);
    s.carriage_step = static_cast<std::int32_t>(get32(p, at + 6));
    s.feed_step = static_cast<std::int32_t>(get32(p, at + 10));
    s.underruns = get16(p, at + 14);
    return s;
}

}  // namespace tactus::encode
