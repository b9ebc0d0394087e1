// SPDX-License-Identifier: GPL-3.0-or-later
// A sheet's dots: where the feed and the head stand for each, in striking order.
#include <algorithm>
#include <string>
#include <vector>

#include "plan/planner_internal.hpp"
#include "common/try.hpp"

namespace tactus::plan {

namespace {
using Hit = Planner::Hit;

Result<void> check_page(const profile::PrinterProfile& p, const layout::Page& page, std::size_t index) {
    const auto& g = p.geometry;
    const std::string where = "page " + std::to_string(index + 1);
    if (page.lines.size() > static_cast<std::size_t>(g.lines_per_page))
        return fail(ErrorKind::input, "has " + std::to_string(page.lines.size()) + " lines, the profile allows " +
                        std::to_string(g.lines_per_page) + " (geometry.lines_per_page)",
                    where);
    for (std::size_t l = 0; l < page.lines.size(); ++l) {
        const auto& line = page.lines[l];
        const auto lw = where + " line " + std::to_string(l + 1);
        if (line.size() > static_cast<std::size_t>(g.cells_per_line))
            return fail(ErrorKind::input, "has " + std::to_string(line.size()) + " cells, the profile allows " +
                            std::to_string(g.cells_per_line) + " (geometry.cells_per_line)",
                        lw);
        if (!g.eight_dot)
            for (std::size_t c = 0; c < line.size(); ++c)
                if (line[c].dots & 0xC0)
                    return fail(ErrorKind::input, "cell " + std::to_string(c + 1) +
                                    " has dot 7 or 8 but the profile is six-dot (geometry.eight_dot)",
                                lw);
    }
    for (std::size_t i = 0; i < page.graphic.size(); ++i) {
        const auto& d = page.graphic[i];
        if (!(d.x_mm >= 0 && d.x_mm <= p.paper.width_mm && d.y_mm >= 0 && d.y_mm <= p.paper.height_mm))
            return fail(ErrorKind::input, "graphic dot " + std::to_string(i + 1) + " at " + std::to_string(d.x_mm) + ", " +
                            std::to_string(d.y_mm) + " mm is off the paper (" + std::to_string(p.paper.width_mm) +
                            " x " + std::to_string(p.paper.height_mm) + " mm)",
                        where);
    }
    return {};
}

Hit hit_at(const profile::PrinterProfile& p, const motion::StepAxis& carriage, const motion::StepAxis& feed, Side side,
           const DotPlace& place) {
    return {feed.steps_for(place.paper_y_mm),
            carriage.steps_for(carriage_target_mm(p, hammer_for(side), place.paper_x_mm)), side, place};
}

Hit make_hit(const profile::PrinterProfile& p, const motion::StepAxis& carriage, const motion::StepAxis& feed,
             Side side, int line, int cell, int dot) {
    return hit_at(p, carriage, feed, side, dot_place(p, side, line, cell, dot));
}

}  // namespace

Planner::HitTable::HitTable(const profile::PrinterProfile& p, const motion::StepAxis& carriage,
                            const motion::StepAxis& feed)
    : lines(std::max(0, p.geometry.lines_per_page)), cells(std::max(0, p.geometry.cells_per_line)) {
    const int dots = p.geometry.eight_dot ? 8 : 6;
    for (Side side : {Side::front, Side::back}) {
        auto& v = hits[side == Side::front ? 0 : 1];
        v.resize(static_cast<std::size_t>(lines) * static_cast<std::size_t>(cells) * 8);
        for (int l = 0; l < lines; ++l)
            for (int c = 0; c < cells; ++c)
                for (int d = 1; d <= dots; ++d)
                    v[static_cast<std::size_t>((l * cells + c) * 8 + d - 1)] = make_hit(p, carriage, feed, side, l, c, d);
    }
}

// Every dot of one sheet, sorted by feed position then carriage position.
// Returns a reference to a buffer of this thread that the next call reuses
// (a sheet's dots without a reallocation per sheet).
Result<const std::vector<Hit>*> collect_hits(const profile::PrinterProfile& p, const layout::PagedDocument& doc,
                                             std::size_t sheet_number, const motion::StepAxis& carriage,
                                             const motion::StepAxis& feed, bool check,
                                             const Planner::HitTable* table) {
    thread_local std::vector<Hit> hits, sorted;
    struct Key {
        std::int32_t feed_step, head_step;
        std::uint32_t index;
    };
    thread_local std::vector<Key> keys;
    hits.clear();
    const layout::Sheet sheet = doc.sheet(sheet_number);
    const int dots = p.geometry.eight_dot ? 8 : 6;
    for (const auto& [side, page] : {std::pair{Side::front, sheet.front}, std::pair{Side::back, sheet.back}}) {
        if (!page) continue;
        const auto index = static_cast<std::size_t>(page - doc.pages.data());
        if (check)
            TACTUS_TRY_VOID(check_page(p, *page, index));
        for (std::size_t l = 0; l < page->lines.size(); ++l) {
            const auto& line = page->lines[l];
            for (std::size_t c = 0; c < line.size(); ++c) {
                const document::Cell cell = line[c];
                if (cell.blank()) continue;
                for (int d = 1; d <= dots; ++d) {
                    if (!cell.has_dot(d)) continue;
                    if (const Hit* known = table ? table->find(side, l, c, d) : nullptr)
                        hits.push_back(*known);
                    else
                        hits.push_back(make_hit(p, carriage, feed, side, static_cast<int>(l), static_cast<int>(c), d));
                }
            }
        }
        // A graphic's dots, struck where they are (the graphic stage put them on the step grid).
        for (const auto& gd : page->graphic)
            hits.push_back(hit_at(p, carriage, feed, side, place_on_paper(p, side, gd.x_mm, gd.y_mm)));
    }
    // By feed position, then carriage position. The sort runs on 12-byte keys
    // carrying the dot's index, then the dots are gathered: std::sort's moves
    // depend only on its comparisons, which give the same answers as on the
    // dots, so the order is the same, ties included.
    sorted.resize(hits.size());
    // First as one 64-bit integer per dot (feed, carriage, index, from the
    // smallest of each): when no two dots share both positions, the order is
    // the only one sorted by position, whatever sorts it.
    thread_local std::vector<std::uint64_t> packed;
    if (!hits.empty() && hits.size() < (std::size_t{1} << 24)) {
        std::int32_t feed_min = hits[0].feed_step, feed_max = feed_min, head_min = hits[0].head_step,
                     head_max = head_min;
        for (const auto& h : hits) {
            feed_min = std::min(feed_min, h.feed_step), feed_max = std::max(feed_max, h.feed_step);
            head_min = std::min(head_min, h.head_step), head_max = std::max(head_max, h.head_step);
        }
        constexpr std::int64_t kRange = std::int64_t{1} << 20;
        if (std::int64_t{feed_max} - feed_min < kRange && std::int64_t{head_max} - head_min < kRange) {
            packed.resize(hits.size());
            for (std::size_t i = 0; i < hits.size(); ++i)
                packed[i] = static_cast<std::uint64_t>(hits[i].feed_step - feed_min) << 44 |
                            static_cast<std::uint64_t>(hits[i].head_step - head_min) << 24 | i;
            std::sort(packed.begin(), packed.end());
            bool tie = false;
            for (std::size_t i = 1; i < packed.size() && !tie; ++i) tie = packed[i] >> 24 == packed[i - 1] >> 24;
            if (!tie) {
                for (std::size_t i = 0; i < packed.size(); ++i) sorted[i] = hits[packed[i] & 0xFFFFFF];
                return &sorted;
            }
        }
    }
    // Dots that share both positions: their order is what std::sort leaves
    // them in, as it always was.
    keys.resize(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i)
        keys[i] = {hits[i].feed_step, hits[i].head_step, static_cast<std::uint32_t>(i)};
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
        return a.feed_step != b.feed_step ? a.feed_step < b.feed_step : a.head_step < b.head_step;
    });
    for (std::size_t i = 0; i < keys.size(); ++i) sorted[i] = hits[keys[i].index];
    return &sorted;
}


}  // namespace tactus::plan
