// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The front half of the pipeline in one call: import -> translate -> layout.
// Translation (liblouis, one thread at a time) and layout run concurrently: a
// translator thread hands finished blocks to the paginator on the caller's thread
// through a bounded queue; a big document is translated by several
// worker processes instead (pipeline/translation_workers.hpp).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include "import/import.hpp"
#include "layout/layout_options.hpp"
#include "layout/page.hpp"
#include "pipeline/book_layout.hpp"
#include "translate/catalogue.hpp"
#include "translate/language_switch.hpp"

namespace tactus::pipeline {

struct PipelineOptions {
    import::ImportOptions import;
    std::string tables = translate::kDefaultTable;
    // Passages in another language with that language's table (on unless
    // turned off; docs/translation.md, "Passages in another language").
    translate::LanguageSwitchOptions language_switch;
    layout::LayoutOptions layout;
    // Translation processes for big documents: 0 picks by size and cores
    // (TranslationWorkers::suggested_workers), 1 keeps everything in-process.
    unsigned translation_workers = 0;
    // Ready-made braille (BRF, PEF) is kept page for page (layout/braille_pages.hpp)
    // unless this asks to lay it out again like text on the layout's pages.
    bool reflow_braille = false;
    // An empty document is an error unless the user asks for one blank page.
    bool allow_empty = false;
    // Lay the document out as a braille book: volumes, title and contents
    // pages, running heads (pipeline/book_layout.hpp). Text only: ready-made
    // braille keeps its own pages.
    std::optional<BookOptions> book;
    // Hears (code points done, code points in all) as translation goes on, from
    // the translating thread; for a terminal's progress line.
    std::function<void(std::size_t, std::size_t)> progress;
    // Pictures kept by the import (document::Block::images) as graphic pages:
    // this makes one picture's pages (the caller's graphic stage, which knows
    // the machine), placed after the block that holds it on sheets of their
    // own (layout::Paginator::add_graphic); the picture's description stays in
    // the text before it as its caption. Empty: pictures stay descriptions.
    // A picture it fails on stays its description, with a warning naming it.
    // Called on the caller's thread, never while a block is being translated.
    std::function<Result<layout::PagedDocument>(const document::Image&)> graphic_pages;
};

// `labels`, when given, receives the number each page shows (page_range.hpp:
// "12"; a book's preliminary pages "t1", "p1"), for a range the user names.
Result<layout::PagedDocument> lay_out(const document::Document& document, const PipelineOptions& options,
                                      std::vector<std::string>* labels = nullptr);
Result<layout::PagedDocument> lay_out_file(const std::filesystem::path& path,
                                   const PipelineOptions& options);

}  // namespace tactus::pipeline
