// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The walk shared by the HTML, EPUB and DTBook importers: an element tree
// (pugixml; HTML is parsed by Gumbo and copied into one, html_tree.hpp) turned
// into blocks. One vocabulary serves all three, as their names do not clash:
// HTML's h1-h6, p, ul/ol/li, blockquote, table, aside, img, em/strong, and
// EPUB's epub:type / ARIA roles (noteref, footnote, endnote, pagebreak);
// DTBook's level1-6/level with h1-h6/hd, list, pagenum, noteref/note,
// annotation, imggroup, prodnote, sidebar, linegroup/line. Each rule is
// described in docs/import.md ("HTML, EPUB and DTBook").
#include <pugixml.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include "import/document_builder.hpp"

namespace tactus::import::detail {

// Elements nested deeper than this are refused with an error naming where:
// real books nest a few dozen deep, and the walk is recursive.
inline constexpr int max_markup_depth = 400;

// One content document of a book (an EPUB spine item, or the whole HTML or
// DTBook file): its tree, its name for note links and messages, and the
// source line of an element.
struct MarkupPart {
    std::string name;  // "OEBPS/chapter-1.xhtml"; "" for a single file
    pugi::xml_node root;
    std::function<int(const pugi::xml_node&)> line_of;
};

// A link's path resolved against the part it is in ("OEBPS/text/ch1.xhtml" +
// "../notes.xhtml" -> "OEBPS/notes.xhtml"), percent escapes decoded.
std::string resolve_path(std::string_view base_part, std::string_view relative);

// All the text under `node`, white space collapsed, trimmed.
std::string text_of(const pugi::xml_node& node);

class MarkupWalk {
public:
    // The parts are walked in order; a note reference may point into any of
    // them ("endnotes.xhtml#note-1"), and the note comes after the block that
    // refers to it, numbered as the print numbers it.
    explicit MarkupWalk(std::vector<MarkupPart> parts);
    Result<document::Document> run();

    // Reads a described <img>'s picture (ImportOptions::images): given the
    // part it is in and its src, the picture, or nothing with `why` set when
    // it cannot be kept (named in a warning; the description stays).
    using PictureReader = std::function<std::optional<document::Image>(std::string_view part, std::string_view src,
                                                                         std::string& why)>;
    void keep_pictures(PictureReader read) { pictures_ = std::move(read); }

private:
    struct Context {
        document::BlockKind kind = document::BlockKind::paragraph;
        int level = 0;
        std::uint8_t emphasis = document::emphasis_none;
        std::string language;
        int list_depth = 0;
        int quote_depth = 0;
        int section_depth = 0;  // DTBook <level> nesting, for <hd>
        bool inline_only = false;  // in a heading, a table cell or a note: blocks run on
    };

    Result<void> walk_children(const pugi::xml_node& node, const Context& ctx, int depth);
    Result<void> walk(const pugi::xml_node& node, const Context& ctx, int depth);
    Result<void> block(const pugi::xml_node& node, Context ctx, int depth);
    Result<void> list(const pugi::xml_node& node, const Context& ctx, int depth, bool ordered);
    Result<void> table(const pugi::xml_node& node, const Context& ctx, int depth);
    Result<void> reference(const pugi::xml_node& node, const Context& ctx, int depth);
    Result<void> note(const pugi::xml_node& node, const Context& ctx, int depth, std::string label);
    void page_break(const pugi::xml_node& node);
    void image(const pugi::xml_node& node, const Context& ctx);
    void math(const pugi::xml_node& node, const Context& ctx);
    void text(std::string_view raw, const Context& ctx);
    void pending_space(const Context& ctx);
    // A paragraph of a table cell ends or starts here (a block, a list item, <br>).
    void cell_paragraph_break(const Context& ctx);
    void open(const Context& ctx);
    void close();
    void warn(const pugi::xml_node& node, std::string what);
    void flush_breaks();
    [[nodiscard]] int line(const pugi::xml_node& node) const;
    [[nodiscard]] std::string where(const pugi::xml_node& node) const;

    std::vector<MarkupPart> parts_;
    std::size_t part_ = 0;  // the part being walked
    PictureReader pictures_;
    void attach_picture(const pugi::xml_node& node);
    DocumentBuilder builder_;
    int current_line_ = 0;        // the source line of the element being walked
    bool space_pending_ = false;  // white space seen since the last text
    // In a table cell: a paragraph, list item or <br> ended since the last
    // text, so the pending space is a line break, the cell's next paragraph
    // (document.hpp, table_cell).
    bool line_pending_ = false;
    bool after_label_ = false;  // a list item's label in a cell, no text after it yet
    std::uint8_t last_emphasis_ = document::emphasis_none;  // of the last text: a pending space takes these
    std::string last_language_;
    std::string base_language_;  // the root element's: the document's own
    bool block_fresh_ = true;     // the open block has no text yet
    std::string item_label_;      // a list item's bullet or number, before its first text
    // Notes by "part#id"; those already written (a note is written once).
    std::map<std::string, pugi::xml_node> notes_;
    std::set<const void*> notes_written_;
    int note_number_ = 0;
    int note_depth_ = 0;
    int table_depth_ = 0;
    std::vector<std::string> pending_breaks_;  // page breaks met inside a table or a note
    std::vector<std::string> warnings_;
    std::map<std::string, int> warning_counts_;
};

}  // namespace tactus::import::detail
