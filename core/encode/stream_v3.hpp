// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Protocol v3's job stream (docs/protocol.md, "The job stream (version 3)"): a pass
// is one record of relative moves in dot-grid units with a hammer flag per
// strike, the way the original embosser's print plan was written; the
// controller times every move from the ramp table in its flash. 1 to 2 line
// bytes per strike, against v2's 57.
//
//   JOB_BEGIN 0x10 u16 job, u16 first pass    JOB_END 0x11
//   SHEET_BEGIN 0x12 u16 sheet                SHEET_END 0x13
//   PASS 0x14 flags [skip] feed:svar first:uvar n:u8, n x entry (h e dddddd [d])
//   HOME 0x40                                 SEEK 0x42 carriage / 0x43 feed, u16 absolute step
//
// Ops may span DATA frames (the controller takes them byte by byte), and each
// DATA payload ends with data_check_v3 of its ops.
//
// The encoder refuses a plan it cannot express, naming the pass and strike: a
// move that is not the firmware's table move for its step count (the planner
// makes them with PlanOptions::firmware), a settle other than the one
// CONFIGURE sets, a distance off the dot grid once the firmware's backlash
// rule is applied, a pass whose strikes do not all run one way, more than 255
// strikes in a pass.
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "common/result.hpp"
#include "encode/stream.hpp"
#include "machine/firmware_tables.hpp"
#include "plan/plan.hpp"

namespace tactus::encode {

namespace v3 {
inline constexpr std::uint8_t op_job_begin = 0x10;
inline constexpr std::uint8_t op_job_end = 0x11;
inline constexpr std::uint8_t op_sheet_begin = 0x12;
inline constexpr std::uint8_t op_sheet_end = 0x13;
inline constexpr std::uint8_t op_pass = 0x14;
inline constexpr std::uint8_t op_home = 0x40;
inline constexpr std::uint8_t op_seek_carriage = 0x42;
inline constexpr std::uint8_t op_seek_feed = 0x43;
namespace pass_flag {
inline constexpr std::uint8_t back_side = 0x01;
inline constexpr std::uint8_t no_feed = 0x02;
inline constexpr std::uint8_t sweep_neg = 0x04;
inline constexpr std::uint8_t first_neg = 0x08;
inline constexpr std::uint8_t skip = 0x10;
inline constexpr std::uint8_t all = 0x1F;  // any other bit set: a malformed record
}  // namespace pass_flag
// A strike entry's first byte: h e dddddd, a second distance byte when e.
namespace entry {
inline constexpr std::uint8_t concave = 0x80;  // h: the concave hammer (the back side's dot)
inline constexpr std::uint8_t ext = 0x40;      // e: a second byte of distance follows
inline constexpr std::uint8_t dist = 0x3F;     // the distance (its high bits when e)
}  // namespace entry
}  // namespace v3

// The plan as a v3 job stream from `start`. JobStream::op_ends holds the end
// of every op and of every pass entry (where a frame may end; any byte may).
Result<JobStream> encode_job_v3(const plan::JobPlan& plan, const machine::FirmwareTables& tables,
                                const machine::StrikeTiming& timing, std::uint16_t job_id,
                                const StreamStart& start);

// Cuts the stream into DATA payloads of at most `max_ops` op bytes (the check
// is added per frame): [begin, end) byte ranges, from byte `from` on.
std::vector<std::pair<std::size_t, std::size_t>> chunk_stream_v3(const JobStream& stream, std::size_t max_ops,
                                                                 std::size_t from = 0);

// A DATA payload: the ops and their check.
std::vector<std::uint8_t> data_payload_v3(std::span<const std::uint8_t> ops);

// What a v3 controller does with a stream, positions only (the firmware's
// rules: HOME zeroes the carriage and leaves it last moving toward home, a
// reversal adds the backlash, SHEET_BEGIN zeroes the feed): one entry per
// strike fired. For tests and the conformance of the encoder with the firmware.
struct StrikeV3 {
    std::uint16_t sheet = 0;
    std::int32_t carriage_step = 0;
    std::int32_t feed_step = 0;
    bool concave = false;
    bool operator==(const StrikeV3&) const = default;
};
Result<std::vector<StrikeV3>> execute_v3(std::span<const std::uint8_t> stream, const machine::FirmwareTables& tables);

}  // namespace tactus::encode
