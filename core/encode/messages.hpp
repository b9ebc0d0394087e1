// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The messages of the Tactus link protocol (docs/protocol.md): frame types, the
// payloads of the immediate messages, and the status the controller reports.
// Everything here is sized for the 89C52: fixed little layouts, no field wider
// than the firmware keeps in RAM.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "machine/controller_config.hpp"
#include "machine/reference_firmware.hpp"

namespace tactus::encode {

// Protocol 2 (legacy): step schedules in the job stream (encode/stream.hpp).
inline constexpr std::uint8_t kProtocolVersion = machine::reference_firmware::kLegacyProtocol;
// The reference firmware's protocol (docs/protocol.md): the same frames,
// sessions and window; table moves and dot-grid passes in the job stream
// (encode/stream_v3.hpp); a DATA check; the ramp table id in HELLO_REPLY.
inline constexpr std::uint8_t kProtocolV3 = machine::reference_firmware::kProtocol;

// Frame types. Host-to-controller types are below 0x80, replies have the top bit.
enum class FrameType : std::uint8_t {
    hello = 0x01,      // open a session (resets the sequence numbers), ask version/capabilities
    configure = 0x02,  // machine geometry and timings from the printer profile
    data = 0x03,       // a chunk of the job stream (ops), buffered in the controller's ring
    pause = 0x04,      // stop at the next safe point (end of the current move or strike)
    resume = 0x05,     // continue; clears recoverable faults whose cause is gone
    abort = 0x06,      // stop now, drop the buffered job
    status = 0x07,     // ask for a full status report
    keepalive = 0x08,  // nothing to do; proves the host is alive
    hello_reply = 0x81,
    ack = 0x82,         // short status; SEQ = next sequence number expected
    nak = 0x83,         // frame refused; SEQ = next expected, payload says why
    status_reply = 0x84,
};
[[nodiscard]] bool is_known_type(std::uint8_t type);

enum class ControllerState : std::uint8_t {
    idle = 0,     // no job, or job finished
    running = 1,  // executing the job stream
    waiting = 2,  // running, but the ring is empty (waiting for data)
    paused = 3,   // stopped at a safe point on request or keep-alive loss
    fault = 4,    // stopped by a fault (see Faults)
    homing = 5,
};
[[nodiscard]] const char* state_name(ControllerState s);

// Fault bits. paper_out, limit_switch, hammer and host_timeout stop the job at a
// safe point; reset bits are set at boot and cleared by the next hello.
namespace fault {
inline constexpr std::uint8_t paper_out = 0x01;
inline constexpr std::uint8_t limit_switch = 0x02;
inline constexpr std::uint8_t hammer = 0x04;
inline constexpr std::uint8_t power_on_reset = 0x08;  // RAM lost: cold boot
inline constexpr std::uint8_t warm_reset = 0x10;      // watchdog/RST pin: RAM kept, progress valid
inline constexpr std::uint8_t host_timeout = 0x20;    // keep-alive lost; paused
inline constexpr std::uint8_t underrun = 0x40;        // ring ran dry inside a move (never expected)
inline constexpr std::uint8_t stream_error = 0x80;    // malformed op in the job stream
}  // namespace fault
[[nodiscard]] std::string fault_names(std::uint8_t faults);

// Status flags (status.flags).
namespace flag {
inline constexpr std::uint8_t configured = 0x01;
inline constexpr std::uint8_t homed = 0x02;  // carriage position known
inline constexpr std::uint8_t pass_active = 0x04;  // inside a pass (its feed is done)
inline constexpr std::uint8_t paper_present = 0x08;
inline constexpr std::uint8_t job_active = 0x10;
// The job named by job_id ran to its JOB_END (cleared by JOB_BEGIN, by ABORT of
// a running job and by power loss). Job id and counts outlive the job, so a
// host that died meanwhile reads what the controller finished (docs/protocol.md).
inline constexpr std::uint8_t job_ended = 0x20;
}  // namespace flag

// Why a frame was refused (NAK payload byte 0).
enum class NakReason : std::uint8_t {
    out_of_order = 1,  // SEQ is ahead of the expected one: a frame was lost
    no_space = 2,      // DATA larger than the free ring space (host broke the window)
    no_session = 3,    // no hello since boot
    bad_payload = 4,   // known type, malformed payload
    unknown_type = 5,
};

// The short status carried by every ACK and NAK (8 bytes).
struct AckInfo {
    std::uint16_t job_id = 0;            // job the counts below belong to (0: none yet)
    std::uint8_t buffer_free = 0;        // ring bytes free, after everything acknowledged
    std::uint16_t executed_passes = 0;   // passes of the current job fully executed
    ControllerState state = ControllerState::idle;
    std::uint8_t faults = 0;
    std::uint8_t strikes_in_pass = 0;    // strikes made in the pass being executed
    bool operator==(const AckInfo&) const = default;
};

// The full status (STATUS_REPLY, 25 bytes).
struct Status {
    AckInfo ack;
    std::uint8_t flags = 0;
    std::uint16_t job_id = 0;
    std::uint16_t sheet = 0;      // sheet loaded (0: none)
    std::uint16_t pass_index = 0; // pass being executed (job-wide, 0-based)
    std::int32_t carriage_step = 0;
    std::int32_t feed_step = 0;
    std::uint16_t underruns = 0;  // times the executor found the ring empty mid-pass
    bool operator==(const Status&) const = default;
};

// HELLO payload: the host's session nonce (a new one per session, so a stale
// duplicate HELLO is recognised and never resets the sequence twice).
struct Hello {
    std::uint16_t nonce = 0;
    std::uint8_t protocol = kProtocolVersion;
    bool operator==(const Hello&) const = default;
};

namespace capability {
inline constexpr std::uint8_t interpoint = 0x01;  // two hammers, one pass embosses both sides
inline constexpr std::uint8_t lpt = 0x02;
inline constexpr std::uint8_t uart = 0x04;
inline constexpr std::uint8_t warm_restart = 0x08;  // keeps progress across a watchdog reset
}  // namespace capability

struct HelloReply {
    std::uint8_t protocol = kProtocolVersion;
    std::uint8_t firmware_major = 1;
    std::uint8_t firmware_minor = 0;
    std::uint8_t capabilities = 0;
    std::uint8_t ring_bytes = 0;   // size of the job-stream ring buffer
    std::uint8_t max_payload = 0;  // largest DATA payload accepted
    std::uint8_t window_frames = 0; // most frames the host may have unacknowledged
    std::uint32_t table_id = 0;     // v3: the ramp tables the firmware was built with
    bool operator==(const HelloReply&) const = default;
};

// v3's CONFIGURE (10 bytes): travel, homing interval, hammer pulse, settle,
// keep-alive, each u16.
std::vector<std::uint8_t> encode_config_v3(const machine::ControllerConfig&, std::uint16_t settle_ticks);

// CONFIGURE carries machine::ControllerConfig. Steps per mm are sent in
// micro-steps per metre so the firmware never sees a float.

// Payload codecs. Decoders check the exact length and every range.
std::vector<std::uint8_t> encode_hello(const Hello&);
Result<Hello> decode_hello(std::span<const std::uint8_t>);
std::vector<std::uint8_t> encode_hello_reply(const HelloReply&);
Result<HelloReply> decode_hello_reply(std::span<const std::uint8_t>);
std::vector<std::uint8_t> encode_config(const machine::ControllerConfig&);
Result<machine::ControllerConfig> decode_config(std::span<const std::uint8_t>);
std::vector<std::uint8_t> encode_ack(const AckInfo&);
Result<AckInfo> decode_ack(std::span<const std::uint8_t>);
std::vector<std::uint8_t> encode_nak(NakReason, const AckInfo&);
Result<std::pair<NakReason, AckInfo>> decode_nak(std::span<const std::uint8_t>);
std::vector<std::uint8_t> encode_status(const Status&);
Result<Status> decode_status(std::span<const std::uint8_t>);

}  // namespace tactus::encode
