// SPDX-License-Identifier: GPL-3.0-or-later
// Markdown (CommonMark, md4c). Conventions, see docs/import.md:
//  - ordered list items keep their number as text ("3. "), bullet items start
//    with the bullet "• " (U+2022, the UEB bullet sign);
//  - tables (GitHub style, md4c's MD_FLAG_TABLES) become table rows and cells,
//    the head row a header row; block quotes become quote blocks;
//  - footnotes: `[^id]` and `[^id]: text` (markdown_footnotes.hpp), numbered
//    1, 2, 3 in the order of their first reference;
//  - print page break: a form feed, a thematic break (---, ***), or an HTML
//    comment <!-- pagebreak --> (<!-- pagebreak 12 --> sets the printed label);
//    <!-- braillepage --> forces a new braille page;
//  - code is plain text, one paragraph per line of a code block;
//  - <u>, <sup>, <sub> and <span lang="..."> are underline, raised and lowered
//    text and a passage's language; <!-- box --> and <!-- /box --> lines
//    enclose a box (document/markdown_html.hpp, the writer's own);
//  - link and image text are kept, URLs dropped; other inline HTML tags are
//    dropped, other HTML comments are dropped, HTML blocks keep their text
//    without tags.
#include <md4c.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <vector>

#include "common/file_io.hpp"
#include "common/utf8.hpp"
#include "document/markdown_html.hpp"
#include "import/document_builder.hpp"
#include "import/import.hpp"
#include "import/picture_part.hpp"
#include "import/trim.hpp"
#include "import/importers.hpp"
#include "import/markdown_footnotes.hpp"
#include "import/markdown_front_matter.hpp"
#include "import/text_position.hpp"

namespace tactus::import::detail {
namespace {

// md4c hands entities over undecoded ("&amp;", "&#233;"). Numeric ones are
// decoded exactly; of the named ones the common typographic set is known, and
// an unknown name is kept literally rather than dropped.
std::string decode_entity(std::string_view e) {
    std::string out;
    if (e.size() > 3 && e[1] == '#') {
        const bool hex = e[2] == 'x' || e[2] == 'X';
        const std::string digits(e.substr(hex ? 3 : 2, e.size() - (hex ? 4 : 3)));
        char* end = nullptr;
        const unsigned long cp = std::strtoul(digits.c_str(), &end, hex ? 16 : 10);
        if (end && *end == '\0' && cp > 0 && cp <= 0x10FFFF && (cp < 0xD800 || cp > 0xDFFF))
            append_utf8(out, static_cast<char32_t>(cp));
        else
            append_utf8(out, 0xFFFD);  // CommonMark: invalid code points become U+FFFD
        return out;
    }
    struct Named {
        std::string_view name;
        char32_t cp;
    };
    static constexpr Named named[] = {
        {"&amp;", '&'},      {"&lt;", '<'},        {"&gt;", '>'},       {"&quot;", '"'},
        {"&apos;", '\''},    {"&nbsp;", 0xA0},     {"&copy;", 0xA9},    {"&reg;", 0xAE},
        {"&deg;", 0xB0},     {"&plusmn;", 0xB1},   {"&middot;", 0xB7},  {"&frac12;", 0xBD},
        {"&times;", 0xD7},   {"&divide;", 0xF7},   {"&ndash;", 0x2013}, {"&mdash;", 0x2014},
        {"&lsquo;", 0x2018}, {"&rsquo;", 0x2019},  {"&ldquo;", 0x201C}, {"&rdquo;", 0x201D},
        {"&bull;", 0x2022},  {"&hellip;", 0x2026}, {"&euro;", 0x20AC},  {"&trade;", 0x2122},
        {"&larr;", 0x2190},  {"&rarr;", 0x2192},   {"&minus;", 0x2212}, {"&le;", 0x2264},
        {"&ge;", 0x2265},    {"&ne;", 0x2260},     {"&pi;", 0x3C0},     {"&sect;", 0xA7},
    };
    for (const auto& n : named)
        if (n.name == e) {
            append_utf8(out, n.cp);
            return out;
        }
    return std::string(e);
}

// <br>, <br/> or <br /> in any case.
bool is_line_break_tag(std::string_view tag) {
    if (tag.size() < 4 || tag.front() != '<' || tag.back() != '>') return false;
    auto name = tag.substr(1, tag.size() - 2);
    while (!name.empty() && (name.back() == '/' || name.back() == ' ')) name.remove_suffix(1);
    return name.size() == 2 && (name[0] | 0x20) == 'b' && (name[1] | 0x20) == 'r';
}

// Text of an HTML block with the tags removed (a <div> around a sentence).
std::string strip_tags(std::string_view html) {
    std::string out;
    bool in_tag = false;
    for (const char c : html) {
        if (c == '<') in_tag = true;
        else if (c == '>' && in_tag) in_tag = false;
        else if (!in_tag) out.push_back(c == '\n' ? ' ' : c);
    }
    return out;
}

class MarkdownReader {
public:
    MarkdownReader(std::string_view all, const LineIndex& lines, const std::vector<MarkdownFootnote>& notes)
        : all_(all), lines_(lines), notes_(notes), note_numbers_(notes.size(), 0) {}

