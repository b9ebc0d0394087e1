// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Documents for the tests of the editor's core (core/edit) and of the widgets
// over it: the bundled samples as editor lines, and a long synthetic book.
#include <stdexcept>
#include <string>
#include <vector>

#include "document/print_page.hpp"
#include "edit/editor_lines.hpp"
#include "edit/live_layout.hpp"
#include "import/import.hpp"
#include "pipeline/pipeline.hpp"

namespace tactus::test {

inline std::string sample_path(const std::string& name) {
    return std::string(TACTUS_RESOURCES_DIR "/samples/") + name;
}

inline std::vector<std::string> sample_lines(const std::string& name) {
    auto doc = import::import_file(sample_path(name));
    return doc ? edit::render_editor_lines(*doc) : std::vector<std::string>{};
}

// A live layout of `lines` (a test's setup: throws when the table is missing).
inline edit::LiveLayout live_layout(const std::vector<std::string>& lines, const std::string& table = "en-ueb-g2.ctb",
                                    layout::LayoutOptions options = {}, edit::Dialect dialect = edit::Dialect::markdown) {
    auto l = edit::LiveLayout::create(table, options);
    if (!l) throw std::runtime_error(l.error().to_string());
    l->set_dialect(dialect);
    l->reset(lines);
    return std::move(*l);
}

// The layout's editor lines, in order.
inline std::vector<std::string> lines_of(const edit::LiveLayout& l) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < l.line_count(); ++i) out.push_back(l.line(i));
    return out;
}

// The document the editor lines stand for, as core sees it.
inline document::Document document_of(const std::vector<std::string>& lines) {
    document::Document d;
    std::string previous_label(document::first_print_page);
    bool started = false;
    for (const auto& l : lines) {
        if (auto b = edit::parse_editor_line(l)) {
            if (b->kind == document::BlockKind::print_page_break) {
                // The one numbering rule (document/print_page.hpp).
                auto label = document::page_break_label(b->label, previous_label, started);
                if (!label) continue;
                b->label_counted = b->label.empty();
                b->label = previous_label = *label;
            }
            if (b->kind != document::BlockKind::braille_page_break) started = true;
            d.blocks.push_back(std::move(*b));
        }
    }
    return d;
}

// A long document with headings, lists, emphasis and print page breaks.
inline std::vector<std::string> synthetic_book(int paragraphs) {
    static const char* words[] = {"the",  "braille", "reader",  "finds", "each",  "cell",     "with",
                                  "light", "fingers", "and",    "knowledge", "of", "contractions", "into",
                                  "sheet", "embosser", "hammer", "paper", "dots",  "interpoint"};
    std::vector<std::string> out;
    unsigned seed = 7;
    const auto next = [&seed] { return seed = seed * 1103515245u + 12345u, (seed >> 16) & 0x7fff; };
    int page = 1;
    for (int p = 0; p < paragraphs; ++p) {
        if (p % 40 == 0) out.push_back("# Chapter " + std::to_string(p / 40 + 1));
        if (p % 17 == 5) out.push_back("<!-- pagebreak " + std::to_string(++page) + " -->");
        std::string line = p % 9 == 3 ? "- " : "";
        const auto n = 8 + next() % 60;
        for (unsigned w = 0; w < n; ++w) {
            if (w) line += ' ';
            std::string word = words[next() % 20];
            if (next() % 23 == 0) word = "*" + word + "*";
            line += word;
        }
        out.push_back(line + ".");
    }
    return out;
}

}  // namespace tactus::test
