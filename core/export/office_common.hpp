// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the DOCX and ODT writers share: XML escaping, a list item's label read
// back into a list style and number, the notes of a document by label, a
// block's pictures paired with their descriptions and sized, and the
// warnings for what a format does not keep. Each writer only writes its
// own XML.
#include <cstddef>
#include <map>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
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

// A block's pictures (document::Block::images) as the writers place them:
// each transcriber's note takes the block's next picture and is written as
// its description; the pictures left when the notes run out follow the
// block's text, undescribed. The model does not say which note describes
// which picture, but the importers give a described picture its note where
// it stands, so pairing them in order reads back as the same spans and the
// same pictures in the same order.
class BlockPictures {
public:
    explicit BlockPictures(const document::Block& block) : images_(block.images) {}
    // The picture for the next transcriber's note; nullptr once all are placed.
    const document::Image* next() { return next_ < images_.size() ? &images_[next_++] : nullptr; }
    // The pictures no note took; afterwards there are none.
    std::span<const document::Image> rest() {
        const auto from = std::exchange(next_, images_.size());
        return std::span<const document::Image>(images_).subspan(from);
    }

private:
    const std::vector<document::Image>& images_;
    std::size_t next_ = 0;
};

// A picture's file name in the package, numbered in the order written
// ("image3.png", "image4.jpeg", "image5.svg"), or "" for a type the importers
// would not read back as a picture (only PNG, JPEG and SVG make a graphic):
// such a picture is left out with a warning, and its description stays.
std::string picture_file_name(int number, std::string_view media_type);

// A picture a writer puts in its package: its file name there and its bytes.
struct PictureFile {
    std::string file;  // "image1.png"
    const document::Image* image = nullptr;
};

// `image` added to `files` under the next picture_file_name, and true; for a
// type the importers would not read back as a picture, nothing added, the loss
// named at `block`, and false (the writer writes its description alone).
bool add_picture_file(std::vector<PictureFile>& files, const document::Image& image, std::size_t block, Losses& losses);

// How large a picture is written, in EMU (914400 to the inch; DOCX's unit,
// ODT's lengths are written from it).
struct Extent {
    long long cx = 0;
    long long cy = 0;
};
Extent picture_extent(const document::Image& image);

// An EMU length as ODF writes it, in centimetres ("2.540cm"), the same in
// every locale.
std::string odf_length(long long emu);

// The next block after `i` (before `end`) that the text shows: notes are
// written where they are referred to, not where they stand.
const document::Block* next_shown(const std::vector<document::Block>& blocks, std::size_t i, std::size_t end);

// The end of the run of table blocks starting at `begin`.
std::size_t table_end(const std::vector<document::Block>& blocks, std::size_t begin, std::size_t end);

// The number of columns of a table (the widest row, merged cells counted).
int table_columns(const std::vector<document::Block>& blocks, std::size_t begin, std::size_t end);

}  // namespace tactus::exporter::office
