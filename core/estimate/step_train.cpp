// SPDX-License-Identifier: GPL-3.0-or-later
#include "estimate/step_train.hpp"

#include <algorithm>

#include "machine/limits.hpp"
#include "motion/steps.hpp"

namespace tactus::estimate {

motion::MoveShape step_train_shape(std::span<const motion::StepSegment> segments, double steps_per_mm,
                                 double duration_s) {
    const auto ticks = motion::expand_steps(segments);
    motion::MoveShape s;
    s.distance = static_cast<double>(ticks.size()) / steps_per_mm;
    double t = 0, p = 0;
    const auto line_to = [&](double t1, double p1) {
        if (t1 > t) {
            s.pieces.push_back(motion::Piece{t, t1 - t, motion::Derivs{p, (p1 - p) / (t1 - t), 0, 0, 0, 0}});
            t = t1;
        }
        p = p1;
    };
    for (std::size_t k = 0; k < ticks.size(); ++k)
        line_to(static_cast<double>(ticks[k]) / machine::kTickHz, (static_cast<double>(k) + 0.5) / steps_per_mm);
    // The last half step takes as long as the step before it would.
    const double last = ticks.size() > 1 ? static_cast<double>(ticks.back() - ticks[ticks.size() - 2]) / machine::kTickHz
                                         : 1e-3;
    line_to(t + 0.5 * last, s.distance);
    s.duration = std::max(duration_s, t);
    if (s.duration > t) s.pieces.push_back(motion::Piece{t, s.duration - t, motion::Derivs{s.distance, 0, 0, 0, 0, 0}});
    return s;
}

}  // namespace tactus::estimate
