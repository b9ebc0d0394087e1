// SPDX-License-Identifier: GPL-3.0-or-later
// Plain text: blank lines separate paragraphs, the lines of a paragraph are
// kept as written, with a soft line break between them (document/soft_break.hpp:
// print keeps the lines, hard-wrapped text reflows in braille), a form feed is a
// print page break. A text with no blank line between its lines at all (a
// verse-per-line Bible, a word list, a poem) has no other paragraph marks: each
// of its lines is a paragraph, or the whole file would become one.
#include "import/document_builder.hpp"
#include "import/importers.hpp"
#include "import/text_lines.hpp"

namespace tactus::import::detail {
namespace {

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
        if (is_blank_text_line(text)) {
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

// True when some blank line separates two lines of text.
bool has_paragraph_breaks(std::string_view utf8) {
    ParagraphBreaks breaks;
    for_each_text_line(utf8, [&](std::string_view line, int) { return !breaks.line(line); });
    return breaks.found();
}

}  // namespace

Result<document::Document> import_text(std::string_view utf8) {
    TextReader reader(!has_paragraph_breaks(utf8));
    for_each_text_line(utf8, [&](std::string_view line, int number) {
        reader.line(line, number);
        return !reader.builder().full();
    });
    return reader.builder().finish();
}

}  // namespace tactus::import::detail
