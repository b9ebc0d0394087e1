// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the DOCX and ODT writers share: XML escaping, a list item's label read
// back into a list style and number, the notes of a document by label, and
// the warnings for what a format does not keep. Each writer only writes its
// own XML.
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "document/document.hpp"

namespace tactus::exporter::office {

// Text for XML character data and attribute values: & < > " escaped, and the
// C0 controls XML 1.0 cannot hold (all but tab, LF and CR) left out and counted.
std::string escape(std::string_view text, std::size_t* dropped = nullptr);

// The importers write a list item's label in front of its text ("3. ",
// "\u2022 "); a writer gives it back to the list style that makes it again.
enum class ListStyle { bullet, decimal_dot, decimal_paren, plain };

struct ListLabel {
    ListStyle style = ListStyle::plain;
    int number = 0;          // decimal styles: the item's number
    std::size_t length = 0;  // bytes of the label and its space at the start of the first span
};

// The label of a list item: "\u2022 " a bullet, "12. " / "3) " a number
// (one to nine digits, from 1); anything else (a roman "iv. ", "1.2. ", no
// label) is plain: the item's text is written as it is, label included, in a
// list that draws none. Only a label in a span of plain text counts, with
// text after it, as the importers write it.
ListLabel list_label(const document::Block& item);

// The item's spans without its label.
std::vector<document::Span> without_label(const document::Block& item, const ListLabel& label);

// A note's text without its reference (the first span) and the space after it.
std::vector<document::Span> note_body(const document::Block& note);

// Note blocks by label, and which labels the text refers to.
struct Notes {
    explicit Notes(const document::Document& document);
    std::map<std::string, std::size_t> by_label;  // label -> block index
    std::set<std::string> referenced;
};

// The warnings a writer gives: what was left out or changed, how many, and
// the first block it happened at.
class Losses {
public:
    void add(const std::string& what, std::size_t block);
    [[nodiscard]] std::vector<std::string> lines(std::string_view format) const;

private:
    struct Count {
        int count = 0;
        std::size_t first = 0;
    };
    std::vector<std::pair<std::string, Count>> kinds_;
};

// A 1x1 transparent PNG: a picture for an image's description to belong to
// (DOCX wp:docPr descr, ODT svg:desc), since the model keeps the description
// and not the picture.
std::string_view placeholder_png();

// The next block after `i` (before `end`) that the text shows: notes are
// written where they are referred to, not where they stand.
const document::Block* next_shown(const std::vector<document::Block>& blocks, std::size_t i, std::size_t end);

// The end of the run of table blocks starting at `begin`.
std::size_t table_end(const std::vector<document::Block>& blocks, std::size_t begin, std::size_t end);

// The number of columns of a table (the widest row, merged cells counted).
int table_columns(const std::vector<document::Block>& blocks, std::size_t begin, std::size_t end);

}  // namespace tactus::exporter::office
