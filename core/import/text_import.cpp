// SPDX-License-Identifier: GPL-3.0-or-later
// Plain text: blank lines separate paragraphs, the lines of a paragraph are
// joined with a space (hard-wrapped text reflows in braille), a form feed is a
// print page break.
#include "import/document_builder.hpp"
#include "import/importers.hpp"

namespace tactus::import_detail {
namespace {

bool is_blank(std::string_view s) {
    return s.find_first_not_of(" \t\v") == std::string_view::npos;
}

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\v");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\v");
    return s.substr(first, last - first + 1);
}

class TextReader {
public:
    void line(std::string_view text, int number) {
        // A form feed may sit alone on a line or inside one; either way it ends
        // the paragraph and starts a print page.
        for (;;) {
            const auto ff = text.find('\f');
            segment(text.substr(0, ff), number);
            if (ff == std::string_view::npos) break;
            builder_.print_page_break(number);
            text.remove_prefix(ff + 1);
        }
    }
    DocumentBuilder& builder() { return builder_; }

private:
    void segment(std::string_view text, int number) {
        if (is_blank(text)) {
            builder_.end();
            return;
        }
        if (!builder_.is_open())
            builder_.begin(BlockKind::paragraph, 0, number);
        else
            builder_.add_text(" ");
        builder_.add_text(trim(text));
    }

    DocumentBuilder builder_;
};

}  // namespace

Result<Document> import_text(std::string_view utf8) {
    TextReader reader;
    int number = 1;
    std::size_t start = 0;
    while (start < utf8.size() && !reader.builder().full()) {
        auto end = utf8.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = utf8.size();
        reader.line(utf8.substr(start, end - start), number++);
        if (end < utf8.size() && utf8[end] == '\r' && end + 1 < utf8.size() && utf8[end + 1] == '\n')
            ++end;
        start = end + 1;
    }
    return reader.builder().finish();
}

}  // namespace tactus::import_detail
