// SPDX-License-Identifier: GPL-3.0-or-later
// BRF (Braille ASCII): every page becomes one verbatim braille block, pages are
// separated by braille page breaks. Lines end with LF or CRLF; a form feed ends
// the page (alone on a line or at the end of the last line of the page).
#include <array>
#include <cstdio>

#include "import/document_builder.hpp"
#include "import/importers.hpp"

namespace tactus::import::detail {
namespace {

std::string describe(unsigned char c) {
    std::array<char, 48> buf{};
    if (c >= 0x21 && c < 0x7F)
        std::snprintf(buf.data(), buf.size(), "'%c' (0x%02X)", c, c);
    else
        std::snprintf(buf.data(), buf.size(), "byte 0x%02X", c);
    return buf.data();
}

}  // namespace

Result<document::Document> import_brf(std::string_view bytes) {
    // DOS-era files may end with a Ctrl-Z end-of-file marker: not part of the braille.
    if (!bytes.empty() && bytes.back() == '\x1A') bytes.remove_suffix(1);

    DocumentBuilder builder;
    std::vector<document::BrailleLine> page;
    document::BrailleLine line;
    bool line_started = false;  // the current line has at least one character
    int line_number = 1;
    int column = 1;
    int page_line = 1;  // source line where the current page starts

    const auto end_line = [&] {
        page.push_back(std::move(line));
        line = {};
        line_started = false;
    };
    const auto end_page = [&] {
        builder.braille_block(std::move(page), page_line);
        page = {};
        builder.braille_page_break(line_number);
    };

    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const char c = bytes[i];
        if (c == '\n' || c == '\r') {
            if (c == '\r' && i + 1 < bytes.size() && bytes[i + 1] == '\n') ++i;
            end_line();
            ++line_number;
            column = 1;
            continue;
        }
        if (c == '\f') {
            if (line_started) end_line();
            end_page();
            ++column;
            page_line = line_number;
            // The usual "\f\r\n" or "\f\n" belongs to the break, not to an empty line.
            if (i + 1 < bytes.size() && (bytes[i + 1] == '\n' || bytes[i + 1] == '\r')) {
                if (bytes[i + 1] == '\r' && i + 2 < bytes.size() && bytes[i + 2] == '\n') ++i;
                ++i;
                ++line_number;
                column = 1;
                page_line = line_number;
            }
            if (builder.full()) break;
            continue;
        }
        document::Cell cell;
        if (!document::cell_from_brf(c, cell))
            return fail(ErrorKind::input, describe(static_cast<unsigned char>(c)) + " is not Braille ASCII",
                        std::to_string(line_number) + ":" + std::to_string(column));
        line.push_back(cell);
        line_started = true;
        ++column;
    }
    if (line_started) end_line();
    if (!page.empty()) builder.braille_block(std::move(page), page_line);
    return builder.finish();
}

}  // namespace tactus::import::detail
