// SPDX-License-Identifier: GPL-3.0-or-later
// Plain text: blank lines separate paragraphs, the lines of a paragraph are
// kept as written, with a soft line break between them (document/soft_break.hpp:
// print keeps the lines, hard-wrapped text reflows in braille), a form feed is a
// print page break. A text with no blank line between its lines at all (a
// verse-per-line Bible, a word list, a poem) has no other paragraph marks: each
// of its lines is a paragraph, or the whole file would become one.
#include "import/document_builder.hpp"
#include "import/importers.hpp"

namespace tactus::import::detail {
namespace {

bool is_blank(std::string_view s) {
    return s.find_first_not_of(" \t\v") == std::string_view::npos;
}

class TextReader {
public:
    explicit TextReader(bool line_per_paragraph) : line_per_paragraph_(line_per_paragraph) {}
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
    // A paragraph's lines are kept as written, the spaces at their ends too
    // (the text is verbatim; braille leaves them out and reads a soft line
    // break as one space, document/soft_break.hpp).
    void segment(std::string_view text, int number) {
        if (is_blank(text)) {
            builder_.end();
            return;
        }
        if (!builder_.is_open() || line_per_paragraph_) {
            builder_.begin(document::BlockKind::paragraph, 0, number);
        } else {
            builder_.add_text("\n");
        }
        builder_.add_text(text);
    }

    bool line_per_paragraph_;
    DocumentBuilder builder_;
};

template <typename Fn>
void for_each_line(std::string_view utf8, Fn&& fn) {
    std::size_t start = 0;
    int number = 1;
    while (start < utf8.size()) {
        auto end = utf8.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = utf8.size();
        if (!fn(utf8.substr(start, end - start), number++)) return;
        if (end < utf8.size() && utf8[end] == '\r' && end + 1 < utf8.size() && utf8[end + 1] == '\n')
            ++end;
        start = end + 1;
    }
}

// True when some blank line separates two lines of text.
bool has_paragraph_breaks(std::string_view utf8) {
    bool seen_text = false;
    bool blank_after_text = false;
    bool found = false;
    for_each_line(utf8, [&](std::string_view line, int) {
        if (is_blank(line)) {
            blank_after_text = seen_text;
        } else {
            if (blank_after_text) found = true;
            seen_text = true;
        }
        return !found;
    });
    return found;
}

}  // namespace

Result<document::Document> import_text(std::string_view utf8) {
    TextReader reader(!has_paragraph_breaks(utf8));
    for_each_line(utf8, [&](std::string_view line, int number) {
        reader.line(line, number);
        return !reader.builder().full();
    });
    return reader.builder().finish();
}

}  // namespace tactus::import::detail
