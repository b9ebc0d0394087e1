// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private to core/link: the session, the go-back-N send queue and what the
// controller last reported. link_session.cpp has the session's bodies,
// link.cpp the request/reply calls, job_sender.cpp the job streaming.
#include <algorithm>
#include <cmath>
#include <array>
#include <cstdio>
#include <deque>
#include <optional>
#include <random>

#include "encode/frame.hpp"
#include "encode/stream.hpp"
#include "encode/stream_v3.hpp"
#include "link/link.hpp"
#include "transport/byte_stream.hpp"

namespace tactus::link {

using encode::AckInfo;
using encode::Frame;
using encode::FrameType;
namespace fault = encode::fault;
using std::chrono::microseconds;

inline double seconds(std::chrono::milliseconds ms) { return static_cast<double>(ms.count()) / 1000.0; }
inline constexpr std::uint8_t kRestartFaults =
    fault::limit_switch | fault::warm_reset | fault::stream_error | fault::underrun;

struct Link::Impl {
    std::unique_ptr<transport::ByteStream> s;
    LinkOptions opt;
    std::string device;
    encode::FrameDecoder decoder;
    LinkStats stats;
    std::atomic<bool> pause_req{false}, resume_req{false};

    // session
    bool session = false;
    std::uint16_t nonce = 0;
    std::uint8_t next_seq = 0;
    HelloReply info;
    std::optional<machine::ControllerConfig> config;
    // v3: the tables the plan was made with, matched against HELLO_REPLY.
    std::optional<machine::FirmwareTables> tables;
    machine::StrikeTiming timing;
    std::mt19937 rng{std::random_device{}()};

    // what the controller last told us
    AckInfo ack;
    std::optional<Status> last_status;
    std::optional<HelloReply> last_hello;
    bool session_lost = false;   // NAK no_session: the controller rebooted
    bool saw_power_loss = false;
    std::optional<Error> refused;  // bad_payload / unknown_type: a protocol mismatch
    double last_rx = 0;
    // When a frame last arrived that failed its CRC: the controller is there
    // (a noisy line garbles its answers), so the silence timeout does not
    // apply; the give-up still bounds the wait (at 2e-2 per byte, a silence
    // timeout would fail sessions after 3 s of garbled answers).
    double last_garbled = -1e300;
    double last_tx = 0;
    // When the controller last took a frame of ours (or executed a pass: the
    // job's own bookkeeping), for the bounded give-up.
    double last_progress = 0;

    // go-back-N send queue
    struct Outgoing {
        std::uint8_t seq;
        FrameType type;
        std::vector<std::uint8_t> payload;
        double sent_at;
    };
    std::deque<Outgoing> unacked;
    double last_goback = -1;
    // DATA frames acknowledged, and retransmission timeouts, since the session
    // opened: the job's frame size follows them (job_sender.cpp).
    std::size_t data_acked = 0;
    std::size_t session_timeouts = 0;

    Error device_error(const Error& e) const {
        return Error{e.message, device, e.kind};
    }

    std::size_t window_frames() const;

    double rto() const;

    // When the controller was last heard from: a valid frame, or one a noisy
    // line garbled. The silence timeout counts from here.
    [[nodiscard]] double last_heard() const { return std::max(last_rx, last_garbled); }
    // How long the controller may stay silent before it counts as gone (the
    // controller says nothing to a frame it cannot read, so on a noisy line
    // silence proves little):
    // * the silence timeout;
    // * for a request (HELLO, CONFIGURE, ...) at least kSilentRetries
    //   retransmission timeouts: at 9600 baud 3 s is 7 tries, and at 2e-2 per
    //   byte a 24-byte CONFIGURE is lost on its way 7 times running in about
    //   1 session of 6;
    // * the give-up, once the line has garbled a frame within the give-up.
    static constexpr double kSilentRetries = 12;
    [[nodiscard]] double quiet_allowed(bool request) const;
    [[nodiscard]] bool silent_too_long(double since, bool request = false) const;
    // "3.0 s": how long the controller was given (an error message's).
    [[nodiscard]] std::string quiet_text(bool request = true) const;

    Result<void> raw_write(const std::vector<std::uint8_t>& bytes);
    Result<void> transmit(const Outgoing& o);
    Result<void> send(FrameType type, std::vector<std::uint8_t> payload);
    Result<void> resend_all();

    [[nodiscard]] bool v3() const { return session && info.protocol == encode::kProtocolV3; }
    // The ring bytes a DATA frame takes: v3's check is not stored.
    std::size_t ops_bytes(const Outgoing& o) const {
        return v3() && o.payload.size() >= 2 ? o.payload.size() - 2 : o.payload.size();
    }

    Result<std::vector<std::uint8_t>> config_payload() const;

    static std::string table_hex(std::uint32_t id);
    Result<void> use_firmware_tables(const machine::FirmwareTables& t, const machine::StrikeTiming& st);

    std::size_t data_in_flight() const;
    std::size_t credit() const;

    // Every controller frame carries the next sequence number it expects:
    // everything before it has been accepted.
    void acknowledge_through(std::uint8_t expected);
    Result<void> handle(const Frame& f);

    // Reads whatever arrives within `timeout` and handles each frame.
    Result<void> pump(double timeout_s);

    // Sends one frame and waits until the controller has accepted it.
    Result<void> transact(FrameType type, std::vector<std::uint8_t> payload);

    // Opens a session offering `version`. nullopt: the controller refused
    // that version (NAK bad payload to HELLO), so another may be tried.
    Result<std::optional<HelloReply>> hello_as(std::uint8_t version);
    Result<HelloReply> hello();
    Result<Status> status();

    // The device went away: reopen it until the deadline.
    Result<void> reconnect_device();

    Result<JobOutcome> send_job(const plan::JobPlan& plan, std::size_t start_sheet,
                                const ProgressFn& progress, const CancelToken& cancel,
                                std::uint16_t job_id);
};

}  // namespace tactus::link
