// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The print pane's structured view: each editor line (core's Markdown line
// dialect, edit/editor_lines.hpp) shown as one QTextDocument block with its
// structure as Qt's rich text (a heading's level and font, a list's numbers
// or bullets from a QTextList, emphasis as char formats, a table row as its
// cells at tab stops, a page break as an empty block the pane draws as a
// rule, a box as its box lines around its blocks, underline and raised or
// lowered text as char formats, a picture as an image object showing it, its
// description its tooltip and the words the pane says for it) and no markup
// characters; and the way back, a block to its line
// through core's Markdown writer. One block per line keeps the braille pane,
// the cursor map and the live layout working line by line (docs/editor.md).
#include <QFont>
#include <QString>
#include <QTextBlock>
#include <QTextFormat>
#include <QStringList>
#include <span>
#include <string>

#include "edit/editor_pictures.hpp"

class QTextDocument;

namespace tactus::gui::structured {

// What a block stands for (block format property kStyle).
enum class Style : int {
    body = 0,
    heading,
    bullet_item,
    number_item,
    quote,
    note,
    print_page_break,
    braille_page_break,
    braille,
    table_row,
    table_delimiter,  // a table's "| --- |" line: a thin rule under the header row
    blank,            // a line that stands for no block
    box_start,        // "<!-- box -->": the line above a box's blocks, drawn as a box line
    box_end,          // "<!-- /box -->": the line below them
};

inline constexpr int kStyle = QTextFormat::UserProperty + 1;      // block: Style
inline constexpr int kLevel = QTextFormat::UserProperty + 2;      // block: heading/list/quote level
inline constexpr int kCode = QTextFormat::UserProperty + 3;       // block: the line, for lines shown as no text
inline constexpr int kNoteRef = QTextFormat::UserProperty + 4;    // char: a note's reference
inline constexpr int kTranscriber = QTextFormat::UserProperty + 5;  // char: transcriber's note text
inline constexpr int kLanguage = QTextFormat::UserProperty + 6;   // char: the passage's language
inline constexpr int kPosition = QTextFormat::UserProperty + 7;   // char: document::Position
// block: a numbered item whose number is its text (Qt 6.4's lists all count from 1).
inline constexpr int kNumberText = QTextFormat::UserProperty + 8;
// image: a picture's name in the editor's pictures (edit/editor_pictures.hpp) and its description.
inline constexpr int kPicture = QTextFormat::UserProperty + 9;
inline constexpr int kPictureDescription = QTextFormat::UserProperty + 10;

// The widest a picture is shown in the print pane, in pixels: a thumbnail
// that says what the picture is without pushing the text away.
inline constexpr int kPictureWidth = 160;

// Replaces the document's text with `lines` shown structured, in `base`'s
// size; a picture's mark as the picture `pictures` holds under its name (a
// framed box with its description when it holds none or it cannot be drawn).
void render(QTextDocument* doc, std::span<const std::string> lines, const QFont& base,
            const edit::PictureStore* pictures = nullptr);

// A picture as an image object at the cursor: shown as `render` shows it.
void insert_picture(QTextCursor& cursor, const std::string& name, const std::string& description,
                    const edit::PictureStore* pictures);

// The descriptions of the pictures in a block, in order ("" for one without).
QStringList picture_descriptions(const QTextBlock& block);

// The editor line a block stands for now (after edits), in the Markdown dialect.
std::string line_of(const QTextBlock& block);

// The block's style; body for a block typed anew.
Style style_of(const QTextBlock& block);

// A position in the block's text <-> a column in edit::editor_line_content of
// its line (what the cursor map counts in: a list item's number, a table's
// two spaces between cells).
int content_column(const QTextBlock& block, int position);
int block_position(const QTextBlock& block, int content_column);

// The char format text of a style is shown in (a heading's size and weight).
QTextCharFormat base_char_format(Style style, int level, const QFont& base);
// A block's format for a style (level: heading 1-6, list or quote depth).
QTextBlockFormat block_format(Style style, int level);

// True when the char format reads as bold emphasis (a heading's own weight does not).
bool is_bold(const QTextCharFormat& format);

}  // namespace tactus::gui::structured