    // One form-feed-free piece of the input, a substring of `all`.
    Result<void> parse(std::string_view segment) {
        MD_PARSER parser{};
        parser.abi_version = 0;
        parser.flags = MD_FLAG_STRIKETHROUGH | MD_FLAG_TABLES;
        parser.enter_block = [](MD_BLOCKTYPE t, void* d, void* self) {
            return static_cast<MarkdownReader*>(self)->enter_block(t, d);
        };
        parser.leave_block = [](MD_BLOCKTYPE t, void* d, void* self) {
            return static_cast<MarkdownReader*>(self)->leave_block(t, d);
        };
        parser.enter_span = [](MD_SPANTYPE t, void* d, void* self) {
            auto* reader = static_cast<MarkdownReader*>(self);
            if (t == MD_SPAN_IMG) reader->enter_image(*static_cast<const MD_SPAN_IMG_DETAIL*>(d));
            return reader->span(t, +1);
        };
        parser.leave_span = [](MD_SPANTYPE t, void*, void* self) {
            auto* reader = static_cast<MarkdownReader*>(self);
            if (t == MD_SPAN_IMG) reader->leave_image();
            return reader->span(t, -1);
        };
        parser.text = [](MD_TEXTTYPE t, const MD_CHAR* s, MD_SIZE n, void* self) {
            return static_cast<MarkdownReader*>(self)->text(t, std::string_view(s, n));
        };
        segment_start_ = line_of(segment.data());
        if (md_parse(segment.data(), static_cast<MD_SIZE>(segment.size()), &parser, this) != 0)
            return fail(ErrorKind::input, builder_.full() ? "too many blocks" : "Markdown parser failed",
                        std::to_string(segment_start_));
        return {};
    }

    void page_break(int line) { builder_.print_page_break(line); }
    DocumentBuilder& builder() { return builder_; }

    // Pictures are kept (ImportOptions::images) from files in `folder`, the
    // document's own, or below it.
    void keep_images(std::filesystem::path folder) { image_folder_ = std::move(folder); }
    // ImportOptions::picture_marks: an image is its description and its src.
    void mark_pictures() { picture_marks_ = true; }

    void enter_image(const MD_SPAN_IMG_DETAIL& d) {
        pending_image_.reset();
        if (picture_marks_) {
            // The picture by name, with its file's bytes when there is a folder to read it from.
            in_alt_ = true;
            alt_.clear();
            const std::string src(d.src.text, d.src.size);
            std::string why;
            if (image_folder_) pending_image_ = picture_file(*image_folder_, src, why);
            if (!pending_image_) pending_image_ = document::Image{.bytes = {}, .media_type = {}, .name = src};
            return;
        }
        if (!image_folder_) return;
        const std::string src(d.src.text, d.src.size);
        const int line = line_of(d.src.text);
        auto warn = [&](const std::string& why) {
            builder_.warn("line " + std::to_string(line) + ": picture " + src + ": " + why + "; its description stays");
        };
        std::string why;
        pending_image_ = picture_file(*image_folder_, src, why);
        if (!why.empty()) warn(why);
    }

    void leave_image() {
        if (in_alt_) {
            in_alt_ = false;
            begin_text();
            builder_.add_transcriber_note(alt_);
        }
        if (pending_image_) builder_.add_image(std::move(*pending_image_));
        pending_image_.reset();
    }

private:
    std::optional<std::filesystem::path> image_folder_;
    std::optional<document::Image> pending_image_;
    bool picture_marks_ = false;
    bool in_alt_ = false;  // picture_marks_: inside an image, whose text is its description
    std::string alt_;
    struct List {
        bool ordered = false;
        unsigned next = 1;
        char delimiter = '.';
    };

