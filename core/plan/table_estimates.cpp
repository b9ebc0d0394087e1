// SPDX-License-Identifier: GPL-3.0-or-later
// The residual estimates of table moves that every planner of the process
// shares (plan/planner.hpp, TableEstimates).
#include <algorithm>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <utility>
#include <vector>

#include "plan/planner.hpp"
#include "profile/firmware_tables.hpp"

namespace tactus::plan {

struct TableEstimates::Entry {
    std::mutex mutex;
    std::unordered_map<std::uint32_t, estimate::TuneChoice> moves;
};

namespace {
struct SharedTableEstimates {
    std::mutex mutex;
    std::vector<std::pair<TableEstimates::Key, std::shared_ptr<TableEstimates::Entry>>> entries;  // oldest first
};
SharedTableEstimates& shared_table_estimates() {
    static SharedTableEstimates s;
    return s;
}
}  // namespace

TableEstimates::Key TableEstimates::key_for(const profile::PrinterProfile& p, const machine::FirmwareTables& t) {
    Key k;
    k.carriage = t.carriage;
    k.settle_ticks = profile::strike_timing(p).settle_ticks;
    k.steps_per_mm = p.carriage.steps_per_mm;
    k.dynamics = p.dynamics;
    k.vibration = p.vibration;
    k.dwell_s = p.head.dwell_s;
    return k;
}

std::shared_ptr<TableEstimates::Entry> TableEstimates::entry(const Key& key) {
    auto& s = shared_table_estimates();
    const std::lock_guard lock(s.mutex);
    for (const auto& [k, e] : s.entries)
        if (k == key) return e;
    if (s.entries.size() >= kMaxKeys) s.entries.erase(s.entries.begin());
    s.entries.emplace_back(key, std::make_shared<Entry>());
    return s.entries.back().second;
}

std::optional<estimate::TuneChoice> TableEstimates::find(Entry& e, std::uint32_t steps) {
    const std::lock_guard lock(e.mutex);
    if (auto it = e.moves.find(steps); it != e.moves.end()) return it->second;
    return std::nullopt;
}

void TableEstimates::store(Entry& e, const estimate::TuneChoice& c) {
    const std::lock_guard lock(e.mutex);
    e.moves.emplace(c.steps, c);
}

std::size_t TableEstimates::keys() {
    auto& s = shared_table_estimates();
    const std::lock_guard lock(s.mutex);
    return s.entries.size();
}

std::size_t TableEstimates::moves() {
    auto& s = shared_table_estimates();
    const std::lock_guard lock(s.mutex);
    std::size_t n = 0;
    for (const auto& [k, e] : s.entries) {
        const std::lock_guard l(e->mutex);
        n += e->moves.size();
    }
    return n;
}

void TableEstimates::clear() {
    auto& s = shared_table_estimates();
    const std::lock_guard lock(s.mutex);
    s.entries.clear();
}

}  // namespace tactus::plan
