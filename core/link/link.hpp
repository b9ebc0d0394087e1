// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The host side of the link: opens a device string, talks the Tactus protocol
// (docs/protocol.md) to the 89C52, streams a JobPlan with a sliding window and
// retransmission, and reports each pass only once the controller says it has
// EXECUTED it. This is what the spool drives.
//
// Threading: one thread calls send_job(), which blocks until the job ends.
// request_pause(), request_resume() and the CancelToken may be used from any
// other thread while it runs; pause()/resume()/abort()/status() are for use
// when no job is streaming (they do their own request/reply).
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "common/result.hpp"
#include "encode/messages.hpp"
#include "machine/firmware_tables.hpp"
#include "plan/plan.hpp"

namespace tactus::transport {
class ByteStream;
}

namespace tactus::link {

using machine::ControllerConfig;
using encode::ControllerState;
using encode::HelloReply;
using encode::Status;

struct LinkOptions {
    // A reply must arrive within this time (plus the line time of the bytes in
    // flight) or the oldest frame is sent again.
    std::chrono::milliseconds retransmit_timeout{250};
    // No valid frame from the controller for this long: the device is treated
    // as disconnected and reopened until reconnect_deadline.
    std::chrono::milliseconds silence_timeout{3000};
    std::chrono::milliseconds reconnect_deadline{30000};
    // Paper out: wait this long for the operator to load paper before giving up.
    std::chrono::milliseconds fault_wait{120000};
    std::chrono::milliseconds keepalive_period{500};
    // Bounded give-up: a job ends JobEnd::not_answering when the controller
    // has acknowledged no frame and executed no pass for this long, however
    // it fails (silent, reopened and silent again, or answering without ever
    // taking a frame). A controller that is waiting for paper, paused, or
    // printing acknowledges the keep-alive every 500 ms, so only a controller
    // that is gone or wedged meets it.
    std::chrono::milliseconds give_up_after{30000};
    std::uint16_t job_id = 1;
    // Limits below what the controller offers (0: its own). Window 1 with small
    // payloads is the stop-and-wait style of Marlin-like senders (benchmarks).
    std::size_t max_window_frames = 0;
    std::size_t max_payload = 0;
    // Protocol version to speak: 0 lets the controller decide (HELLO offers
    // v2; a controller that refuses it is offered v3, which the reference
    // firmware speaks), 2 or 3 to insist on one.
    std::uint8_t protocol = 0;
    // For a `sim` device (Link::open): the ramp tables of the profile the job
    // is planned with (profile::make_firmware_tables), so the simulated
    // controller speaks protocol 3 as the firmware built from that profile
    // does (controller::open_device). Without them it speaks protocol 2.
    std::optional<machine::FirmwareTables> sim_firmware;
};

// One pass the controller has executed (called in execution order).
struct PassExecuted {
    std::size_t sheet = 0;          // 1-based, as in the plan
    std::size_t pass_in_sheet = 0;  // 0-based index into SheetPlan::passes
    std::size_t passes_done = 0;    // executed so far in this send_job call
    std::size_t passes_total = 0;   // passes this send_job call streams
};

// Everything that happens during a job, for progress bars and logs. `executed`
// is set for a pass acknowledgement; otherwise `note` says what happened
// ("paper out: load paper", "reconnected", "controller reset: resuming at ...").
struct Progress {
    const PassExecuted* executed = nullptr;
    std::string note;
    std::size_t bytes_sent = 0;
    std::size_t bytes_total = 0;  // job-stream bytes of this call (grows on resends)
    Status status;
};
using ProgressFn = std::function<void(const Progress&)>;

class CancelToken {
public:
    void cancel() { flag_.store(true, std::memory_order_relaxed); }
    [[nodiscard]] bool cancelled() const { return flag_.load(std::memory_order_relaxed); }

private:
    std::atomic<bool> flag_{false};
};

struct LinkStats {
    std::size_t frames_sent = 0;
    std::size_t frames_resent = 0;
    std::size_t bytes_written = 0;     // raw line bytes, frames included
    std::size_t payload_bytes = 0;     // DATA payload bytes acknowledged
    std::size_t naks = 0;
    std::size_t timeouts = 0;
    std::size_t crc_errors = 0;        // corrupt frames received from the controller
    std::size_t reconnects = 0;
    std::size_t restarts = 0;          // job stream rebuilt after a controller reset/fault
    double data_seconds = 0;           // from the first DATA frame to the last ACK
};

// not_answering: the bounded give-up (LinkOptions::give_up_after); the error
// is a device error naming the sheet to resume from, and the job is not at
// fault (the spool waits for the printer instead of counting a retry).
enum class JobEnd { completed, cancelled, failed, not_answering };

struct JobOutcome {
    JobEnd end = JobEnd::failed;
    std::size_t passes_done = 0;  // executed in this call
    // Where to start again (sheet, 1-based) when the job did not complete:
    // the first sheet with a pass not executed.
    std::size_t resume_sheet = 0;
    Error error;  // why it failed (empty when completed or cancelled)
    LinkStats stats;
};

class Link {
public:
    // Opens a device string ("serial:/dev/ttyUSB0?baud=57600", "pty:/dev/pts/3",
    // "hid:10c4:ea80", "lpt:/dev/parport0", "sim"). The error names the device
    // and says whether it is missing, busy or refused.
    static Result<Link> open(std::string_view device, LinkOptions options = {});
    // Over an already open stream (tests, the in-process simulator).
    static Link over(std::unique_ptr<transport::ByteStream> stream, LinkOptions options = {});