    int enter_block(MD_BLOCKTYPE type, void* detail) {
        switch (type) {
            case MD_BLOCK_UL:
                builder_.end();
                lists_.push_back(List{});
                break;
            case MD_BLOCK_QUOTE:
                builder_.end();
                ++quote_depth_;
                break;
            case MD_BLOCK_THEAD:
                in_head_ = true;
                break;
            case MD_BLOCK_TR:
                builder_.table_row(in_head_, 0);
                column_ = 0;
                break;
            case MD_BLOCK_TH:
            case MD_BLOCK_TD: {
                // The column's alignment, from the delimiter row ("|:--|:-:|--:|").
                auto align = document::Align::none;
                switch (static_cast<MD_BLOCK_TD_DETAIL*>(detail)->align) {
                    case MD_ALIGN_LEFT: align = document::Align::left; break;
                    case MD_ALIGN_CENTER: align = document::Align::centre; break;
                    case MD_ALIGN_RIGHT: align = document::Align::right; break;
                    default: break;
                }
                builder_.begin_cell(column_++, 0, 1, align);
                break;
            }
            case MD_BLOCK_OL: {
                builder_.end();
                const auto* d = static_cast<MD_BLOCK_OL_DETAIL*>(detail);
                lists_.push_back(List{true, d->start, d->mark_delimiter});
                break;
            }
            case MD_BLOCK_LI:
                builder_.end();
                item_prefix_.clear();
                if (!lists_.empty() && lists_.back().ordered)
                    item_prefix_ = std::to_string(lists_.back().next++) + lists_.back().delimiter + " ";
                else
                    item_prefix_ = kBullet;
                item_pending_ = true;
                break;
            case MD_BLOCK_H:
                builder_.begin(document::BlockKind::heading,
                               static_cast<int>(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level), 0);
                break;
            case MD_BLOCK_P:
                open_text_block();
                break;
            case MD_BLOCK_HR:
                builder_.print_page_break(0);
                break;
            case MD_BLOCK_CODE:
                builder_.end();
                in_code_ = true;
                break;
            case MD_BLOCK_HTML:
                builder_.end();
                html_.clear();
                in_html_ = true;
                break;
            default:
                break;
        }
        return builder_.full() ? 1 : 0;
    }

    int leave_block(MD_BLOCKTYPE type, void*) {
        switch (type) {
            case MD_BLOCK_UL:
            case MD_BLOCK_OL:
                builder_.end();
                lists_.pop_back();
                break;
            case MD_BLOCK_LI:
                builder_.end();
                item_pending_ = false;
                break;
            case MD_BLOCK_QUOTE:
                builder_.end();
                --quote_depth_;
                break;
            case MD_BLOCK_THEAD:
                in_head_ = false;
                builder_.drop_empty_row();  // an empty header row: a table without one
                break;
            case MD_BLOCK_TH:
            case MD_BLOCK_TD:
                builder_.end();
                break;
            case MD_BLOCK_TABLE:
                builder_.end_table();
                break;
            case MD_BLOCK_CODE:
                builder_.end();
                in_code_ = false;
                break;
            case MD_BLOCK_HTML:
                in_html_ = false;
                leave_html();
                break;
            case MD_BLOCK_H:
            case MD_BLOCK_P:
                builder_.end();
                break;
            default:
                break;
        }
        return builder_.full() ? 1 : 0;
    }

    int span(MD_SPANTYPE type, int delta) {
        switch (type) {
            case MD_SPAN_EM: italic_ += delta; break;
            case MD_SPAN_STRONG: bold_ += delta; break;
            case MD_SPAN_U: underline_ += delta; break;
            default: break;
        }
        return 0;
    }

    int text(MD_TEXTTYPE type, std::string_view s) {
        if (in_html_) {
            html_.append(s);
            html_line_ = html_line_ ? html_line_ : line_of(s.data());
            return 0;
        }
        switch (type) {
            case MD_TEXT_HTML:
                // A tag's content arrives as text. <br> is a hard line break, as
                // in HTML (how the Markdown writer keeps a table cell's
                // paragraphs apart, document/cell_paragraphs.hpp).
                if (is_line_break_tag(s)) add("\n", s);
                else inline_tag(s);
                return 0;
            case MD_TEXT_SOFTBR: add(" ", s); return 0;
            case MD_TEXT_BR: add("\n", s); return 0;
            case MD_TEXT_NULLCHAR: add("\xEF\xBF\xBD", s); return 0;
            case MD_TEXT_ENTITY: add(decode_entity(s), s); return 0;
            default: break;
        }
        if (!in_code_) {
            add(s, s);
            return 0;
        }
        // Code block: one paragraph per line, indentation kept.
        while (!s.empty()) {
            const auto nl = s.find('\n');
            add(s.substr(0, nl), s);
            if (nl == std::string_view::npos) break;
            builder_.end();
            s.remove_prefix(nl + 1);
        }
        return 0;
    }

