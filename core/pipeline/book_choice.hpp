// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// When a document is laid out as a braille book (pipeline/book_layout.hpp)
// without being asked: the app's rule, and the room a volume's body has,
// which the volume breaks use too, so both read the same number.
#include <cstddef>

#include "import/import.hpp"
#include "layout/page.hpp"
#include "pipeline/book_layout.hpp"

namespace tactus::pipeline {

// Braille pages a volume's body may fill: the volume's sheets as pages, less
// room for its preliminary pages (a title page and a contents page or two,
// each part on its own sheet).
std::size_t volume_body_room(const BookOptions& book, const layout::PageGeometry& geometry);

// A book reads as a book: an EPUB always (it is a publication with a title,
// an author and chapters), and any text whose plain layout (`plain_pages`
// braille pages) is longer than one volume's body. Ready-made braille never:
// it keeps its own pages.
bool lays_out_as_book(import::SourceFormat format, bool ready_braille, std::size_t plain_pages,
                      const BookOptions& book, const layout::PageGeometry& geometry);

}  // namespace tactus::pipeline
