// SPDX-License-Identifier: GPL-3.0-or-later
#include "layout/braille_pages.hpp"

#include <algorithm>

namespace tactus::layout {
namespace {

// One source page: the rows of the braille blocks between two page breaks.
struct SourcePage {
    const document::Block* first = nullptr;
    std::vector<const document::BrailleLine*> rows;  // into the document's blocks: no copy
    int source_line = 0;
    std::size_t section = 0;
    std::size_t first_block = 0;  // the page's first braille block
};

std::vector<SourcePage> source_pages(const document::Document& doc) {
    std::vector<SourcePage> pages;
    std::size_t section = 0;
    bool open = false;
    for (std::size_t i = 0; i < doc.blocks.size(); ++i) {
        while (section + 1 < doc.braille_sections.size() && doc.braille_sections[section + 1].first_block <= i) {
            ++section;
            open = false;  // a section always starts a page
        }
        const auto& b = doc.blocks[i];
        if (b.kind == document::BlockKind::braille_page_break) {
            open = false;
            continue;
        }
        if (b.kind != document::BlockKind::braille) continue;
        if (!open) {
            pages.push_back(SourcePage{&b, {}, b.source_line, section, i});
            open = true;
        }
        for (const auto& row : b.braille_lines) pages.back().rows.push_back(&row);
    }
    return pages;
}

int longest_row(const std::vector<const document::BrailleLine*>& rows) {
    std::size_t n = 0;
    for (const auto* r : rows) n = std::max(n, r->size());
    return static_cast<int>(n);
}

// Each section's page: its own grid (PEF cols/rows in force for it, its
// volume's unless it overrides them), at least as large as its pages' rows
// (an edit can make a row longer than the file's cols). Without sections (a
// BRF) one entry: the file's grid, at least its pages.
struct SectionPage {
    int cols = 0;
    int rows = 0;
};
std::vector<SectionPage> section_pages(const document::Document& doc, const std::vector<SourcePage>& pages) {
    std::vector<SectionPage> out(std::max<std::size_t>(doc.braille_sections.size(), 1));
    for (std::size_t s = 0; s < doc.braille_sections.size(); ++s)
        out[s] = {doc.braille_sections[s].cols, doc.braille_sections[s].rows};
    if (doc.braille_sections.empty() && doc.braille_grid) out[0] = {doc.braille_grid->cols, doc.braille_grid->rows};
    for (const auto& p : pages) {
        auto& g = out[std::min(p.section, out.size() - 1)];
        g.cols = std::max(g.cols, longest_row(p.rows));
        g.rows = std::max(g.rows, static_cast<int>(p.rows.size()));
    }
    return out;
}

}  // namespace

bool is_ready_braille(const document::Document& doc) {
    bool any = false;
    for (const auto& b : doc.blocks) {
        switch (b.kind) {
            case document::BlockKind::braille: any = true; break;
            case document::BlockKind::braille_page_break: break;
            default: return false;
        }
    }
    return any;
}

std::optional<BraillePageMisfit> find_braille_misfit(const document::Document& doc, const LayoutOptions& target) {
    const auto& g = target.geometry;
    const auto pages = source_pages(doc);
    const auto grids = section_pages(doc, pages);
    const bool sections = !doc.braille_sections.empty();
    for (std::size_t p = 0; p < pages.size(); ++p) {
        const int rows = static_cast<int>(pages[p].rows.size());
        const int cols = longest_row(pages[p].rows);
        // A PEF page is its section's grid (each page is that size on paper,
        // keep_braille_pages lays it out so); a BRF page is its rows.
        const auto& grid = grids[std::min(pages[p].section, grids.size() - 1)];
        const int need_rows = sections ? grid.rows : rows;
        const int need_cols = sections ? grid.cols : cols;
        if (need_rows <= g.lines_per_page && need_cols <= g.cells_per_line) continue;
        BraillePageMisfit m{.page = static_cast<int>(p + 1),
                            .rows = rows,
                            .cols = cols,
                            .file_cols = sections ? grid.cols : doc.braille_grid ? doc.braille_grid->cols : cols,
                            .file_rows = sections ? grid.rows : doc.braille_grid ? doc.braille_grid->rows : rows,
                            .target_cols = g.cells_per_line,
                            .target_rows = g.lines_per_page,
                            .source_line = pages[p].source_line,
                            .volumes = {}};
        // The file's page, volume by volume: a volume is as large as its largest section.
        if (!sections) {
            m.volumes.push_back({1, std::max(grids[0].cols, 1), std::max(grids[0].rows, 1)});
        } else {
            for (std::size_t s = 0; s < doc.braille_sections.size(); ++s) {
                if (s == 0 || doc.braille_sections[s].starts_volume)
                    m.volumes.push_back({static_cast<int>(m.volumes.size()) + 1, 0, 0});
                m.volumes.back().cols = std::max(m.volumes.back().cols, grids[s].cols);
                m.volumes.back().rows = std::max(m.volumes.back().rows, grids[s].rows);
            }
        }
        for (auto& v : m.volumes) v.fits = v.cols <= g.cells_per_line && v.rows <= g.lines_per_page;
        return m;
    }
    return std::nullopt;
}

Result<void> check_braille_fits(const document::Document& doc, const LayoutOptions& target) {
    const auto m = find_braille_misfit(doc, target);
    if (!m) return {};
    return fail(ErrorKind::input, "braille page " + std::to_string(m->page) + " has " + std::to_string(m->rows) + " rows of up to " +
                    std::to_string(m->cols) + " cells (the file's page is " + std::to_string(m->file_cols) +
                    " cells x " + std::to_string(m->file_rows) + " lines), but the page holds " +
                    std::to_string(m->target_cols) + " cells x " + std::to_string(m->target_rows) +
                    " lines; stopped before anything was laid out or embossed. Use a printer or --preset whose page is"
                    " at least that large, or --reflow to lay the braille out again on this page",
                m->source_line > 0 ? std::to_string(m->source_line) : std::string{});
}

Result<PagedDocument> keep_braille_pages(const document::Document& doc, const LayoutOptions& target,
                                         std::vector<BlockPlace>* places) {
    if (auto ok = check_braille_fits(doc, target); !ok) return std::unexpected(located(ok.error(), doc.source_name));
    const auto pages = source_pages(doc);
    PagedDocument out;
    out.metadata = doc.metadata;
    out.geometry.interpoint = target.geometry.interpoint;
    // The sheets' page holds every section's page (the largest of them).
    const auto grids = section_pages(doc, pages);
    int cols = 0, rows = 0;
    bool eight_dot = false;
    for (const auto& p : pages)
        for (const auto* r : p.rows)
            eight_dot = eight_dot || std::ranges::any_of(*r, [](document::Cell c) { return (c.dots & 0xC0) != 0; });
    for (const auto& grid : grids) {
        cols = std::max(cols, grid.cols);
        rows = std::max(rows, grid.rows);
    }
    if (doc.braille_grid) {
        cols = std::max(cols, doc.braille_grid->cols);
        rows = std::max(rows, doc.braille_grid->rows);
    }
    out.geometry.cells_per_line = std::max(cols, 1);
    out.geometry.lines_per_page = std::max(rows, 1);
    out.geometry.eight_dot = eight_dot || target.geometry.eight_dot;

    const bool interpoint = out.geometry.interpoint;
    const auto blank_back = [&] {
        Page filler;
        filler.filler = true;
        filler.braille_number = static_cast<int>(out.pages.size()) + 1;
        filler.lines.assign(static_cast<std::size_t>(out.geometry.lines_per_page), document::BrailleLine{});
        out.pages.push_back(std::move(filler));
    };
    std::size_t section = static_cast<std::size_t>(-1);
    if (places) places->assign(doc.blocks.size(), BlockPlace{});
    std::size_t placed = 0;  // blocks before this have their place
    for (const auto& p : pages) {
        const bool section_duplex =
            p.section < doc.braille_sections.size() ? doc.braille_sections[p.section].duplex : interpoint;
        if (p.section != section) {
            section = p.section;
            // A new section starts on a new sheet: never on the back of the last one.
            if (interpoint && out.pages.size() % 2 == 1) blank_back();
            const bool volume = p.section < doc.braille_sections.size() && doc.braille_sections[p.section].starts_volume;
            const auto& grid = grids[std::min(p.section, grids.size() - 1)];
            out.sections.push_back(PageSection{.first_page = out.pages.size(),
                                               .duplex = section_duplex,
                                               .starts_volume = volume || out.sections.empty(),
                                               .cols = grid.cols,
                                               .rows = grid.rows,
                                               .rowgap = p.section < doc.braille_sections.size()
                                                             ? doc.braille_sections[p.section].rowgap
                                                             : 0});
        }
        if (places) {
            // The blocks before the page's first row (its page break) land where it does;
            // the page's blocks, row by row.
            for (; placed < p.first_block; ++placed) (*places)[placed] = BlockPlace{out.pages.size(), 0};
            int row = 0;
            for (; placed < doc.blocks.size() && row < static_cast<int>(p.rows.size()); ++placed) {
                (*places)[placed] = BlockPlace{out.pages.size(), row};
                const auto& b = doc.blocks[placed];
                if (b.kind == document::BlockKind::braille) row += static_cast<int>(b.braille_lines.size());
            }
        }
        Page page;
        page.braille_number = static_cast<int>(out.pages.size()) + 1;
        page.lines.reserve(static_cast<std::size_t>(out.geometry.lines_per_page));
        for (const auto* r : p.rows) page.lines.push_back(*r);
        page.lines.resize(static_cast<std::size_t>(out.geometry.lines_per_page));
        out.pages.push_back(std::move(page));
        // A single-sided section on interpoint paper: every page has its own sheet.
        if (interpoint && !section_duplex) blank_back();
    }
    if (places) {
        // Blocks after the last row: the end of the last page.
        const BlockPlace end = out.pages.empty() ? BlockPlace{}
                                                 : BlockPlace{out.pages.size() - 1, static_cast<int>(pages.back().rows.size())};
        for (; placed < doc.blocks.size(); ++placed) (*places)[placed] = end;
    }
    if (doc.braille_sections.empty()) out.sections.clear();  // BRF: one stream of pages
    return out;
}

}  // namespace tactus::layout
