// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/book_choice.hpp"

#include <algorithm>

namespace tactus::pipeline {

std::size_t volume_body_room(const BookOptions& book, const layout::PageGeometry& geometry) {
    const std::size_t per_volume =
        std::max<std::size_t>(2, static_cast<std::size_t>(std::max(book.sheets_per_volume, 0)) * (geometry.interpoint ? 2 : 1));
    const std::size_t prelims = (book.title_page ? 2u : 0u) + (book.contents ? 2u : 0u);
    return per_volume > prelims + 2 ? per_volume - prelims : per_volume;
}

bool lays_out_as_book(import::SourceFormat format, bool ready_braille, std::size_t plain_pages,
                      const BookOptions& book, const layout::PageGeometry& geometry) {
    if (ready_braille || format == import::SourceFormat::brf || format == import::SourceFormat::pef) return false;
    if (format == import::SourceFormat::epub) return true;
    return plain_pages > volume_body_room(book, geometry);
}

}  // namespace tactus::pipeline
