// SPDX-License-Identifier: GPL-3.0-or-later
#include "encode/stream_v3.hpp"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>

#include "encode/big_endian.hpp"
#include "encode/crc16.hpp"
#include "motion/table_move.hpp"
#include "common/try.hpp"

namespace tactus::encode {
namespace {

// v3's varints are big-endian, the firmware's shape: one byte 0-127, or two
// bytes 1xxxxxxx xxxxxxxx (15 bits); an svar keeps its sign in the top bit
// of the value (-64..63 in one byte).
void put_uvar15(std::vector<std::uint8_t>& o, std::uint32_t v) {
    if (v < 0x80) {
        o.push_back(static_cast<std::uint8_t>(v));
        return;
    }
    o.push_back(static_cast<std::uint8_t>(0x80 | (v >> 8)));
    o.push_back(static_cast<std::uint8_t>(v & 0xFF));
}
void put_svar15(std::vector<std::uint8_t>& o, std::int32_t v) {
    if (v >= -64 && v < 64) {
        o.push_back(static_cast<std::uint8_t>(v & 0x7F));
        return;
    }
    // Always the two-byte form: the firmware reads a one-byte svar as 7 bits
    // signed, so 64..127 written as a one-byte uvar came back as -64..-1 (a
    // feed of 108 units, after a short last page, ran 20 units backwards).
    const auto u = static_cast<std::uint32_t>(v) & 0x7FFF;
    o.push_back(static_cast<std::uint8_t>(0x80 | (u >> 8)));
    o.push_back(static_cast<std::uint8_t>(u & 0xFF));
}

// The firmware's model of one axis: its step counter and the direction it last moved.
struct AxisState {
    std::int32_t pos = 0;
    bool neg = false;
};

std::string where_of(const PassRef& r) {
    return "sheet " + std::to_string(r.sheet) + " pass " + std::to_string(r.pass_in_sheet + 1);
}

// A move of `steps` motor steps (backlash included) as grid units under the
// firmware's rule; advances the axis model. nullopt when off the grid.
std::optional<std::uint32_t> units_of(std::int32_t steps, AxisState& a, const machine::RampTable& t) {
    if (steps == 0) return 0U;
    const bool neg = steps < 0;
    auto head = static_cast<std::int64_t>(std::abs(steps));
    if (neg != a.neg) head -= t.backlash_steps;
    if (head <= 0 || head % t.grid_steps != 0) return std::nullopt;
    a.neg = neg;
    a.pos += steps;
    return static_cast<std::uint32_t>(head / t.grid_steps);
}

struct Encoder {
    const machine::FirmwareTables& t;
    const machine::StrikeTiming& timing;
    JobStream& s;
    void end_op() { s.op_ends.push_back(s.bytes.size()); }
    void seek(std::uint8_t op, std::int32_t target) {
        s.bytes.push_back(op);
        put16(s.bytes, static_cast<std::uint16_t>(target));
        end_op();
    }
    // Brings the firmware's carriage to `want` (position and last direction)
    // with seeks at the homing rate, which add no backlash.
    Result<void> align(AxisState& fw, const AxisState& want) {
        if (fw.pos == want.pos && fw.neg == want.neg) return {};
        if (want.pos < 0 || want.pos > 0x7FFF - 2 * static_cast<std::int32_t>(t.carriage.grid_steps))
            return fail(ErrorKind::input, "carriage position " + std::to_string(want.pos) + " out of the seek range", "plan");
        // Arrive moving the way the plan last moved: overshoot first if need be.
        const bool arrives_neg = want.pos < fw.pos;
        if (want.pos == fw.pos || arrives_neg != want.neg) {
            const auto via = want.neg ? want.pos + static_cast<std::int32_t>(t.carriage.grid_steps)
                                      : std::max(0, want.pos - static_cast<std::int32_t>(t.carriage.grid_steps));
            if (via == want.pos) return fail(ErrorKind::input, "cannot approach carriage step 0 moving away from home", "plan");
            seek(v3::op_seek_carriage, via);
        }
        seek(v3::op_seek_carriage, want.pos);
        fw = want;
        return {};
    }
};

}  // namespace

Result<JobStream> encode_job_v3(const plan::JobPlan& plan, const machine::FirmwareTables& tables,
                                const machine::StrikeTiming& timing, std::uint16_t job_id,
                                const StreamStart& start) {
    TACTUS_TRY(begun, begin_stream(plan, start));
    JobStream s = std::move(begun);
    Encoder e{tables, timing, s};
    s.bytes.push_back(v3::op_job_begin);
    put16(s.bytes, job_id);
    put16(s.bytes, static_cast<std::uint16_t>(start.first_pass));
    e.end_op();
    s.bytes.push_back(v3::op_home);
    e.end_op();
    // The plan's carriage and feed as the firmware counts them (from the job's
    // start), and the firmware's own once the stream begins.
    AxisState carriage{0, true};  // after HOME: at 0, last moved toward home
    AxisState feed{0, false};
    AxisState fw_carriage{0, true};
    AxisState fw_feed{0, false};
    std::size_t idx = 0;
    for (std::size_t sp = 0; sp < plan.sheets.size(); ++sp) {
        const auto& sheet = plan.sheets[sp];
        if (sheet.index > 0xFFFF) return fail(ErrorKind::input, "sheet number above 65535", "plan");
        feed.pos = 0;  // SHEET_BEGIN: the sheet's top edge is the feed origin
        const std::size_t sheet_end_idx = idx + sheet.passes.size();
        const bool emit_sheet = sheet_end_idx > start.first_pass || (sheet.passes.empty() && idx >= start.first_pass);
        // A restart inside a sheet that is still loaded and positioned.
        const bool restart_sheet = start.mid_sheet && idx <= start.first_pass && start.first_pass < sheet_end_idx;
        if (emit_sheet && !restart_sheet) {
            s.bytes.push_back(v3::op_sheet_begin);
            put16(s.bytes, static_cast<std::uint16_t>(sheet.index));
            e.end_op();
            fw_feed.pos = 0;
        }
        for (std::size_t pi = 0; pi < sheet.passes.size(); ++pi, ++idx) {
            const auto& pass = sheet.passes[pi];
            const auto where = where_of({sp, pi, sheet.index});
            const bool emit = idx >= start.first_pass;
            const bool restart_pass = emit && idx == start.first_pass && start.mid_sheet;
            if (pass.moves.size() != pass.strikes.size())
                return fail(ErrorKind::input, "pass has " + std::to_string(pass.moves.size()) + " moves for " +
                                std::to_string(pass.strikes.size()) + " strikes",
                            where);
            if (pass.strikes.size() > 255) return fail(ErrorKind::input, "more than 255 strikes in a pass", where);
            if (!motion::is_table_move(tables.feed, pass.feed))
                return fail(ErrorKind::input, "the feed is not the firmware's table move of " + std::to_string(pass.feed.steps) +
                                " steps: plan with the firmware's tables (PlanOptions::firmware)",
                            where);
            const AxisState feed_before = feed;
            const auto feed_units = units_of(pass.feed.steps, feed, tables.feed);
            if (!feed_units)
                return fail(ErrorKind::input, "a feed of " + std::to_string(pass.feed.steps) + " steps is off the firmware's " +
                                std::to_string(tables.feed.grid_steps) + "-step grid",
                            where);
            if (*feed_units >= 0x4000) return fail(ErrorKind::input, "feed too long for one pass record", where);
            if (feed.pos != pass.feed_step)
                return fail(ErrorKind::input, "the feed reaches step " + std::to_string(feed.pos) + ", the pass is planned at " +
                                std::to_string(pass.feed_step),
                            where);
            // Entries: the carriage moves in grid units, checked against the plan.
            const AxisState before = carriage;
            std::vector<std::uint8_t> entries;
            std::vector<std::size_t> entry_ends;
            std::uint32_t first_units = 0;
            bool first_neg = false;
            std::optional<bool> sweep_neg;
            for (std::size_t i = 0; i < pass.strikes.size(); ++i) {
                const auto& m = pass.moves[i];
                const auto mw = where + " strike " + std::to_string(i + 1);
                if (!motion::is_table_move(tables.carriage, m))
                    return fail(ErrorKind::input, "the move is not the firmware's table move of " + std::to_string(m.steps) +
                                    " steps: plan with the firmware's tables (PlanOptions::firmware)",
                                mw);
                if (m.settle_ticks != timing.settle_ticks)
                    return fail(ErrorKind::input, "settles " + std::to_string(m.settle_ticks) + " ticks, the firmware " +
                                    std::to_string(timing.settle_ticks) + " (CONFIGURE)",
                                mw);
                const auto u = units_of(m.steps, carriage, tables.carriage);
                if (!u)
                    return fail(ErrorKind::input, "a move of " + std::to_string(m.steps) + " steps is off the firmware's " +
                                    std::to_string(tables.carriage.grid_steps) + "-step grid",
                                mw);
                if (carriage.pos != pass.strikes[i].carriage_step)
                    return fail(ErrorKind::input, "moves reach carriage step " + std::to_string(carriage.pos) +
                                    " but the strike is planned at " + std::to_string(pass.strikes[i].carriage_step),
                                mw);
                const std::uint8_t h = pass.strikes[i].hammer == plan::Hammer::concave ? v3::entry::concave : 0x00;
                if (i == 0) {
                    first_units = *u;
                    first_neg = m.steps < 0;
                    if (first_units >= 0x8000) return fail(ErrorKind::input, "first move too long for a pass record", mw);
                    entries.push_back(h);
                    entry_ends.push_back(entries.size());
                } else {
                    if (m.steps != 0) {
                        if (sweep_neg && *sweep_neg != (m.steps < 0))
                            return fail(ErrorKind::input, "the pass's strikes do not all run one way", mw);
                        sweep_neg = m.steps < 0;
                    }
                    if (*u <= v3::entry::dist) {
                        entries.push_back(static_cast<std::uint8_t>(h | *u));
                    } else if (*u < 0x4000) {
                        entries.push_back(static_cast<std::uint8_t>(h | v3::entry::ext | (*u >> 8)));
                        entries.push_back(static_cast<std::uint8_t>(*u & 0xFF));
                    } else {
                        return fail(ErrorKind::input, "a strike " + std::to_string(*u) + " grid units from the last", mw);
                    }
                    entry_ends.push_back(entries.size());
                }
            }
            if (!emit) continue;
            if (restart_pass) {
                // The feed was made before the reset: stand where it ended.
                e.seek(v3::op_seek_feed, pass.feed_step);
                fw_feed = feed;
            } else if (fw_feed.pos != feed_before.pos) {
                // A restart on a fresh sheet after its first pass: feed to where the last pass left it.
                e.seek(v3::op_seek_feed, feed_before.pos);
                fw_feed = feed_before;
            }
            if (auto r = e.align(fw_carriage, before); !r) return std::unexpected(located(r.error(), where));
            const std::uint8_t skip = restart_pass ? start.skip : 0;
            const std::uint8_t flags = static_cast<std::uint8_t>(
                (pass.side == plan::Side::back ? v3::pass_flag::back_side : 0) |
                (restart_pass ? v3::pass_flag::no_feed : 0) | (sweep_neg.value_or(false) ? v3::pass_flag::sweep_neg : 0) |
                (first_neg ? v3::pass_flag::first_neg : 0) | (skip ? v3::pass_flag::skip : 0));
            s.bytes.push_back(v3::op_pass);
            s.bytes.push_back(flags);
            if (skip) s.bytes.push_back(skip);
            put_svar15(s.bytes, pass.feed.steps < 0 ? -static_cast<std::int32_t>(*feed_units)
                                                    : static_cast<std::int32_t>(*feed_units));
            put_uvar15(s.bytes, first_units);
            s.bytes.push_back(static_cast<std::uint8_t>(pass.strikes.size()));
            e.end_op();
            // Each entry ends a place a frame may end.
            const std::size_t base = s.bytes.size();
            s.bytes.insert(s.bytes.end(), entries.begin(), entries.end());
            for (const auto end : entry_ends) s.op_ends.push_back(base + end);
            fw_carriage = carriage;
            if (!restart_pass) fw_feed = feed;
        }
        if (emit_sheet) {
            s.bytes.push_back(v3::op_sheet_end);
            e.end_op();
        }
    }
    s.bytes.push_back(v3::op_job_end);
    e.end_op();
    return s;
}

std::vector<std::pair<std::size_t, std::size_t>> chunk_stream_v3(const JobStream& stream, std::size_t max_ops,
                                                                 std::size_t from) {
    std::vector<std::pair<std::size_t, std::size_t>> chunks;
    if (max_ops == 0) return chunks;
    for (std::size_t b = from; b < stream.bytes.size(); b += max_ops)
        chunks.emplace_back(b, std::min(stream.bytes.size(), b + max_ops));
    return chunks;
}

std::vector<std::uint8_t> data_payload_v3(std::span<const std::uint8_t> ops) {
    std::vector<std::uint8_t> p(ops.begin(), ops.end());
    const auto c = data_check_v3(ops);
    put16(p, c);
    return p;
}

Result<std::vector<StrikeV3>> execute_v3(std::span<const std::uint8_t> in, const machine::FirmwareTables& t) {
    std::vector<StrikeV3> out;
    AxisState c{0, false}, f{0, false};
    std::uint16_t sheet = 0;
    std::size_t i = 0;
    auto need = [&](std::size_t n) -> Result<void> {
        if (i + n > in.size()) return fail(ErrorKind::protocol, "stream ends inside an op", "byte " + std::to_string(i));
        return {};
    };
    auto u8 = [&] { return in[i++]; };
    auto be16 = [&] {
        const auto v = static_cast<std::uint16_t>((in[i] << 8) | in[i + 1]);
        i += 2;
        return v;
    };
    auto uvar = [&]() -> Result<std::uint32_t> {
        TACTUS_TRY_VOID(need(1));
        const std::uint8_t b = u8();
        if (!(b & 0x80)) return b;
        TACTUS_TRY_VOID(need(1));
        return (static_cast<std::uint32_t>(b & 0x7F) << 8) | u8();
    };
    // The firmware's carriage(): a reversal adds the backlash to the motor's move.
    auto move = [](AxisState& a, const machine::RampTable& tab, std::uint32_t units, bool neg) {
        if (units == 0) return;
        std::int32_t motor = static_cast<std::int32_t>(units * tab.grid_steps);
        if (neg != a.neg) motor += static_cast<std::int32_t>(tab.backlash_steps);
        a.neg = neg;
        a.pos += neg ? -motor : motor;
    };
    while (i < in.size()) {
        const std::size_t at = i;
        const std::uint8_t op = u8();
        switch (op) {
            case v3::op_job_begin:
                TACTUS_TRY_VOID(need(4));
                i += 4;
                break;
            case v3::op_job_end:
            case v3::op_sheet_end: break;
            case v3::op_sheet_begin:
                TACTUS_TRY_VOID(need(2));
                sheet = be16();
                f.pos = 0;
                break;
            case v3::op_home: c = {0, true}; break;
            case v3::op_seek_carriage:
            case v3::op_seek_feed: {
                TACTUS_TRY_VOID(need(2));
                const auto target = static_cast<std::int16_t>(be16());
                AxisState& a = op == v3::op_seek_feed ? f : c;
                if (target != a.pos) a.neg = target < a.pos;
                a.pos = target;
                break;
            }
            case v3::op_pass: {
                TACTUS_TRY_VOID(need(1));
                const std::uint8_t flags = u8();
                if (flags & 0xE0) return fail(ErrorKind::protocol, "reserved pass flags", "byte " + std::to_string(at));
                std::uint8_t skip = 0;
                if (flags & v3::pass_flag::skip) {
                    TACTUS_TRY_VOID(need(1));
                    skip = u8();
                }
                TACTUS_TRY_VOID(need(1));
                const bool two = (in[i] & 0x80) != 0;
                TACTUS_TRY(fu, uvar());
                std::int32_t feed = two ? ((fu & 0x4000) ? static_cast<std::int32_t>(fu) - 0x8000
                                                          : static_cast<std::int32_t>(fu))
                                        : ((fu & 0x40) ? static_cast<std::int32_t>(fu) - 128
                                                        : static_cast<std::int32_t>(fu));
                TACTUS_TRY(first, uvar());
                TACTUS_TRY_VOID(need(1));
                const std::uint8_t n = u8();
                if (!(flags & v3::pass_flag::no_feed) && feed != 0)
                    move(f, t.feed, static_cast<std::uint32_t>(std::abs(feed)), feed < 0);
                for (std::uint8_t k = 0; k < n; ++k) {
                    TACTUS_TRY_VOID(need(1));
                    const std::uint8_t en = u8();
                    std::uint32_t d = en & 0x3F;
                    if (en & 0x40) {
                        TACTUS_TRY_VOID(need(1));
                        d = (d << 8) | u8();
                    }
                    if (k == 0)
                        move(c, t.carriage, first, (flags & v3::pass_flag::first_neg) != 0);
                    else
                        move(c, t.carriage, d, (flags & v3::pass_flag::sweep_neg) != 0);
                    if (skip) {
                        --skip;
                        continue;
                    }
                    out.push_back({sheet, c.pos, f.pos, (en & 0x80) != 0});
                }
                break;
            }
            default: return fail(ErrorKind::protocol, "unknown op 0x" + std::to_string(op), "byte " + std::to_string(at));
        }
    }
    return out;
}

}  // namespace tactus::encode
