// SPDX-License-Identifier: GPL-3.0-or-later
#include "machine/firmware_tables.hpp"

#include <algorithm>

namespace tactus::machine {

std::uint16_t RampTable::interval(std::uint32_t k, std::uint32_t n) const {
    const auto r1 = static_cast<std::uint32_t>(intervals.size());  // R + 1
    const std::uint32_t i = std::min({k, n + 2 - k, r1});
    return intervals[i - 1];
}

std::uint64_t RampTable::move_ticks(std::uint32_t n) const {
    std::uint64_t t = 0;
    for (std::uint32_t k = 1; k <= n; ++k) t += interval(k, n);
    return t;
}

}  // namespace tactus::machine