    // The inline tags core's writer writes for what Markdown has no mark for;
    // any other tag is dropped (its content is text all the same).
    void inline_tag(std::string_view html) {
        namespace h = document::markdown_html;
        const auto tag = h::read_tag(html);
        if (!tag) return;
        const int delta = tag->closing ? -1 : +1;
        switch (tag->what) {
            case h::Tag::What::underline: underline_ += delta; break;
            case h::Tag::What::superscript: superscript_ += delta; break;
            case h::Tag::What::subscript: subscript_ += delta; break;
            case h::Tag::What::language:
                if (!tag->closing)
                    languages_.push_back(tag->language.empty() && !languages_.empty() ? languages_.back() : tag->language);
                else if (!languages_.empty())
                    languages_.pop_back();
                break;
        }
        underline_ = std::max(underline_, 0);
        superscript_ = std::max(superscript_, 0);
        subscript_ = std::max(subscript_, 0);
    }

    void open_text_block() {
        if (!lists_.empty())
            builder_.begin(document::BlockKind::list_item, static_cast<int>(lists_.size()), 0);
        else if (quote_depth_ > 0)
            builder_.begin(document::BlockKind::quote, quote_depth_, 0);
        else
            builder_.begin(document::BlockKind::paragraph, 0, 0);
    }

    // Text with footnote markers in it: each marker is a reference, and the
    // first reference to a note brings its text.
    void add(std::string_view s, std::string_view where) {
        if (in_alt_) {
            alt_.append(s);
            return;
        }
        for (std::size_t i = 0; i < s.size(); ++i) {
            const auto marker = read_footnote_marker(s.substr(i));
            if (!marker || marker->first >= notes_.size()) continue;
            add_text(s.substr(0, i), where);
            reference(marker->first);
            s.remove_prefix(i + marker->second);
            i = static_cast<std::size_t>(-1);
        }
        add_text(s, where);
    }

    void reference(std::size_t index) {
        begin_text();
        int& number = note_numbers_[index];
        const bool first = number == 0;
        if (first) number = ++notes_referenced_;
        const auto label = std::to_string(number);
        builder_.note_reference(label);
        if (!first) return;
        write_note(builder_, index, label);
    }

public:
    // Notes that nothing refers to are kept (dropping them would lose a note
    // line in the editor when its reference is deleted). Each is
    // kept where its definition stands: before the first block that starts
    // after the definition's line (after that block's own notes, never inside
    // a table), or at the end. Numbered on after the referenced notes, in the
    // order of definition (docs/layout.md "Notes").
    void place_unreferenced_notes(document::Document& doc) {
        for (std::size_t index = 0; index < notes_.size(); ++index) {
            if (note_numbers_[index] != 0) continue;
            note_numbers_[index] = ++notes_referenced_;
            DocumentBuilder one;
            write_note(one, index, std::to_string(note_numbers_[index]));
            auto note = one.finish();
            if (!note || note->blocks.empty()) continue;
            auto& blocks = doc.blocks;
            std::size_t at = 0;
            for (; at < blocks.size(); ++at) {
                const auto& b = blocks[at];
                const bool inside_table =
                    b.kind == document::BlockKind::table_cell ||
                    (b.kind == document::BlockKind::table_row && at > 0 && document::is_table_kind(blocks[at - 1].kind));
                if (b.kind != document::BlockKind::note && !inside_table && b.source_line > notes_[index].line) break;
            }
            blocks.insert(blocks.begin() + static_cast<std::ptrdiff_t>(at), note->blocks.front());
        }
    }

private:

    // A note block: its reference, then the note's own Markdown (emphasis,
    // links), read as a document of its own.
    void write_note(DocumentBuilder& builder, std::size_t index, const std::string& label) const {
        const auto& note = notes_[index];
        builder.begin_note(label, note.line);
        const LineIndex lines(note.text);
        static const std::vector<MarkdownFootnote> none;
        MarkdownReader inner(note.text, lines, none);
        if (inner.parse(note.text)) {
            auto doc = inner.builder().finish();
            if (doc)
                for (const auto& b : doc->blocks)
                    for (const auto& span : b.spans)
                        builder.add_text(span.text, span.emphasis, span.position, span.language);
        }
        builder.end_note();
    }

    // The open block, with a list item's number or bullet first (before a
    // reference too, when the item's text starts with one).
    void begin_text() {
        if (!builder_.is_open()) open_text_block();
        if (item_pending_ && builder_.open_kind() == document::BlockKind::list_item) {
            item_pending_ = false;
            builder_.add_text(item_prefix_);
        }
    }

