// SPDX-License-Identifier: GPL-3.0-or-later
#include "structured_print.hpp"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QImage>
#include <QPainter>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextImageFormat>
#include <QTextList>
#include <QUrl>
#include <algorithm>
#include <optional>

#include "edit/editor_lines.hpp"
#include "export/markdown_syntax.hpp"
#include "export/text_export.hpp"

namespace tactus::gui::structured {
namespace {

using document::Block;
using document::BlockKind;
using document::Span;
using exporter::markdown::kBullet;
using exporter::markdown::ordinal_length;

constexpr QChar kCellSeparator = QLatin1Char('\t');

QString qs(const std::string& s) { return QString::fromStdString(s); }

// Tints for the blocks that are not running text; light, so text stays readable.
const QColor kTableTint(0xee, 0xf2, 0xf7);
const QColor kHeaderTint(0xd5, 0xdf, 0xec);
const QColor kRuleTint(0x60, 0x70, 0x88);
const QColor kNoteTint(0xfb, 0xf6, 0xe4);
const QColor kQuoteTint(0xf1, 0xf1, 0xf1);
const QColor kBoxTint(0xe4, 0xec, 0xe4);

QTextCharFormat span_format(const Span& s, const QTextCharFormat& base) {
    auto f = base;
    if (s.emphasis & document::emphasis_bold) f.setFontWeight(QFont::Bold);
    if (s.emphasis & document::emphasis_italic) f.setFontItalic(true);
    if (s.emphasis & document::emphasis_underline) f.setFontUnderline(true);
    if (s.note_reference) {
        f.setProperty(kNoteRef, true);
        f.setVerticalAlignment(QTextCharFormat::AlignSuperScript);
    } else if (s.position != document::Position::baseline) {
        f.setProperty(kPosition, static_cast<int>(s.position));
        f.setVerticalAlignment(s.position == document::Position::superscript ? QTextCharFormat::AlignSuperScript
                                                                             : QTextCharFormat::AlignSubScript);
    }
    if (s.transcriber_note) f.setProperty(kTranscriber, true);
    if (!s.language.empty()) f.setProperty(kLanguage, qs(s.language));
    return f;
}

Span span_of(const QString& text, const QTextCharFormat& f) {
    Span s{text.toStdString()};
    std::uint8_t e = document::emphasis_none;
    if (is_bold(f)) e |= document::emphasis_bold;
    if (f.fontItalic()) e |= document::emphasis_italic;
    if (f.fontUnderline()) e |= document::emphasis_underline;
    s.emphasis = e;
    s.note_reference = f.boolProperty(kNoteRef);
    if (!s.note_reference && f.hasProperty(kPosition))
        s.position = static_cast<document::Position>(f.intProperty(kPosition));
    s.transcriber_note = f.boolProperty(kTranscriber);
    s.language = f.stringProperty(kLanguage).toStdString();
    return s;
}

void append(std::vector<Span>& spans, Span s) {
    if (s.text.empty()) return;
    if (!spans.empty()) {
        auto& last = spans.back();
        auto a = last, b = s;
        a.text.clear();
        b.text.clear();
        if (a == b && !s.note_reference) {
            last.text += s.text;
            return;
        }
    }
    spans.push_back(std::move(s));
}

// The block's text as spans; with `cells`, split into one list per table
// cell. A picture is its description, a transcriber's note, and its name in
// `images` (one list per cell), as a picture's mark reads (edit/editor_pictures.hpp).
std::vector<std::vector<Span>> spans_of(const QTextBlock& block, bool cells,
                                        std::vector<std::vector<document::Image>>* images = nullptr) {
    std::vector<std::vector<Span>> out(1);
    std::vector<std::vector<document::Image>> pictures(1);
    for (auto it = block.begin(); !it.atEnd(); ++it) {
        const auto frag = it.fragment();
        if (!frag.isValid()) continue;
        const auto text = frag.text();
        const auto format = frag.charFormat();
        if (format.hasProperty(kPicture)) {
            for (const auto ch : text) {
                if (ch == QChar::ObjectReplacementCharacter) {
                    Span note{format.stringProperty(kPictureDescription).toStdString()};
                    note.transcriber_note = true;
                    if (!note.text.empty()) out.back().push_back(std::move(note));
                    pictures.back().push_back(document::Image{.bytes = {}, .media_type = {},
                                                              .name = format.stringProperty(kPicture).toStdString()});
                } else {
                    // Text typed with the picture's format: text.
                    auto plain = format;
                    plain.clearProperty(kPicture);
                    append(out.back(), span_of(QString(ch), plain));
                }
            }
            continue;
        }
        qsizetype from = 0;
        for (qsizetype i = 0; i <= text.size(); ++i) {
            const bool end = i == text.size();
            if (!end && !(cells && text[i] == kCellSeparator) && text[i] != QChar::LineSeparator) continue;
            append(out.back(), span_of(text.mid(from, i - from), format));
            // A line break: in a table cell the break between the cell's
            // paragraphs ("\n", document.hpp), elsewhere a space (a soft
            // break typed with Shift+Enter has no block of its own).
            if (!end && text[i] == QChar::LineSeparator)
                append(out.back(), span_of(cells ? QStringLiteral("\n") : QStringLiteral(" "), format));
            else if (!end) {
                out.emplace_back();
                pictures.emplace_back();
            }
            from = i + 1;
        }
    }
    if (images) *images = std::move(pictures);
    return out;
}

// What a picture is shown as: itself, at most kPictureWidth wide; or, when
// there is none to draw, a framed box with its description.
QImage picture_image(const document::Image* image, const QString& description, const QFont& font) {
    QImage shown;
    if (image)
        shown.loadFromData(QByteArray::fromStdString(image->bytes), image->media_type == "image/svg+xml" ? "SVG" : nullptr);
    if (!shown.isNull()) {
        if (shown.width() > kPictureWidth) shown = shown.scaledToWidth(kPictureWidth, Qt::SmoothTransformation);
        return shown;
    }
    QImage box(kPictureWidth, kPictureWidth / 2, QImage::Format_ARGB32);
    box.fill(Qt::white);
    QPainter p(&box);
    p.setPen(QPen(Qt::darkGray, 2));
    p.drawRect(box.rect().adjusted(1, 1, -2, -2));
    p.setFont(font);
    p.setPen(Qt::black);
    p.drawText(box.rect().adjusted(6, 6, -6, -6), Qt::AlignCenter | Qt::TextWordWrap,
               description.isEmpty() ? QCoreApplication::translate("tactus::gui::structured", "Picture") : description);
    return box;
}

void insert_spans(QTextCursor& c, const std::vector<Span>& spans, const QTextCharFormat& base,
                  const std::vector<document::Image>& images = {}, const edit::PictureStore* pictures = nullptr,
                  bool cell = false) {
    std::size_t next = 0;
    for (const auto& s : spans) {
        if (s.transcriber_note && next < images.size()) {
            insert_picture(c, images[next++].name, s.text, pictures);
            continue;
        }
        // A cell's paragraphs are apart by "\n", which insertText would make a
        // block of its own: one line is one block, so they are shown as line
        // breaks inside the row's block.
        c.insertText(cell ? qs(s.text).replace(QLatin1Char('\n'), QChar::LineSeparator) : qs(s.text),
                     span_format(s, base));
    }
    for (; next < images.size(); ++next) insert_picture(c, images[next].name, {}, pictures);
}

// A list item's number or bullet, taken off its text (the QTextList shows it).
struct ItemMark {
    bool bullet = true;
    int number = 1;
    QChar suffix = QLatin1Char('.');
};

ItemMark take_mark(std::vector<Span>& spans) {
    ItemMark m;
    if (spans.empty()) return m;
    auto& first = spans.front().text;
    if (first.starts_with(kBullet)) {
        first.erase(0, kBullet.size());
    } else if (const auto n = ordinal_length(first); n > 1 && n < first.size() && first[n] == ' ') {
        m.bullet = false;
        m.suffix = QLatin1Char(first[n - 1]);
        m.number = std::stoi(first.substr(0, n - 1));
        first.erase(0, n + 1);
    }
    if (first.empty()) spans.erase(spans.begin());
    return m;
}

QTextListFormat::Style bullet_style(int level) {
    switch ((level - 1) % 3) {
        case 0: return QTextListFormat::ListDisc;
        case 1: return QTextListFormat::ListCircle;
        default: return QTextListFormat::ListSquare;
    }
}

struct Shown {
    Style style = Style::body;
    int level = 0;
    std::optional<Block> block;
};

Shown classify(const std::string& line) {
    Shown s;
    if (const int box = edit::box_line(line); box != 0) {
        s.style = box > 0 ? Style::box_start : Style::box_end;
        return s;
    }
    s.block = edit::parse_editor_line(line);
    if (!s.block) {
        s.style = edit::is_table_delimiter(line) ? Style::table_delimiter : Style::blank;
        return s;
    }
    s.level = s.block->level;
    switch (s.block->kind) {
        case BlockKind::heading: s.style = Style::heading; break;
        case BlockKind::list_item:
            s.style = s.block->spans.empty() || s.block->spans.front().text.starts_with(kBullet) ? Style::bullet_item
                                                                                                : Style::number_item;
            break;
        case BlockKind::quote: s.style = Style::quote; break;
        case BlockKind::note: s.style = Style::note; break;
        case BlockKind::print_page_break: s.style = Style::print_page_break; break;
        case BlockKind::braille_page_break: s.style = Style::braille_page_break; break;
        case BlockKind::braille: s.style = Style::braille; break;
        case BlockKind::table_row:
        case BlockKind::table_cell: s.style = Style::table_row; break;
        case BlockKind::paragraph: s.style = Style::body; break;
    }
    return s;
}

// Lines whose block shows no text of its own keep the line itself.
bool keeps_code(Style s) {
    return s == Style::print_page_break || s == Style::braille_page_break || s == Style::table_delimiter ||
           s == Style::blank || s == Style::braille || s == Style::box_start || s == Style::box_end;
}

}  // namespace

bool is_bold(const QTextCharFormat& format) { return format.fontWeight() >= QFont::Bold; }

QTextCharFormat base_char_format(Style style, int level, const QFont& base) {
    QTextCharFormat f;
    f.setFontWeight(QFont::Normal);
    f.setFontItalic(false);
    f.setFontUnderline(false);
    f.setVerticalAlignment(QTextCharFormat::AlignNormal);
    const qreal size = base.pointSizeF() > 0 ? base.pointSizeF() : 10.0;
    f.setFontPointSize(size);
    if (style == Style::heading) {
        static constexpr qreal kScale[] = {2.0, 1.6, 1.35, 1.2, 1.1, 1.0};
        f.setFontPointSize(size * kScale[std::clamp(level, 1, 6) - 1]);
        // Lighter than bold emphasis, so bold inside a heading stays bold text.
        f.setFontWeight(QFont::DemiBold);
    } else if (style == Style::table_delimiter) {
        f.setFontPointSize(2);
    }
    return f;
}

QTextBlockFormat block_format(Style style, int level) {
    QTextBlockFormat f;
    f.setProperty(kStyle, static_cast<int>(style));
    f.setProperty(kLevel, level);
    f.setBottomMargin(6);
    switch (style) {
        case Style::heading:
            f.setHeadingLevel(std::clamp(level, 1, 6));
            f.setTopMargin(8);
            break;
        case Style::bullet_item:
        case Style::number_item:
            f.setBottomMargin(2);
            break;
        case Style::quote:
            f.setLeftMargin(24.0 * std::max(level, 1));
            f.setRightMargin(24);
            f.setBackground(kQuoteTint);
            break;
        case Style::note:
            f.setBackground(kNoteTint);
            break;
        case Style::table_row:
            f.setBackground(kTableTint);
            f.setBottomMargin(0);
            break;
        case Style::table_delimiter:
            f.setBackground(kRuleTint);
            f.setBottomMargin(0);
            break;
        case Style::box_start:
        case Style::box_end:
            // The box line: a tinted band the pane writes the box's name on.
            f.setBackground(kBoxTint);
            break;
        default:
            break;
    }
    return f;
}

Style style_of(const QTextBlock& block) {
    const auto f = block.blockFormat();
    return f.hasProperty(kStyle) ? static_cast<Style>(f.intProperty(kStyle)) : Style::body;
}

void insert_picture(QTextCursor& cursor, const std::string& name, const std::string& description,
                    const edit::PictureStore* pictures) {
    const document::Image* image = nullptr;
    if (pictures)
        if (const auto it = pictures->find(name); it != pictures->end()) image = &it->second;
    const auto text = qs(description);
    const auto shown = picture_image(image, text, cursor.document()->defaultFont());
    const QString url = QStringLiteral("tactus-picture:") + qs(name);
    cursor.document()->addResource(QTextDocument::ImageResource, QUrl(url), shown);
    QTextImageFormat f;
    f.setName(url);
    f.setWidth(shown.width());
    f.setHeight(shown.height());
    f.setProperty(kPicture, qs(name));
    f.setProperty(kPictureDescription, text);
    f.setToolTip(text);
    cursor.insertImage(f);
}

QStringList picture_descriptions(const QTextBlock& block) {
    QStringList out;
    for (auto it = block.begin(); !it.atEnd(); ++it) {
        const auto frag = it.fragment();
        if (!frag.isValid() || !frag.charFormat().hasProperty(kPicture)) continue;
        for (const auto ch : frag.text())
            if (ch == QChar::ObjectReplacementCharacter) out << frag.charFormat().stringProperty(kPictureDescription);
    }
    return out;
}

void render(QTextDocument* doc, std::span<const std::string> lines, const QFont& base,
            const edit::PictureStore* pictures) {
    doc->clear();
    QTextCursor c(doc);
    c.beginEditBlock();
    const QFontMetricsF metrics(base);
    QTextList* list = nullptr;  // the list the previous line is in
    int list_level = 0;
    bool list_bullet = false;
    int next_number = 0;
    QList<QTextOption::Tab> tabs;  // the current table's columns
    for (std::size_t i = 0; i < lines.size(); ++i) {
        auto shown = classify(lines[i]);
        auto bf = block_format(shown.style, shown.level);
        if (keeps_code(shown.style)) bf.setProperty(kCode, qs(lines[i]));
        const auto cf = base_char_format(shown.style, shown.level, base);
        if (shown.style == Style::table_row || shown.style == Style::table_delimiter) {
            if (tabs.isEmpty()) {
                // Each column as wide as its widest cell in this table.
                std::vector<qreal> widths;
                for (auto j = i; j < lines.size(); ++j) {
                    const auto s = classify(lines[j]).style;
                    if (s != Style::table_row && s != Style::table_delimiter) break;
                    if (s != Style::table_row) continue;
                    const auto cells = edit::parse_table_cells(lines[j]);
                    if (widths.size() < cells.size()) widths.resize(cells.size());
                    for (std::size_t k = 0; k < cells.size(); ++k)
                        widths[k] = std::max(widths[k], metrics.horizontalAdvance(qs(cells[k].text())));
                }
                qreal x = 0;
                for (const auto w : widths) {
                    x += w + metrics.horizontalAdvance(QStringLiteral("MMM"));
                    tabs << QTextOption::Tab(x, QTextOption::LeftTab);
                }
            }
            bf.setTabPositions(tabs);
            if (shown.style == Style::table_row && i + 1 < lines.size() && edit::is_table_delimiter(lines[i + 1]))
                bf.setBackground(kHeaderTint);
        } else {
            tabs.clear();
        }
        if (i == 0) {
            c.setBlockFormat(bf);
            c.setBlockCharFormat(cf);
        } else {
            c.insertBlock(bf, cf);
        }
        c.setCharFormat(cf);
        auto& b = shown.block;
        switch (shown.style) {
            case Style::heading:
            case Style::quote:
            case Style::body:
                insert_spans(c, b->spans, cf, b->images, pictures);
                break;
            case Style::note:
                insert_spans(c, b->spans, cf, b->images, pictures);
                break;
            case Style::bullet_item:
            case Style::number_item: {
                if (shown.style == Style::number_item && !(list && !list_bullet && list_level == shown.level)) {
                    // A list counting from another number than 1: its numbers
                    // stay text, as QTextList (Qt 6.4) cannot start elsewhere.
                    auto probe = b->spans;
                    if (const auto m = take_mark(probe); m.number != 1) {
                        auto numbered = bf;
                        numbered.setProperty(kNumberText, true);
                        numbered.setIndent(std::max(shown.level, 1));
                        c.setBlockFormat(numbered);
                        insert_spans(c, b->spans, cf, b->images, pictures);
                        break;
                    }
                }
                const auto mark = take_mark(b->spans);
                const bool joins = list && list_level == shown.level && list_bullet == mark.bullet &&
                                   (mark.bullet || mark.number == next_number);
                if (joins) {
                    list->add(c.block());
                } else {
                    QTextListFormat lf;
                    lf.setIndent(std::max(shown.level, 1));
                    if (mark.bullet) {
                        lf.setStyle(bullet_style(shown.level));
                    } else {
                        lf.setStyle(QTextListFormat::ListDecimal);
                        lf.setNumberSuffix(QString(mark.suffix));
                    }
                    list = c.createList(lf);
                    list_level = shown.level;
                    list_bullet = mark.bullet;
                }
                next_number = mark.number + 1;
                insert_spans(c, b->spans, cf, b->images, pictures);
                continue;  // the list goes on
            }
            case Style::table_row: {
                const auto cells = edit::parse_table_cells(lines[i]);
                for (std::size_t k = 0; k < cells.size(); ++k) {
                    if (k) c.insertText(QString(kCellSeparator), cf);
                    insert_spans(c, cells[k].spans, cf, cells[k].images, pictures, true);
                }
                break;
            }
            case Style::braille:
                c.insertText(qs(std::string(exporter::markdown::trim(lines[i]))), cf);
                break;
            default:
                break;  // a break, a rule or a blank line: no text
        }
        list = nullptr;
    }
    c.endEditBlock();
}

std::string line_of(const QTextBlock& block) {
    const auto style = style_of(block);
    const auto f = block.blockFormat();
    const int level = f.intProperty(kLevel);
    const auto text = block.text();
    // Cells typed in the braille pane make the paragraph verbatim braille, whatever its style was.
    if (!text.isEmpty() && edit::is_braille_line(text.toStdString())) return text.toStdString();
    if (keeps_code(style)) {
        const auto code = f.stringProperty(kCode);
        if (style == Style::braille) return text.toStdString();  // cells as they are, as with codes shown
        if (text.isEmpty()) return code.toStdString();
        // Text typed into a break or a rule: a paragraph of its own (the break is replaced, nothing dropped).
    }
    Block b;
    b.level = level;
    std::vector<std::vector<document::Image>> images;
    if (style == Style::table_row) {
        document::Document row;
        auto spans = spans_of(block, true, &images);
        for (std::size_t k = 0; k < spans.size(); ++k) {
            Block cell;
            cell.kind = BlockKind::table_cell;
            cell.level = static_cast<int>(k);
            cell.spans = std::move(spans[k]);
            cell.images = std::move(images[k]);
            row.blocks.push_back(std::move(cell));
        }
        // A picture in a cell as its mark (edit/editor_pictures.hpp).
        return edit::render_with_picture_marks(row, [](const document::Document& d) {
            return std::vector<std::string>{exporter::markdown_table_row(d.blocks)};
        }).front();
    }
    b.spans = std::move(spans_of(block, false, &images).front());
    b.images = std::move(images.front());
    switch (style) {
        case Style::heading:
            b.kind = BlockKind::heading;
            b.level = std::clamp(level, 1, 6);
            break;
        case Style::bullet_item:
        case Style::number_item: {
            const auto* list = block.textList();
            if (!list && f.boolProperty(kNumberText)) {  // the number is in the text
                b.kind = BlockKind::list_item;
                b.level = std::max(f.indent(), 1);
                break;
            }
            if (!list) {  // taken out of its list (backspace at its start)
                b.kind = BlockKind::paragraph;
                break;
            }
            b.kind = BlockKind::list_item;
            b.level = std::max(list->format().indent(), 1);
            const bool bullet = list->format().style() != QTextListFormat::ListDecimal;
            const auto mark = bullet ? std::string(kBullet) : list->itemText(block).toStdString() + " ";
            if (!b.spans.empty() && b.spans.front().emphasis == document::emphasis_none &&
                !b.spans.front().note_reference && !b.spans.front().transcriber_note)
                b.spans.front().text.insert(0, mark);
            else
                b.spans.insert(b.spans.begin(), Span{mark});
            break;
        }
        case Style::quote:
            b.kind = BlockKind::quote;
            b.level = std::max(level, 1);
            break;
        case Style::note:
            b.kind = !b.spans.empty() && b.spans.front().note_reference ? BlockKind::note : BlockKind::paragraph;
            break;
        default:
            b.kind = BlockKind::paragraph;
            break;
    }
    if (b.kind == BlockKind::paragraph && b.spans.empty() && b.images.empty()) return {};
    return edit::render_editor_line(b);
}

namespace {

// The characters the line's content has before the block's text starts.
int lead_of(const QTextBlock& block) {
    const auto style = style_of(block);
    if ((style == Style::bullet_item || style == Style::number_item) && block.textList()) {
        const auto* list = block.textList();
        if (list->format().style() != QTextListFormat::ListDecimal) return static_cast<int>(QString::fromUtf8(kBullet.data(), static_cast<qsizetype>(kBullet.size())).size());
        return static_cast<int>(list->itemText(block).size()) + 1;
    }
    return 0;
}

}  // namespace

int content_column(const QTextBlock& block, int position) {
    const auto text = block.text();
    position = std::clamp(position, 0, static_cast<int>(text.size()));
    int col = lead_of(block) + position;
    // A table's cells are two spaces apart in the content, one tab apart here.
    if (style_of(block) == Style::table_row) col += static_cast<int>(text.left(position).count(kCellSeparator));
    return col;
}

int block_position(const QTextBlock& block, int content) {
    const auto text = block.text();
    int pos = std::max(0, content - lead_of(block));
    if (style_of(block) == Style::table_row) {
        int col = 0;
        for (int i = 0; i < text.size(); ++i) {
            if (col >= content - lead_of(block)) return i;
            col += text[i] == kCellSeparator ? 2 : 1;
        }
        return static_cast<int>(text.size());
    }
    return std::min(pos, static_cast<int>(text.size()));
}

}  // namespace tactus::gui::structured