    Link(Link&&) noexcept;
    Link& operator=(Link&&) noexcept;
    ~Link();

    // Opens a session: new nonce, sequence numbers reset, version checked.
    Result<HelloReply> hello();
    Result<void> configure(const machine::ControllerConfig& config);
    // Protocol v3 (the reference firmware): the ramp tables the plan was made
    // with (profile::load_firmware_tables) and the strike timing CONFIGURE
    // sets. Refused, with the reason, when the firmware reports other tables
    // in HELLO_REPLY: a job planned with them would strike in the wrong
    // places and times. Call after hello(), before configure().
    Result<void> use_firmware_tables(const machine::FirmwareTables& tables, const machine::StrikeTiming& timing);
    // The protocol version of the open session (0: none).
    [[nodiscard]] std::uint8_t protocol() const;
    Result<Status> status();
    Result<void> pause();
    Result<void> resume();
    Result<void> abort();
    // Close and reopen the device, then hello() again (after an unplug).
    Result<void> reconnect();

    // Streams sheets start_sheet.. of the plan (1-based). Returns when every pass
    // is executed, the job is cancelled (the controller is told to abort), or it
    // fails for good (hammer fault, device gone past the reconnect deadline,
    // paper not loaded in time). A Result error is returned only for misuse
    // (no session, start_sheet out of range, a plan the protocol cannot carry);
    // job failures are in JobOutcome.
    //
    // `job_id` is the id JOB_BEGIN carries. 0: the link picks one from
    // 0x0002-0x8000, never the id the controller last reported. The spool
    // picks its own (0x8001-0xFFFF) and stores it before calling, so a
    // controller count under that id is known to be this stream's.
    Result<JobOutcome> send_job(const plan::JobPlan& plan, std::size_t start_sheet,
                                const ProgressFn& progress, const CancelToken& cancel,
                                std::uint16_t job_id = 0);

    // Thread-safe requests honoured by a running send_job().
    void request_pause();
    void request_resume();

    [[nodiscard]] const LinkStats& stats() const;
    [[nodiscard]] std::string device() const;
    [[nodiscard]] transport::ByteStream& stream();

private:
    struct Impl;
    explicit Link(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace tactus::link