    void add_text(std::string_view s, std::string_view where) {
        if (s.empty()) return;
        begin_text();
        builder_.note_line(line_of(where.data()));
        const auto emphasis = static_cast<std::uint8_t>(
            (italic_ > 0 ? document::emphasis_italic : 0) | (bold_ > 0 ? document::emphasis_bold : 0) |
            (underline_ > 0 ? document::emphasis_underline : 0));
        const auto position = superscript_ > 0 ? document::Position::superscript
                              : subscript_ > 0 ? document::Position::subscript
                                               : document::Position::baseline;
        builder_.add_text(s, emphasis, position, languages_.empty() ? std::string_view() : languages_.back());
    }

    void leave_html() {
        const auto html = trim(html_);
        const int line = html_line_;
        html_line_ = 0;
        if (html.starts_with("<!--") && html.ends_with("-->")) {
            const auto body = trim(html.substr(4, html.size() - 7));
            if (body.starts_with("pagebreak")) {
                auto label = trim(body.substr(9));
                if (label.starts_with(':')) label = trim(label.substr(1));
                builder_.print_page_break(line, std::string(label));
            } else if (body == "braillepage") {
                // Written by the editor for a forced braille page (a BRF form feed).
                builder_.braille_page_break(line, DocumentBuilder::BrailleBreak::written);
            } else if (body == document::markdown_html::kBoxStartBody) {
                builder_.end();
                builder_.begin_box();
            } else if (body == document::markdown_html::kBoxEndBody) {
                builder_.end();
                builder_.end_box();
            }
            return;  // any other comment is not content
        }
        const auto text = strip_tags(html);
        if (trim(text).empty()) return;
        builder_.begin(document::BlockKind::paragraph, 0, line);
        builder_.add_text(trim(text));
        builder_.end();
    }

    int line_of(const char* p) const {
        if (p < all_.data() || p >= all_.data() + all_.size()) return 0;  // md4c's own buffer
        return lines_.line_at(static_cast<std::size_t>(p - all_.data()));
    }

    static constexpr std::string_view kBullet = "\u2022 ";  // the UEB bullet sign ⠸⠲

    std::string_view all_;
    const LineIndex& lines_;
    const std::vector<MarkdownFootnote>& notes_;
    std::vector<int> note_numbers_;  // per note: its number, 0 until referenced
    int notes_referenced_ = 0;
    int quote_depth_ = 0;
    bool in_head_ = false;
    int column_ = 0;
    DocumentBuilder builder_;
    std::vector<List> lists_;
    std::string item_prefix_;
    bool item_pending_ = false;
    bool in_code_ = false;
    bool in_html_ = false;
    std::string html_;
    int html_line_ = 0;
    int segment_start_ = 1;
    int italic_ = 0, bold_ = 0, underline_ = 0;
    int superscript_ = 0, subscript_ = 0;
    std::vector<std::string> languages_;  // the open <span>s', innermost last
};

}  // namespace

Result<document::Document> import_markdown(std::string_view source, const std::filesystem::path* image_folder,
                                           bool picture_marks) {
    // Front matter is metadata: left out of the text, its lines kept as blank
    // lines so every line after it keeps its number in messages.
    const auto front = front_matter(source);
    std::string without_front;
    if (front) {
        without_front.assign(static_cast<std::size_t>(front->lines), '\n');
        without_front.append(source.substr(front->length));
        source = without_front;
    }
    const auto prepared = prepare_footnotes(source);
    const std::string_view utf8 = prepared.text;
    const LineIndex lines(utf8);
    MarkdownReader reader(utf8, lines, prepared.notes);
    if (image_folder) reader.keep_images(*image_folder);
    if (picture_marks) reader.mark_pictures();
    // CommonMark treats a form feed as blank space; as the print page break of
    // plain text it splits the input, and each piece is parsed on its own.
    std::size_t start = 0;
    for (;;) {
        const auto ff = utf8.find('\f', start);
        const auto piece = utf8.substr(start, ff == std::string_view::npos ? ff : ff - start);
        if (auto ok = reader.parse(piece); !ok) {
            if (reader.builder().full()) break;  // finish() reports it
            return std::unexpected(ok.error());
        }
        if (ff == std::string_view::npos) break;
        reader.page_break(lines.line_at(ff));
        start = ff + 1;
    }
    auto doc = reader.builder().finish();
    if (doc) reader.place_unreferenced_notes(*doc);
    if (doc && front) doc->metadata = front->metadata;
    return doc;
}

}  // namespace tactus::import::detail
