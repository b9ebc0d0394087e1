// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A document laid out as a braille book (BANA Braille Formats 2016; each rule
// and its section in docs/layout.md, "Books"): volumes split at chapter or
// section headings near a target size, each volume with its own preliminary
// pages (a title page with "volume N of M", numbered t1, t2, ...; the
// contents with print and braille page numbers, p1, p2, ...), running heads on the body
// pages after each volume's first, body page numbers going on from volume to
// volume. Each rule is an option here with the rules' default.
#include <string>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include <functional>
#include <optional>

#include "layout/layout_options.hpp"
#include "layout/page.hpp"
#include "translate/translator.hpp"

namespace tactus::pipeline {

struct BookOptions {
    // Volumes are split near this many sheets (preliminary pages included),
    // and only when the book is longer than one volume.
    int sheets_per_volume = 70;
    // Headings at this level or above (1 = chapters) may start a volume.
    int split_level = 2;
    bool title_page = true;
    bool contents = true;
    int contents_depth = 2;  // heading levels listed in the contents
    bool running_heads = true;
    // The title page's lines; empty: from the document's metadata (EPUB,
    // DTBook, PEF: title, creator, publisher, date), else left out.
    std::string title;
    std::string author;
    std::string publisher;
    std::string year;
    std::string transcriber;  // "Transcribed by ..."; empty: no such line
};

// One volume's pages in PagedDocument::pages: its preliminary pages, then its body.
struct VolumeRange {
    std::size_t first_page = 0;
    // Where the p-numbered preliminary pages (the contents) start: the pages
    // before it are the t-numbered title page (page_labels reads this).
    std::size_t contents_first_page = 0;
    std::size_t body_first_page = 0;
    std::size_t end_page = 0;  // one past its last page
};

struct BookLayout {
    layout::PagedDocument pages;  // sections: each volume starts one (starts_volume)
    std::vector<VolumeRange> volumes;
};

// The translator gives the body, the title page and contents text and the
// page numbers. `translation_workers` above 1 translates the body in that many
// forked processes (pipeline/translation_workers.hpp), as the plain layout
// does; the pages are the same either way.
Result<BookLayout> lay_out_book(const document::Document& document, const layout::LayoutOptions& layout,
                                const BookOptions& book, const translate::Translator& translator,
                                unsigned translation_workers = 1);

// Told, after each block of the body is translated (most of the work), how
// many of all are done; returning true stops the layout (the document changed,
// the user cancelled).
using BookProgress = std::function<bool(std::size_t done, std::size_t total)>;
// As above, with progress; nullopt when `progress` stopped it.
Result<std::optional<BookLayout>> lay_out_book(const document::Document& document, const layout::LayoutOptions& layout,
                                               const BookOptions& book, const translate::Translator& translator,
                                               const BookProgress& progress, unsigned translation_workers = 1);

}  // namespace tactus::pipeline
