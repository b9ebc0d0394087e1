// SPDX-License-Identifier: GPL-3.0-or-later
// The link's session layer: opening a session (HELLO, version fallback), the
// go-back-N send queue and its retransmission timeout, reading and handling
// the controller's frames, and waiting for it to take a request.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "link/link_impl.hpp"
#include "common/try.hpp"

namespace tactus::link {

std::size_t Link::Impl::window_frames() const {
    std::size_t w = session ? std::max<std::size_t>(1, info.window_frames) : 1;
    if (opt.max_window_frames > 0) w = std::min(w, opt.max_window_frames);
    return w;
}

double Link::Impl::rto() const {
    double inflight = 0;
    for (const auto& o : unacked) inflight += static_cast<double>(o.payload.size() + encode::kFrameOverhead);
    const double bps = s->bytes_per_second();
    const double line = bps > 0 ? (inflight + 2 * encode::kMaxFrame) / bps : 0;
    return seconds(opt.retransmit_timeout) + line;
}

double Link::Impl::quiet_allowed(bool request) const {
    const bool noisy = s->now() - last_garbled < seconds(opt.give_up_after);
    double quiet = seconds(opt.silence_timeout);
    if (request) quiet = std::max(quiet, kSilentRetries * rto());
    if (noisy) quiet = std::max(quiet, seconds(opt.give_up_after));
    return quiet;
}

bool Link::Impl::silent_too_long(double since, bool request) const {
    return s->now() - std::max(since, last_heard()) > quiet_allowed(request);
}

std::string Link::Impl::quiet_text(bool request) const {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f s", quiet_allowed(request));
    return b;
}

Result<void> Link::Impl::raw_write(const std::vector<std::uint8_t>& bytes) {
    auto r = s->write(bytes);
    if (!r) return std::unexpected(device_error(r.error()));
    stats.bytes_written += bytes.size();
    last_tx = s->now();
    return {};
}

Result<void> Link::Impl::transmit(const Outgoing& o) {
    ++stats.frames_sent;
    return raw_write(encode::encode_frame(o.seq, o.type, o.payload));
}

Result<void> Link::Impl::send(FrameType type, std::vector<std::uint8_t> payload) {
    Outgoing o{next_seq++, type, std::move(payload), s->now()};
    unacked.push_back(o);
    return transmit(unacked.back());
}

Result<void> Link::Impl::resend_all() {
    for (auto& o : unacked) {
        o.sent_at = s->now();
        ++stats.frames_resent;
        if (auto r = transmit(o); !r) return r;
    }
    last_goback = s->now();
    return {};
}

Result<std::vector<std::uint8_t>> Link::Impl::config_payload() const {
    if (!config) return fail(ErrorKind::internal, "no configuration", device);
    if (!v3()) return encode::encode_config(*config);
    if (!tables)
        return fail(ErrorKind::usage,
                    "the controller speaks protocol 3 (the reference firmware, ramp table " + table_hex(info.table_id) +
                        "): give the firmware's tables (its build/ramp.json) to plan with",
                    device);
    return encode::encode_config_v3(*config, timing.settle_ticks);
}

std::string Link::Impl::table_hex(std::uint32_t id) {
    char b[9];
    std::snprintf(b, sizeof b, "%08x", id);
    return b;
}

Result<void> Link::Impl::use_firmware_tables(const machine::FirmwareTables& t, const machine::StrikeTiming& st) {
    if (!session) return fail(ErrorKind::internal, "no session: call hello() first", device);
    if (!v3())
        return fail(ErrorKind::device, "the controller speaks protocol " + std::to_string(info.protocol) +
                        ", not the reference firmware's 3: it takes no firmware tables",
                    device);
    if (t.table_id != info.table_id)
        return fail(ErrorKind::device,
                    "the firmware was built for ramp table " + table_hex(info.table_id) + ", the plan's tables are " +
                        table_hex(t.table_id) +
                        ": rebuild the firmware with this profile (make -C firmware PROFILE=...) or plan with "
                        "the tables it was built with (its build/ramp.json)",
                    device);
    tables = t;
    timing = st;
    return {};
}

std::size_t Link::Impl::data_in_flight() const {
    std::size_t n = 0;
    for (const auto& o : unacked)
        if (o.type == FrameType::data) n += ops_bytes(o);
    return n;
}

std::size_t Link::Impl::credit() const {
    const std::size_t inflight = data_in_flight();
    return ack.buffer_free > inflight ? ack.buffer_free - inflight : 0;
}

void Link::Impl::acknowledge_through(std::uint8_t expected) {
    while (!unacked.empty()) {
        // Only a HELLO_REPLY answers a HELLO: a stale ACK left on the line
        // by an earlier session (a host killed mid-job) must not pop it.
        if (unacked.front().type == FrameType::hello) break;
        const auto d = static_cast<std::uint8_t>(expected - unacked.front().seq);
        if (d == 0 || d > 128) break;
        if (unacked.front().type == FrameType::data) {
            stats.payload_bytes += unacked.front().payload.size();
            ++data_acked;
        }
        unacked.pop_front();
        last_progress = s->now();
    }
}

Result<void> Link::Impl::handle(const Frame& f) {
    last_rx = s->now();
    const auto type = static_cast<FrameType>(f.type);
    switch (type) {
        case FrameType::hello_reply: {
            TACTUS_TRY(h, encode::decode_hello_reply(f.payload));
            last_hello = h;
            if (!unacked.empty() && unacked.front().type == FrameType::hello &&
                f.seq == static_cast<std::uint8_t>(unacked.front().seq + 1))
                unacked.pop_front();
            return {};
        }
        case FrameType::ack: {
            TACTUS_TRY(a, encode::decode_ack(f.payload));
            ack = a;
            break;
        }
        case FrameType::status_reply: {
            TACTUS_TRY(st, encode::decode_status(f.payload));
            last_status = st;
            ack = st.ack;
            break;
        }
        case FrameType::nak: {
            TACTUS_TRY(n, encode::decode_nak(f.payload));
            ack = n.second;
            ++stats.naks;
            switch (n.first) {
                case encode::NakReason::no_session: session_lost = true; break;
                case encode::NakReason::bad_payload:
                case encode::NakReason::unknown_type:
                    refused = Error{"the controller refused a frame (" +
                                        std::string(n.first == encode::NakReason::bad_payload
                                                        ? "malformed payload"
                                                        : "unknown type") +
                                        "): firmware and host disagree on the protocol",
                                    device, ErrorKind::protocol};
                    break;
                case encode::NakReason::out_of_order:
                case encode::NakReason::no_space: break;
            }
            // A refused frame is not lost: sending it again cannot help
            // (and a re-sent HELLO of a refused version would be refused
            // again after the next version was offered).
            const bool refusal = n.first == encode::NakReason::bad_payload ||
                                 n.first == encode::NakReason::unknown_type;
            if (n.first != encode::NakReason::no_session && !refusal) {
                acknowledge_through(f.seq);
                // Go back to the first frame it lacks, at most once per round trip.
                if (!unacked.empty() && s->now() - last_goback > rto() / 2) {
                    if (auto r = resend_all(); !r) return r;
                }
            }
            if (ack.faults & fault::power_on_reset) saw_power_loss = true;
            return {};
        }
        default: return {};  // a host-side type echoed by line noise: ignore
    }
    if (ack.faults & fault::power_on_reset) saw_power_loss = true;
    acknowledge_through(f.seq);
    return {};
}

Result<void> Link::Impl::pump(double timeout_s) {
    std::array<std::uint8_t, 512> buf{};
    // Rounded up and at least 1 us, so a wait always moves the clock forward.
    auto n = s->read(buf, microseconds(std::max<std::int64_t>(
                              1, static_cast<std::int64_t>(std::ceil(timeout_s * 1e6)))));
    if (!n) return std::unexpected(device_error(n.error()));
    std::vector<Frame> frames;
    if (*n == 0 && timeout_s >= 0.05) decoder.idle(frames);  // quiet line: drop false starts
    decoder.push(std::span(buf).first(*n), frames);
    if (decoder.stats().crc_errors > stats.crc_errors) last_garbled = s->now();
    stats.crc_errors = decoder.stats().crc_errors;
    for (const auto& f : frames)
        if (auto r = handle(f); !r) return r;
    return {};
}

Result<void> Link::Impl::transact(FrameType type, std::vector<std::uint8_t> payload) {
    if (!session) return fail(ErrorKind::internal, "no session: call hello() first", device);
    if (auto r = send(type, std::move(payload)); !r) return r;
    const double start = s->now();
    while (!unacked.empty()) {
        if (refused) return std::unexpected(*std::exchange(refused, std::nullopt));
        if (session_lost) return fail(ErrorKind::device, "the controller restarted; open a new session", device);
        // Silent for the silence timeout: no answer. A controller that
        // answers (a noisy line loses most frames) is given until the
        // give-up to take this one.
        if (silent_too_long(start, true))
            return fail(ErrorKind::device, "no answer from the controller within " + quiet_text(), device);
        if (s->now() - start > seconds(opt.give_up_after))
            return fail(ErrorKind::device, "the controller answers but took no frame in " +
                            std::to_string(opt.give_up_after.count() / 1000) +
                            " s: is the line very noisy, or the baud rate wrong?",
                        device);
        const double due = unacked.front().sent_at + rto();
        if (s->now() >= due) {
            ++stats.timeouts;
            ++session_timeouts;
            if (auto r = resend_all(); !r) return r;
            continue;
        }
        if (auto r = pump(due - s->now()); !r) return r;
    }
    return {};
}

Result<std::optional<HelloReply>> Link::Impl::hello_as(std::uint8_t version) {
    nonce = static_cast<std::uint16_t>(rng() & 0xFFFF);
    if (nonce == 0) nonce = 1;
    session_timeouts = 0;
    unacked.clear();
    session = false;
    session_lost = false;
    refused.reset();
    last_hello.reset();
    decoder.reset();
    // A controller before its first session reports its power-on reset in
    // the NAK that refuses an unknown version; the session that follows
    // clears it. That is not a power loss during the job.
    const bool power_loss_before = saw_power_loss;
    const std::uint8_t seq = next_seq++;
    const auto payload = encode::encode_hello({nonce, version});
    unacked.push_back({seq, FrameType::hello, payload, s->now()});
    const double start = s->now();
    const std::size_t garbled_before = decoder.stats().crc_errors;
    TACTUS_TRY_VOID(transmit(unacked.back()));
    while (!last_hello) {
        // As transact: silent for the silence timeout, or no session by
        // the give-up (the controller answers, but the line garbles it).
        if (silent_too_long(start, true))
            return fail(ErrorKind::device, "no answer to HELLO within " + quiet_text() +
                            ": is the embosser on, the cable in, and the baud rate right?",
                        device);
        if (s->now() - start > seconds(opt.give_up_after))
            return fail(ErrorKind::device, "no valid answer to HELLO in " +
                            std::to_string(opt.give_up_after.count() / 1000) + " s, " +
                            std::to_string(decoder.stats().crc_errors - garbled_before) +
                            " frames arrived corrupted: is the line very noisy, or the baud rate wrong?",
                        device);
        if (s->now() >= unacked.front().sent_at + rto()) {
            ++stats.timeouts;
            ++session_timeouts;
            unacked.front().sent_at = s->now();
            ++stats.frames_resent;
            TACTUS_TRY_VOID(transmit(unacked.front()));
        }
        if (auto r = pump(unacked.front().sent_at + rto() - s->now()); !r)
            return std::unexpected(r.error());
        if (refused) {
            refused.reset();
            saw_power_loss = power_loss_before;
            return std::optional<HelloReply>{};
        }
    }
    if (last_hello->protocol != version)
        return fail(ErrorKind::protocol, "controller speaks protocol version " +
                        std::to_string(last_hello->protocol) + ", this host offered " +
                        std::to_string(version),
                    device);
    info = *last_hello;
    unacked.clear();
    session = true;
    last_rx = s->now();
    last_progress = s->now();
    return std::optional<HelloReply>{info};
}

Result<HelloReply> Link::Impl::hello() {
    // The version of the last session first, so a reconnect or restart
    // does not ask the firmware for v2 each time.
    std::vector<std::uint8_t> versions;
    if (opt.protocol != 0)
        versions = {opt.protocol};
    else if (info.protocol == encode::kProtocolV3)
        versions = {encode::kProtocolV3, encode::kProtocolVersion};
    else
        versions = {encode::kProtocolVersion, encode::kProtocolV3};
    // A controller reports its power-on reset until a session opens:
    // in the NAK refusing a version, and in the stale copies of it that
    // arrive after. That is its state before this session, not a power
    // loss during the job (which is seen before a restart's HELLO).
    const bool power_loss_before = saw_power_loss;
    // Every version twice: a refusal that came late (a copy held in the
    // firmware's decoder behind a false start) can still meet the next
    // offer; a controller that speaks neither refuses both again.
    for (int round = 0; round < 2; ++round)
        for (const auto v : versions) {
            auto h = hello_as(v);
            if (!h) return std::unexpected(h.error());
            if (*h) {
                saw_power_loss = power_loss_before;
                return **h;
            }
            // Refused: the answers to copies of that HELLO (re-sent, or
            // duplicated by the line) may still be on their way, and one
            // taken as refusing the next version failed the session (1
            // run in 1,500 at 2e-2). Let them arrive first; they are ignored.
            const double until = s->now() + rto();
            while (s->now() < until)
                TACTUS_TRY_VOID(pump(until - s->now()));
        }
    std::string offered;
    for (const auto v : versions) offered += (offered.empty() ? "" : " and ") + std::to_string(v);
    return fail(ErrorKind::protocol,
                "the controller refused HELLO for protocol " + offered + ": firmware and host disagree on the protocol",
                device);
}

Result<Status> Link::Impl::status() {
    last_status.reset();
    for (int attempt = 0; attempt < 3; ++attempt) {
        TACTUS_TRY_VOID(transact(FrameType::status, {}));
        // The reply may have been lost while a later ACK got through; wait a little.
        const double until = s->now() + rto();
        while (!last_status && s->now() < until)
            TACTUS_TRY_VOID(pump(until - s->now()));
        if (last_status) return *last_status;
    }
    return fail(ErrorKind::device, "no status reply from the controller", device);
}

Result<void> Link::Impl::reconnect_device() {
    const double start = s->now();
    auto backoff = std::chrono::milliseconds(100);
    for (;;) {
        auto r = s->reopen();
        if (r) {
            decoder.reset();
            ++stats.reconnects;
            last_rx = s->now();
            return {};
        }
        if (s->now() - start > seconds(opt.reconnect_deadline))
            return fail(ErrorKind::device, "device gone and not back within " +
                            std::to_string(opt.reconnect_deadline.count()) +
                            " ms: " + r.error().message,
                        device);
        s->sleep(backoff);
        backoff = std::min(backoff * 2, std::chrono::milliseconds(2000));
    }
}

}  // namespace tactus::link
