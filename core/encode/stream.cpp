// SPDX-License-Identifier: GPL-3.0-or-later
#include "encode/stream.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "encode/big_endian.hpp"
#include "encode/frame.hpp"
#include "encode/varint.hpp"
#include "motion/steps.hpp"
#include "common/try.hpp"

namespace tactus::encode {
namespace {

// The interval of the last step of `s` (Q16.16, wrapping like the 8051's
// 32-bit adds): the prediction the next segment's interval is sent against.
std::uint32_t last_interval(const motion::StepSegment& s) {
    return s.interval_q16 + static_cast<std::uint32_t>(s.add_q16) * (s.count - 1U);
}

// The coarsest grid (2^shift Q16.16 units) both the interval and the add lie
// on: the planner picks the coarsest grid that keeps its steps in tolerance,
// and the low bits it leaves at zero are not sent.
unsigned grid_shift(const motion::StepSegment& s) {
    unsigned shift = 0;
    const auto add = static_cast<std::uint32_t>(s.add_q16);
    while (shift < machine::kMaxGridShift && ((s.interval_q16 | add) & (1U << shift)) == 0) ++shift;
    return shift;
}

// Per segment: count and grid shift; the interval on that grid as its
// difference from the previous segment's last interval (the first of an op from
// 0, so every op decodes alone); the add on that grid. Step timing is
// continuous and the planner picks coarse grids, so a segment is typically 4 or
// 5 bytes (about 8 at full precision).
void put_segment(std::vector<std::uint8_t>& out, const motion::StepSegment& s, const motion::StepSegment* prev) {
    const unsigned shift = grid_shift(s);
    const std::uint32_t ref = prev ? last_interval(*prev) : 0U;
    put_uvar(out, (static_cast<std::uint32_t>(s.count) << 4) | shift);
    put_svar(out, static_cast<std::int32_t>((s.interval_q16 >> shift) - (ref >> shift)));
    put_svar(out, s.add_q16 >> shift);
}

std::string at_byte(std::size_t pos) { return "op byte " + std::to_string(pos); }

}  // namespace

void append_op(std::vector<std::uint8_t>& out, const Op& op) {
    switch (op.code) {
        case OpCode::job_begin:
            out.push_back(0x10);
            put16(out, op.id);
            put16(out, op.first_pass);
            break;
        case OpCode::job_end: out.push_back(0x11); break;
        case OpCode::sheet_begin:
            out.push_back(0x12);
            put16(out, op.id);
            put_svar(out, op.value);
            break;
        case OpCode::sheet_end: out.push_back(0x13); break;
        case OpCode::pass_begin:
            out.push_back(0x14);
            put16(out, op.id);
            out.push_back(op.flags);
            out.push_back(op.skip);
            break;
        case OpCode::pass_end: out.push_back(0x15); break;
        case OpCode::move:
            out.push_back(static_cast<std::uint8_t>(0x20 | static_cast<unsigned>(op.axis) |
                                                    (op.negative ? 0x02U : 0U) |
                                                    (op.continuation ? 0x04U : 0U)));
            out.push_back(static_cast<std::uint8_t>(op.segments.size()));
            for (std::size_t i = 0; i < op.segments.size(); ++i)
                put_segment(out, op.segments[i], i == 0 ? nullptr : &op.segments[i - 1]);
            break;
        case OpCode::strike:
            out.push_back(op.hammer == plan::Hammer::convex ? 0x30 : 0x31);
            put_uvar(out, op.wait_ticks);
            break;
        case OpCode::home: out.push_back(0x40); break;
        case OpCode::seek:
            out.push_back(op.axis == Axis::carriage ? 0x42 : 0x43);
            put_svar(out, op.value);
            break;
    }
}

Result<std::pair<Op, std::size_t>> decode_op(std::span<const std::uint8_t> in) {
    if (in.empty()) return fail(ErrorKind::protocol, "empty op", at_byte(0));
    std::size_t pos = 1;
    const std::uint8_t code = in[0];
    Op op;
    auto need = [&](std::size_t n) { return pos + n <= in.size(); };
    auto get16 = [&] {
        const auto v = static_cast<std::uint16_t>((in[pos] << 8) | in[pos + 1]);
        pos += 2;
        return v;
    };
    auto truncated = [&] { return fail(ErrorKind::protocol, "truncated op 0x" + std::to_string(code), at_byte(pos)); };
    if (code == 0x10) {
        if (!need(4)) return truncated();
        op.code = OpCode::job_begin;
        op.id = get16();
        op.first_pass = get16();
    } else if (code == 0x11) {
        op.code = OpCode::job_end;
    } else if (code == 0x12) {
        if (!need(2)) return truncated();
        op.code = OpCode::sheet_begin;
        op.id = get16();
        const auto v = get_svar(in, pos);
        if (!v) return truncated();
        op.value = *v;
    } else if (code == 0x13) {
        op.code = OpCode::sheet_end;
    } else if (code == 0x14) {
        if (!need(4)) return truncated();
        op.code = OpCode::pass_begin;
        op.id = get16();
        op.flags = in[pos++];
        op.skip = in[pos++];
        if ((op.flags & ~(pass_flag::back_side | pass_flag::no_feed)) != 0)
            return fail(ErrorKind::protocol, "unknown pass flags", at_byte(pos - 2));
    } else if (code == 0x15) {
        op.code = OpCode::pass_end;
    } else if ((code & 0xF8) == 0x20) {
        op.code = OpCode::move;
        op.axis = (code & 0x01) ? Axis::feed : Axis::carriage;
        op.negative = (code & 0x02) != 0;
        op.continuation = (code & 0x04) != 0;
        if (!need(1)) return truncated();
        const std::uint8_t n = in[pos++];
        if (n == 0 || n > kMaxSegmentsPerOp)
            return fail(ErrorKind::protocol, "move with " + std::to_string(n) + " segments", at_byte(pos - 1));
        for (std::uint8_t i = 0; i < n; ++i) {
            const auto head = get_uvar(in, pos, 0xFFFFF, 3);
            const auto delta = head ? get_svar(in, pos) : std::nullopt;
            const auto add = delta ? get_svar(in, pos) : std::nullopt;
            if (!add) return truncated();
            const unsigned shift = *head & 0x0F;
            const auto count = *head >> 4;
            if (count == 0 || shift > machine::kMaxGridShift)
                return fail(ErrorKind::protocol, "step segment with count " + std::to_string(count) + " and grid " +
                                std::to_string(shift),
                            at_byte(pos));
            const std::uint32_t ref = i == 0 ? 0U : last_interval(op.segments.back());
            const std::uint32_t scaled = (ref >> shift) + static_cast<std::uint32_t>(*delta);
            const std::int64_t add_scaled = *add;
            if ((static_cast<std::uint64_t>(scaled) << shift) > 0xFFFFFFFFULL ||
                add_scaled < -(std::int64_t{1} << (31 - shift)) || add_scaled >= (std::int64_t{1} << (31 - shift)))
                return fail(ErrorKind::protocol, "step segment outside the 32-bit registers", at_byte(pos));
            const std::uint32_t interval = scaled << shift;
            // The first interval must fit the 16-bit timer; later ones are checked as run.
            if ((interval >> machine::kStepFractionBits) < 1)
                return fail(ErrorKind::protocol, "step interval outside the 16-bit timer", at_byte(pos));
            op.segments.push_back({interval, static_cast<std::uint16_t>(count),
                                   static_cast<std::int32_t>(add_scaled * (std::int64_t{1} << shift))});
        }
    } else if (code == 0x30 || code == 0x31) {
        op.code = OpCode::strike;
        op.hammer = code == 0x30 ? plan::Hammer::convex : plan::Hammer::concave;
        const auto wait = get_uvar(in, pos, kMaxStrikeWaitTicks, 3);
        if (!wait) return truncated();
        op.wait_ticks = *wait;
    } else if (code == 0x40) {
        op.code = OpCode::home;
    } else if (code == 0x42 || code == 0x43) {
        op.code = OpCode::seek;
        op.axis = code == 0x42 ? Axis::carriage : Axis::feed;
        const auto v = get_svar(in, pos);
        if (!v) return truncated();
        op.value = *v;
    } else {
        return fail(ErrorKind::protocol, "unknown op code " + std::to_string(code), at_byte(0));
    }
    return std::pair{std::move(op), pos};
}

std::uint32_t segment_steps(std::span<const motion::StepSegment> segments) {
    std::uint32_t n = 0;
    for (const auto& s : segments) n += s.count;
    return n;
}

// The controller's own arithmetic (motion::expand_steps): Q16.16 intervals with a
// fraction accumulator, so simulated time is exactly the firmware's.
std::uint64_t segment_ticks(std::span<const motion::StepSegment> segments) {
    const auto t = motion::expand_steps(segments);
    return t.empty() ? 0 : static_cast<std::uint64_t>(t.back());
}

std::uint64_t tick_of_step(std::span<const motion::StepSegment> segments, std::uint32_t k) {
    if (k == 0) return 0;
    const auto t = motion::expand_steps(segments);
    if (t.empty()) return 0;
    return static_cast<std::uint64_t>(t[std::min<std::size_t>(k, t.size()) - 1]);
}

std::vector<PassRef> pass_table(const plan::JobPlan& plan) {
    std::vector<PassRef> t;
    for (std::size_t s = 0; s < plan.sheets.size(); ++s)
        for (std::size_t p = 0; p < plan.sheets[s].passes.size(); ++p)
            t.push_back({s, p, plan.sheets[s].index});
    return t;
}

std::vector<Op> move_ops(Axis axis, const motion::StepMove& m) {
    // One MOVE op, or several when the segments need more than kMaxMoveOpBytes
    // (the controller runs continuation ops without stopping).
    std::vector<Op> ops;
    Op o;
    o.code = OpCode::move;
    o.axis = axis;
    o.negative = m.steps < 0;
    std::size_t size = 2;  // code and segment count
    std::vector<std::uint8_t> seg;
    for (const auto& s : m.segments) {
        if (s.count == 0) continue;
        seg.clear();
        put_segment(seg, s, o.segments.empty() ? nullptr : &o.segments.back());
        if (!o.segments.empty() &&
            (size + seg.size() > kMaxMoveOpBytes || o.segments.size() == kMaxSegmentsPerOp)) {
            ops.push_back(o);
            o.continuation = true;
            o.segments.clear();
            seg.clear();
            put_segment(seg, s, nullptr);
            size = 2;
        }
        o.segments.push_back(s);
        size += seg.size();
    }
    if (!o.segments.empty()) ops.push_back(std::move(o));
    return ops;
}

std::size_t move_bytes(const motion::StepMove& m) {
    std::vector<std::uint8_t> b;
    for (const auto& o : move_ops(Axis::carriage, m)) append_op(b, o);
    return b.size();
}

namespace {

std::string pass_where(const PassRef& r) {
    return "sheet " + std::to_string(r.sheet) + " pass " + std::to_string(r.pass_in_sheet + 1);
}

// Checks a move the controller will run with 16-bit interval arithmetic.
Result<void> check_move(const motion::StepMove& m, const std::string& where) {
    std::int64_t steps = 0;
    for (const auto& s : m.segments) steps += s.count;
    // Replayed with the controller's arithmetic: every interval must stay in its timer's range.
    if (motion::expand_steps(m.segments).size() != static_cast<std::size_t>(steps))
        return fail(ErrorKind::input, "step interval leaves the 16-bit timer range", where);
    if (steps != std::llabs(m.steps))
        return fail(ErrorKind::input, "move of " + std::to_string(m.steps) + " steps has " + std::to_string(steps) +
                        " steps in its segments",
                    where);
    return {};
}

Op op_of(OpCode c) {
    Op o;
    o.code = c;
    return o;
}
Op strike_op(plan::Hammer h, std::uint32_t wait) {
    Op o;
    o.code = OpCode::strike;
    o.hammer = h;
    o.wait_ticks = std::min(wait, kMaxStrikeWaitTicks);
    return o;
}

class Writer {
public:
    explicit Writer(JobStream& s) : s_(s) {}
    void op(const Op& o) {
        append_op(s_.bytes, o);
        s_.op_ends.push_back(s_.bytes.size());
    }
    void move(Axis axis, const motion::StepMove& m) {
        for (const auto& o : move_ops(axis, m)) op(o);
    }

private:
    JobStream& s_;
};

}  // namespace

Result<JobStream> begin_stream(const plan::JobPlan& plan, const StreamStart& start) {
    std::size_t passes = 0;
    for (const auto& sheet : plan.sheets) passes += sheet.passes.size();
    if (passes > kMaxJobPasses)
        return fail(ErrorKind::input, std::to_string(passes) + " passes in one job; the controller counts at most 65,535", "plan");
    if (start.first_pass > passes) return fail(ErrorKind::input, "start pass beyond the plan", "plan");
    JobStream s;
    s.first_pass = start.first_pass;
    s.end_pass = passes;
    return s;
}

Result<JobStream> encode_job(const plan::JobPlan& plan, std::uint16_t job_id,
                             const StreamStart& start) {
    const auto table = pass_table(plan);
    TACTUS_TRY(begun, begin_stream(plan, start));
    JobStream s = std::move(begun);
    Writer w(s);
    Op o;
    o.code = OpCode::job_begin;
    o.id = job_id;
    o.first_pass = static_cast<std::uint16_t>(start.first_pass);
    w.op(o);
    w.op(op_of(OpCode::home));
    std::int32_t carriage = 0;
    const std::size_t first_sheet_pos =
        start.first_pass < table.size() ? table[start.first_pass].sheet_pos : plan.sheets.size();
    for (std::size_t sp = first_sheet_pos; sp < plan.sheets.size(); ++sp) {
        const auto& sheet = plan.sheets[sp];
        const bool first_sheet = sp == first_sheet_pos;
        const bool restart = first_sheet && start.mid_sheet;
        const std::size_t p0 = first_sheet && start.first_pass < table.size()
                                   ? table[start.first_pass].pass_in_sheet
                                   : 0;
        if (sheet.index > 0xFFFF) return fail(ErrorKind::input, "sheet number above 65535", "plan");
        if (!restart) {
            Op b = op_of(OpCode::sheet_begin);
            b.id = static_cast<std::uint16_t>(sheet.index);
            // The feed counter's value once the sheet is loaded: whatever origin
            // the planner counts feed_step from.
            if (!sheet.passes.empty())
                b.value = sheet.passes[0].feed_step - sheet.passes[0].feed.steps;
            w.op(b);
        }
        for (std::size_t pi = p0; pi < sheet.passes.size(); ++pi) {
            const auto& pass = sheet.passes[pi];
            const PassRef ref{sp, pi, sheet.index};
            const auto where = pass_where(ref);
            if (pass.moves.size() != pass.strikes.size())
                return fail(ErrorKind::input, "pass has " + std::to_string(pass.moves.size()) + " moves for " +
                                std::to_string(pass.strikes.size()) + " strikes",
                            where);
            if (pass.strikes.size() > 255) return fail(ErrorKind::input, "more than 255 strikes in a pass", where);
            TACTUS_TRY_VOID(check_move(pass.feed, where + " feed"));
            const bool restart_pass = restart && pi == p0;
            if (restart_pass) {
                Op seek = op_of(OpCode::seek);
                seek.axis = Axis::feed;
                seek.value = pass.feed_step;
                w.op(seek);
            }
            if (!pass.strikes.empty()) {
                const std::int32_t from = pass.strikes[0].carriage_step - pass.moves[0].steps;
                if (from != carriage) {
                    Op seek = op_of(OpCode::seek);
                    seek.axis = Axis::carriage;
                    seek.value = from;
                    w.op(seek);
                    carriage = from;
                }
            }
            Op b = op_of(OpCode::pass_begin);
            // Index of this pass in the job-wide table.
            std::size_t idx = 0;
            for (std::size_t k = 0; k < sp; ++k) idx += plan.sheets[k].passes.size();
            idx += pi;
            b.id = static_cast<std::uint16_t>(idx);
            b.flags = static_cast<std::uint8_t>(
                (pass.side == plan::Side::back ? pass_flag::back_side : 0) |
                (restart_pass ? pass_flag::no_feed : 0));
            b.skip = restart_pass ? start.skip : 0;
            w.op(b);
            if (!restart_pass) w.move(Axis::feed, pass.feed);
            for (std::size_t i = 0; i < pass.strikes.size(); ++i) {
                const auto mw = where + " strike " + std::to_string(i + 1);
                TACTUS_TRY_VOID(check_move(pass.moves[i], mw));
                carriage += pass.moves[i].steps;
                if (carriage != pass.strikes[i].carriage_step)
                    return fail(ErrorKind::input, "moves reach carriage step " + std::to_string(carriage) +
                                    " but the strike is planned at " +
                                    std::to_string(pass.strikes[i].carriage_step),
                                mw);
                w.move(Axis::carriage, pass.moves[i]);
                w.op(strike_op(pass.strikes[i].hammer, pass.moves[i].settle_ticks));
            }
            w.op(op_of(OpCode::pass_end));
        }
        w.op(op_of(OpCode::sheet_end));
    }
    w.op(op_of(OpCode::job_end));
    return s;
}

std::vector<std::pair<std::size_t, std::size_t>> chunk_stream(const JobStream& stream,
                                                              std::size_t max_payload, std::size_t from) {
    std::vector<std::pair<std::size_t, std::size_t>> chunks;
    std::size_t begin = from;
    std::size_t end = from;
    for (const std::size_t op_end : stream.op_ends) {
        if (op_end <= from) continue;
        // An op larger than max_payload (never above kMaxPayload) travels alone.
        if (op_end - begin > max_payload && end > begin) {
            chunks.emplace_back(begin, end);
            begin = end;
        }
        end = op_end;
    }
    if (end > begin) chunks.emplace_back(begin, end);
    return chunks;
}

}  // namespace tactus::encode
