// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The head's ringing carried from strike to strike. For the nominal head model
// and every model of the damping/frequency band, the head's error state
// relative to where the command rests (positions minus the resting command,
// velocities) is advanced exactly through each move, each rest and each
// hammer dwell, so a strike's residual includes whatever the moves before it
// left ringing instead of assuming the head starts every move at rest.
//
// The models are linear and do not depend on where the carriage stands, so a
// move of d steps in direction s changes the error state z as
//   z <- Phi(T) z + s w,
// Phi(T) = exp(A T) the free motion over the move's duration and w the error
// state a head at rest would have at the end of that move: both computed once
// per distinct move (prepare), exactly (simulate.hpp). A rest of t seconds is
// z <- exp(A t) z. docs/motion.md, "Ringing".
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "estimate/dynamics.hpp"
#include "motion/motion.hpp"
#include "motion/step_move.hpp"
#include "profile/profile.hpp"

namespace tactus::estimate {

// The grid of machines a worst case is taken over: damping x 5 values from
// 1 - damping_band to 1 + damping_band, natural frequency x 9 values from
// 1 - frequency_band to 1 + frequency_band (corners included).
std::vector<ModelVariant> band_variants(const profile::Vibration& v);

// Timer ticks (machine::kTickHz) are the unit of settle searches: a settle is
// what the controller waits, in ticks, before the hammer fires.
class Ringing {
public:
    explicit Ringing(const profile::PrinterProfile& p);
    ~Ringing();
    Ringing(Ringing&&) noexcept;
    Ringing& operator=(Ringing&&) noexcept;

    // A move's effect on every model (opaque; shared by every strike that uses it).
    struct Move;
    [[nodiscard]] std::shared_ptr<const Move> prepare(const motion::MoveShape& m) const;
    // The same as prepare(step_train_shape(segments, steps_per_mm, duration_s))
    // (estimate/step_train.hpp), computed without a piece per step: the
    // command between two steps is a straight line, so a run of equal step
    // intervals is one affine map on (state, position, 1) per machine, raised
    // to the run's length by squaring. Exact in arithmetic (only the rounding
    // differs: tested to 1e-6 um); a long table move costs a few dozen small
    // products per machine instead of one per step.
    [[nodiscard]] std::shared_ptr<const Move> prepare_step_train(std::span<const motion::StepSegment> segments,
                                                                 double steps_per_mm, double duration_s) const;
    // `m` followed by `ticks` at rest, as one move (a tuned move and its settle).
    [[nodiscard]] std::shared_ptr<const Move> then_rest(const Move& m, std::uint64_t ticks) const;

    struct Residual {
        double nominal_um = 0;  // the nominal machine
        double worst_um = 0;    // the worst machine of the band
    };

    // The head at rest on the command (after homing).
    void reset();
    // Through a move in direction dir (+1 or -1).
    void move(const Move& m, int dir);
    // The command held for `seconds`.
    void rest(double seconds);
    void rest_ticks(std::uint64_t ticks);
    // `offset_mm` below: where the command rests past the dot the hammer must
    // hit (command minus dot, mm, in carriage coordinates; 0: on the dot). The
    // residual is then |head - dot|, the error state z staying relative to
    // the command. docs/motion.md, "Aim past the dot".
    //
    // Largest |head - dot| while a hammer strikes now (through the dwell,
    // 33 instants), um.
    [[nodiscard]] Residual residual(double offset_mm = 0);
    // Is the worst residual of a strike made after `ticks` more at rest within `target_um`?
    [[nodiscard]] bool within_after(std::uint64_t ticks, double target_um, double offset_mm = 0);
    // The fewest ticks at rest, at least `from`, after which a strike's worst
    // residual is within `target_um` (`from` itself when it is; else rests
    // grow from `from` until one passes, and a bisection to the tick finds
    // the first that passes after the last that failed); -1 when none up to
    // `max_ticks` does.
    [[nodiscard]] std::int64_t settle_ticks(double target_um, std::uint64_t from, std::uint64_t max_ticks,
                                            double offset_mm = 0);
    // settle_ticks from 0 for a strike right after `m` (direction +1), the head at rest before it.
    [[nodiscard]] std::int64_t settle_after(const Move& m, double target_um, std::uint64_t max_ticks,
                                            double offset_mm = 0) const;
    // The hammer dwell passes (the command held); folded into the next move's product.
    void dwell();

    // The residual of a strike right after `m` (plus `rest_s` at rest), the
    // head at rest before it: what auto-tune compares.
    [[nodiscard]] Residual from_rest(const Move& m, double rest_s = 0, double offset_mm = 0) const;
    [[nodiscard]] std::size_t models() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace tactus::estimate
