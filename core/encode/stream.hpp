// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The job stream: what DATA frames carry. A plan becomes a sequence of small ops
// (begin sheet, begin pass, move, strike, ...) that the controller buffers in
// its ring and executes in order. Each op is whole inside one DATA payload, so
// the firmware never parses an op that is only half received.
//
//   JOB_BEGIN   0x10 u16 job, u16 first pass          JOB_END    0x11
//   SHEET_BEGIN 0x12 u16 sheet, svar feed origin      SHEET_END  0x13
//   PASS_BEGIN  0x14 u16 pass, u8 flags, u8 skip      PASS_END   0x15
//   MOVE        0x20|axis|neg<<1|cont<<2, u8 n, n x (uvar count<<4|grid,
//               svar interval>>grid minus the previous segment's last interval>>grid,
//               svar add>>grid)                       (docs/protocol.md, "Step segments")
//   STRIKE      0x30|hammer, uvar ticks at rest before the hammer fires (settle)
//   HOME        0x40
//   SEEK        0x42 carriage / 0x43 feed, svar absolute target
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "common/result.hpp"
#include "plan/plan.hpp"

namespace tactus::encode {

enum class OpCode : std::uint8_t {
    job_begin = 0x10,
    job_end = 0x11,
    sheet_begin = 0x12,
    sheet_end = 0x13,
    pass_begin = 0x14,
    pass_end = 0x15,
    move = 0x20,
    strike = 0x30,
    home = 0x40,
    seek = 0x42,
};

enum class Axis : std::uint8_t { carriage = 0, feed = 1 };

namespace pass_flag {
inline constexpr std::uint8_t back_side = 0x01;
inline constexpr std::uint8_t no_feed = 0x02;  // restart: the feed was done before a reset
}  // namespace pass_flag

// A MOVE op carries at most this many bytes of segments (the writer starts a
// continuation op beyond it), so an op always fits one DATA payload with room
// for the strike after it.
inline constexpr std::size_t kMaxMoveOpBytes = 64;
// Segments per MOVE op: the most that fit kMaxMoveOpBytes at one byte per field.
inline constexpr std::size_t kMaxSegmentsPerOp = (kMaxMoveOpBytes - 2) / 3;
// The longest settle before a strike: 0.9 s at 921.6 kHz (a three-byte varint
// carries 21 bits).
inline constexpr std::uint32_t kMaxStrikeWaitTicks = (1U << 21) - 1;
// The controller counts a job's passes in 16 bits (JOB_BEGIN, PASS_BEGIN, the
// executed-pass count of every ACK), so one job has at most this many.
inline constexpr std::size_t kMaxJobPasses = 0xFFFF;

struct Op {
    OpCode code = OpCode::job_end;
    Axis axis = Axis::carriage;        // move, seek
    bool negative = false;             // move: direction
    bool continuation = false;         // move: continues the previous move without stopping
    plan::Hammer hammer = plan::Hammer::convex;  // strike
    std::uint32_t wait_ticks = 0;                // strike: at rest before the hammer fires
    std::uint16_t id = 0;              // job id, sheet number, pass index
    std::uint16_t first_pass = 0;      // job_begin
    std::uint8_t flags = 0;            // pass_begin
    std::uint8_t skip = 0;             // pass_begin: strikes already made (restart)
    std::int32_t value = 0;            // sheet feed origin, seek target
    std::vector<motion::StepSegment> segments;  // move
    bool operator==(const Op&) const = default;
};

void append_op(std::vector<std::uint8_t>& out, const Op& op);
// Decodes the op at the start of `bytes`: the op and its length in bytes.
Result<std::pair<Op, std::size_t>> decode_op(std::span<const std::uint8_t> bytes);

// A move as the MOVE ops that carry it (one, or more with continuations), and
// their size in bytes.
std::vector<Op> move_ops(Axis axis, const motion::StepMove& m);
std::size_t move_bytes(const motion::StepMove& m);

// Steps and duration (in timer ticks) of a run of segments.
std::uint32_t segment_steps(std::span<const motion::StepSegment> segments);
std::uint64_t segment_ticks(std::span<const motion::StepSegment> segments);
// Tick of step k (1-based) from the start of the segments.
std::uint64_t tick_of_step(std::span<const motion::StepSegment> segments, std::uint32_t k);

// Where a pass sits in the plan.
struct PassRef {
    std::size_t sheet_pos = 0;      // index into JobPlan::sheets
    std::size_t pass_in_sheet = 0;  // index into SheetPlan::passes
    std::size_t sheet = 0;          // SheetPlan::index (1-based)
};
// Every pass of the plan, in job order: its position is the job-wide pass index.
std::vector<PassRef> pass_table(const plan::JobPlan& plan);

// Where a stream starts: a fresh job, or a restart after a controller reset.
struct StreamStart {
    std::size_t first_pass = 0;   // job-wide pass index
    std::uint8_t skip = 0;        // strikes of first_pass already made
    bool mid_sheet = false;       // the sheet is already loaded and positioned
};

struct JobStream {
    std::vector<std::uint8_t> bytes;
    std::vector<std::size_t> op_ends;  // byte offset just past each op
    std::size_t first_pass = 0;
    std::size_t end_pass = 0;          // one past the last pass streamed
};

// An empty stream for the plan from `start`, its pass range set; fails when
// the plan has more passes than the controller counts or `start` is past its
// end. Both protocol versions' encoders begin with it.
Result<JobStream> begin_stream(const plan::JobPlan& plan, const StreamStart& start);

// Encodes the plan from `start` to its end. Fails (with the pass named) on a
// plan the controller could not execute: step counts that do not add up,
// intervals out of the 16-bit timer range, more than 255 strikes in a pass.
Result<JobStream> encode_job(const plan::JobPlan& plan, std::uint16_t job_id,
                             const StreamStart& start);

// Cuts the stream into DATA payloads of whole ops, each at most `max_payload`
// bytes (an op larger than that travels alone): [begin, end) byte ranges,
// from the op boundary `from` on (the link cuts what it has not sent yet
// again when it changes its frame size).
std::vector<std::pair<std::size_t, std::size_t>> chunk_stream(const JobStream& stream,
                                                              std::size_t max_payload, std::size_t from = 0);

}  // namespace tactus::encode
