// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A move in whole motor steps with its step timing: what the planner produces,
// the estimate replays and the encoder sends.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <vector>

namespace tactus::motion {

// Klipper-style step compression: `count` steps, the first `interval` timer ticks
// after the previous step, each following interval `add` ticks longer (negative:
// shorter). Ticks are the 89C52 timer clock (machine::kTickHz).
//
// interval and add are fixed point with 16 fractional bits (Q16.16): a carriage
// cruising at 38.4 ticks per step, or an acceleration ramp whose interval shrinks
// by 0.3 ticks per step, is then one segment instead of one every few steps
// (whole-tick intervals made the schedule larger than a 115200-baud link can
// carry). The controller still only adds: per step it adds the 16-bit fraction of
// `interval` into a fraction accumulator that starts at 0 with each segment, loads
// its timer with the integer part plus the carry, and adds `add` (32-bit) to
// `interval`. expand_steps() in motion/steps.hpp is that arithmetic, exactly.
struct StepSegment {
    std::uint32_t interval_q16 = 0;  // ticks << 16; integer part 1..65535
    std::uint16_t count = 0;
    std::int32_t add_q16 = 0;  // ticks << 16 added to the interval after each step
    bool operator==(const StepSegment&) const = default;
};

// A move's step segments, a value whose copies share one immutable array:
// copying a StepMove (the planner copies a tuned move into every strike that
// uses it) costs a reference count, not an allocation. The array lives as long
// as any copy does, whatever thread or plan holds it. Mutation copies the array
// first when another StepSegments shares it (copy on write); a reference that a
// mutating accessor returned is valid until this object is next copied,
// assigned or mutated.
class StepSegments {
public:
    using value_type = StepSegment;
    using const_iterator = const StepSegment*;
    using iterator = const_iterator;
    using size_type = std::size_t;

    StepSegments() = default;
    StepSegments(std::vector<StepSegment> v) {  // NOLINT(google-explicit-constructor): a vector is segments
        if (!v.empty()) v_ = std::make_shared<std::vector<StepSegment>>(std::move(v));
    }
    StepSegments(std::initializer_list<StepSegment> l) : StepSegments(std::vector<StepSegment>(l)) {}

    [[nodiscard]] const StepSegment* data() const { return v_ ? v_->data() : nullptr; }
    [[nodiscard]] std::size_t size() const { return v_ ? v_->size() : 0; }
    [[nodiscard]] bool empty() const { return size() == 0; }
    [[nodiscard]] const StepSegment* begin() const { return data(); }
    [[nodiscard]] const StepSegment* end() const { return data() + size(); }
    [[nodiscard]] const StepSegment& operator[](std::size_t i) const { return (*v_)[i]; }
    [[nodiscard]] const StepSegment& front() const { return v_->front(); }
    [[nodiscard]] const StepSegment& back() const { return v_->back(); }

    // Mutation (copy on write).
    StepSegment& operator[](std::size_t i) { return own()[i]; }
    StepSegment& back() { return own().back(); }
    void push_back(const StepSegment& s) { own().push_back(s); }
    void clear() { v_.reset(); }

    friend bool operator==(const StepSegments& a, const StepSegments& b) {
        return a.v_ == b.v_ || std::equal(a.begin(), a.end(), b.begin(), b.end());
    }

private:
    std::vector<StepSegment>& own() {
        if (!v_) {
            v_ = std::make_shared<std::vector<StepSegment>>();
        } else if (v_.use_count() != 1) {
            v_ = std::make_shared<std::vector<StepSegment>>(*v_);
        } else {
            // The last other copy may have been released by another thread:
            // its reads happen before our writes.
            std::atomic_thread_fence(std::memory_order_acquire);
        }
        return *v_;
    }
    std::shared_ptr<std::vector<StepSegment>> v_;
};

// One axis move in whole motor steps, with its step timing.
struct StepMove {
    std::int32_t steps = 0;  // signed: direction is the sign
    StepSegments segments;
    double duration_s = 0;
    // Ticks at rest between the last step and the end of duration_s: the
    // planned settle before a strike, which the controller waits out.
    std::uint32_t settle_ticks = 0;
    bool operator==(const StepMove&) const = default;
};

}  // namespace tactus::motion
