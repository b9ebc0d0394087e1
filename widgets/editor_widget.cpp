// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor_widget.hpp"

#include <QKeyEvent>
#include <QRegularExpression>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextList>

#include "braille_pane.hpp"
#include "structured_print.hpp"
#include "edit/cursor_map.hpp"
#include "edit/editor_lines.hpp"

namespace tactus::gui {
namespace {

// One step of the print document's own undo history, driven by the window's stack.
class TextUndoCommand : public QUndoCommand {
public:
    explicit TextUndoCommand(QTextDocument* doc) : doc_(doc) { setText(QObject::tr("typing")); }
    void undo() override { doc_->undo(); }
    void redo() override {
        if (first_) {  // the edit has already happened when the command is pushed
            first_ = false;
            return;
        }
        doc_->redo();
    }

private:
    QTextDocument* doc_;
    bool first_ = true;
};

int prefix_length(const QString& line) {
    static const QRegularExpression prefix(QStringLiteral(R"(^(#{1,6}\s+|\s*[-*+]\s+))"));
    const auto m = prefix.match(line);
    return m.hasMatch() ? static_cast<int>(m.capturedLength()) : 0;
}

// A text line's content is the line without its leading spaces (the text importer trims).
int leading_space(const QString& line) {
    int i = 0;
    while (i < line.size() && (line[i] == QLatin1Char(' ') || line[i] == QLatin1Char('\t'))) ++i;
    return i;
}

bool is_mark(QChar c) { return c == QLatin1Char('*') || c == QLatin1Char('_') || c == QLatin1Char('\\'); }

}  // namespace

int content_column(const QString& line, int column, edit::Dialect dialect) {
    const bool markdown = dialect == edit::Dialect::markdown;
    const int start = markdown ? prefix_length(line) : leading_space(line);
    int out = 0;
    for (int i = start; i < std::min(column, static_cast<int>(line.size())); ++i)
        if (!markdown || !is_mark(line[i])) ++out;
    return out;
}

int line_column(const QString& line, int content, edit::Dialect dialect) {
    const bool markdown = dialect == edit::Dialect::markdown;
    int i = markdown ? prefix_length(line) : leading_space(line);
    for (int seen = 0; i < line.size(); ++i) {
        if (markdown && is_mark(line[i])) continue;
        if (seen++ == content) return i;
    }
    return static_cast<int>(line.size());
}

EditorWidget::EditorWidget(QWidget* parent) : QSplitter(Qt::Horizontal, parent) {
    setObjectName(QStringLiteral("editor"));
    setChildrenCollapsible(false);
    print_ = new PrintPane(this);
    braille_ = new BraillePane(this);
    undo_ = new QUndoStack(this);
    // Braille cells need more size than letters for the dots to be told apart.
    QFont mono(QStringLiteral("DejaVu Sans Mono"));
    mono.setStyleHint(QFont::Monospace);
    mono.setPointSizeF(font().pointSizeF() * 1.6);
    braille_->setFont(mono);
    addWidget(print_);
    addWidget(braille_);
    setStretchFactor(0, 1);
    setStretchFactor(1, 1);

    auto* doc = print_->document();
    doc->setUndoRedoEnabled(true);
    connect(doc, &QTextDocument::undoCommandAdded, this,
            [this, doc] { undo_->push(new TextUndoCommand(doc)); });
    connect(doc, &QTextDocument::contentsChange, this, &EditorWidget::on_contents_change);
    print_->installEventFilter(this);
    connect(print_, &QTextEdit::cursorPositionChanged, this, &EditorWidget::sync_from_print);
    connect(print_, &QTextEdit::selectionChanged, this, &EditorWidget::sync_from_print);
    connect(braille_, &QPlainTextEdit::cursorPositionChanged, this, &EditorWidget::sync_from_braille);
    connect(braille_, &BraillePane::cells_typed, this, &EditorWidget::braille_typed);
    connect(braille_, &BraillePane::erase_backward, this, [this] { braille_erase(true); });
    connect(braille_, &BraillePane::erase_forward, this, [this] { braille_erase(false); });
    connect(braille_, &BraillePane::new_paragraph, this, &EditorWidget::braille_new_paragraph);
    connect(print_, &PrintPane::files_dropped, this, &EditorWidget::files_dropped);
    // A text file's form feed has no glyph: the line shows what it is.
    print_->set_line_marker([this](int line) {
        if (!layout_ || static_cast<std::size_t>(line) >= layout_->line_count()) return QString{};
        // Only where the line shows no text of its own: a form feed, or a break in the structured view.
        if (!print_->document()->findBlockByNumber(line).text().trimmed().isEmpty()) return QString{};
        if (structured()) {
            switch (structured::style_of(print_->document()->findBlockByNumber(line))) {
                case structured::Style::braille_page_break: return tr("Braille page break");
                case structured::Style::box_start:
                case structured::Style::box_end: return structure_text(line);
                default: break;
            }
        }
        return page_break_text(line);
    });
}

QString EditorWidget::page_break_text(int line) const {
    if (!layout_ || line < 0 || static_cast<std::size_t>(line) >= layout_->line_count()) return {};
    const auto i = static_cast<std::size_t>(line);
    const auto block = edit::parse_editor_line(layout_->line(i), layout_->dialect());
    // In a text file a form feed inside a line ("\fChapter 2") starts a page too.
    const bool form_feed = layout_->dialect() == edit::Dialect::text && layout_->line(i).find('\f') != std::string::npos;
    if (!form_feed && (!block || block->kind != document::BlockKind::print_page_break)) return {};
    // The print page it starts, by core's numbering (document/print_page.hpp).
    const auto page = QString::fromStdString(layout_->print_page_at(i));
    return page.isEmpty() ? tr("Print page break") : tr("Print page break, page %1").arg(page);
}

QString EditorWidget::structure_text(int line) const {
    if (!structured() || !layout_) return {};
    const auto block = print_->document()->findBlockByNumber(line);
    if (!block.isValid()) return {};
    // A picture shows no text a screen reader could read: its description is said.
    QStringList said;
    if (const auto kind = paragraph_text(block); !kind.isEmpty()) said << kind;
    for (const auto& description : structured::picture_descriptions(block))
        said << (description.isEmpty() ? tr("Picture without a description") : tr("Picture: %1").arg(description));
    return said.join(QStringLiteral(". "));
}

QString EditorWidget::paragraph_text(const QTextBlock& block) const {
    using structured::Style;
    switch (structured::style_of(block)) {
        case Style::heading:
            return tr("Heading level %1").arg(block.blockFormat().headingLevel());
        case Style::bullet_item:
        case Style::number_item:
            if (const auto* list = block.textList())
                return list->format().style() == QTextListFormat::ListDecimal
                           ? tr("List item %1").arg(list->itemText(block))
                           : tr("List item");
            return block.blockFormat().boolProperty(structured::kNumberText) ? tr("List item") : QString();
        case Style::quote:
            return tr("Quotation");
        case Style::note:
            return tr("Note");
        case Style::box_start:
            return tr("Box");
        case Style::box_end:
            return tr("End of box");
        case Style::table_row: {
            // Its place among the table's rows (the rule under the header is no row).
            int row = 1, rows = 0;
            for (auto b = block.previous(); b.isValid(); b = b.previous()) {
                const auto s = structured::style_of(b);
                if (s == Style::table_row) ++row;
                else if (s != Style::table_delimiter) break;
            }
            rows = row;
            for (auto b = block.next(); b.isValid(); b = b.next()) {
                const auto s = structured::style_of(b);
                if (s == Style::table_row) ++rows;
                else if (s != Style::table_delimiter) break;
            }
            const auto next = block.next();
            const bool header = next.isValid() && structured::style_of(next) == Style::table_delimiter;
            return header ? tr("Table header row, %1 columns").arg(block.text().count(QLatin1Char('\t')) + 1)
                          : tr("Table row %1 of %2").arg(row).arg(rows);
        }
        default:
            return {};
    }
}

EditorWidget::~EditorWidget() = default;

QString EditorWidget::braille_text(std::size_t line) const {
    return QString::fromStdString(document::to_unicode_text(layout_->braille_of(line)));
}

void EditorWidget::adopt(edit::LiveLayout layout) {
    layout_ = std::move(layout);
    print_->set_text_file(layout_->dialect() == edit::Dialect::text);
    syncing_ = true;
    QStringList print, braille;
    print.reserve(static_cast<qsizetype>(layout_->line_count()));
    for (std::size_t i = 0; i < layout_->line_count(); ++i) {
        print << QString::fromStdString(layout_->line(i));
        braille << braille_text(i);
    }
    show_lines(print);
    braille_->document()->setPlainText(braille.join(QLatin1Char('\n')));
    known_blocks_ = print_->document()->blockCount();
    // An empty document is one empty line for the widget: keep the layout in
    // step. Should the view ever show a line as more than one block, its
    // lines are read back from the view: never replaced by empty ones.
    if (layout_->line_count() != static_cast<std::size_t>(known_blocks_)) {
        std::vector<std::string> shown;
        for (auto b = print_->document()->begin(); b.isValid(); b = b.next()) shown.push_back(line_text(b));
        layout_->replace(0, layout_->line_count(), std::move(shown));
    }
    undo_->clear();
    undo_->setClean();
    print_->document()->clearUndoRedoStacks();
    print_->moveCursor(QTextCursor::Start);
    syncing_ = false;
    Q_EMIT layout_changed();
    sync_from_print();
}

void EditorWidget::swap_layout(edit::LiveLayout layout) {
    if (layout_) {  // the same file
        layout.set_line_ending(layout_->line_ending());
        layout.set_encoding(layout_->encoding(), layout_->byte_order_mark());
        layout.set_pictures(layout_->pictures());  // the lines' marks name them
    }
    layout_ = std::move(layout);
    refresh_braille();
}

Result<void> EditorWidget::set_tables(const std::string& tables) {
    if (!layout_) return fail(ErrorKind::internal, "no document", "table");
    if (auto ok = layout_->set_tables(tables); !ok) return ok;
    refresh_braille();
    return {};
}

void EditorWidget::refresh_braille() {
    syncing_ = true;
    QStringList braille;
    for (std::size_t i = 0; i < layout_->line_count(); ++i) braille << braille_text(i);
    braille_->document()->setPlainText(braille.join(QLatin1Char('\n')));
    syncing_ = false;
    Q_EMIT layout_changed();
    sync_from_print();
}

Result<void> EditorWidget::set_layout_options(const layout::LayoutOptions& options) {
    if (!layout_) return fail(ErrorKind::internal, "no document", "layout");
    if (auto ok = layout_->set_options(options); !ok) return ok;
    Q_EMIT layout_changed();
    sync_from_print();
    return {};
}

QString EditorWidget::text() const {
    if (!layout_) return print_->document()->toPlainText();
    QStringList lines;
    lines.reserve(static_cast<qsizetype>(layout_->line_count()));
    for (std::size_t i = 0; i < layout_->line_count(); ++i) lines << QString::fromStdString(layout_->line(i));
    return lines.join(QLatin1Char('\n'));
}

bool EditorWidget::structured() const {
    return !codes_ && (!layout_ || layout_->dialect() == edit::Dialect::markdown);
}

void EditorWidget::show_lines(const QStringList& lines) {
    const QSignalBlocker block(print_->document());
    print_->set_codes_shown(codes_);
    if (structured()) {
        std::vector<std::string> model;
        model.reserve(static_cast<std::size_t>(lines.size()));
        for (const auto& l : lines) model.push_back(l.toStdString());
        structured::render(print_->document(), model, print_->font(), layout_ ? &layout_->pictures() : nullptr);
    } else {
        print_->document()->setPlainText(lines.join(QLatin1Char('\n')));
        // Codes are shown in the pane's own font, whatever the structured view set.
        QTextCursor all(print_->document());
        all.select(QTextCursor::Document);
        all.setCharFormat(structured::base_char_format(structured::Style::body, 0, print_->font()));
    }
    print_->document()->clearUndoRedoStacks();
}

void EditorWidget::set_codes_shown(bool codes) {
    if (codes == codes_) return;
    codes_ = codes;
    if (!layout_) {
        print_->set_codes_shown(codes_);
        return;
    }
    const int line = current_line();
    syncing_ = true;
    QStringList lines;
    for (std::size_t i = 0; i < layout_->line_count(); ++i) lines << QString::fromStdString(layout_->line(i));
    show_lines(lines);
    // The print document's history was of the other view: the window's stack goes with it.
    undo_->clear();
    print_->setTextCursor(QTextCursor(print_->document()->findBlockByNumber(line)));
    syncing_ = false;
    sync_from_print();
}

bool EditorWidget::eventFilter(QObject* watched, QEvent* event) {
    if (watched != print_ || event->type() != QEvent::KeyPress || !structured() || print_->isReadOnly())
        return QSplitter::eventFilter(watched, event);
    const auto* key = static_cast<QKeyEvent*>(event);
    if ((key->key() != Qt::Key_Return && key->key() != Qt::Key_Enter) ||
        (key->modifiers() & ~Qt::KeypadModifier) != Qt::NoModifier)
        return false;
    auto c = print_->textCursor();
    using structured::Style;
    const auto style = structured::style_of(c.block());
    const bool ends_style = style == Style::heading || style == Style::print_page_break ||
                            style == Style::braille_page_break || style == Style::table_delimiter ||
                            style == Style::blank || style == Style::note || style == Style::box_start ||
                            style == Style::box_end;
    if (!ends_style || c.hasSelection() || !c.atBlockEnd()) return false;
    // The new paragraph is body text (a copy of a break's format would be a second break).
    c.insertBlock(structured::block_format(Style::body, 0), structured::base_char_format(Style::body, 0, print_->font()));
    print_->setTextCursor(c);
    return true;
}

void EditorWidget::set_paragraph_style(ParagraphStyle style, int level) {
    if (!structured() || !layout_) return;
    using structured::Style;
    const Style shown = style == ParagraphStyle::heading     ? Style::heading
                        : style == ParagraphStyle::bulleted  ? Style::bullet_item
                        : style == ParagraphStyle::numbered  ? Style::number_item
                        : style == ParagraphStyle::quotation ? Style::quote
                                                             : Style::body;
    auto c = print_->textCursor();
    auto* doc = print_->document();
    const auto first = doc->findBlock(c.selectionStart());
    const auto last = doc->findBlock(c.selectionEnd());
    const auto base = structured::base_char_format(shown, level, print_->font());
    QTextCursor edit(doc);
    edit.beginEditBlock();
    QTextList* list = nullptr;
    for (auto b = first; b.isValid() && b.blockNumber() <= last.blockNumber(); b = b.next()) {
        edit.setPosition(b.position());
        if (auto* old = b.textList()) old->remove(b);
        auto bf = structured::block_format(shown, shown == Style::heading ? level : 1);
        edit.setBlockFormat(bf);
        edit.setBlockCharFormat(base);
        // The text takes the style's size and weight; its emphasis stays.
        for (auto it = b.begin(); !it.atEnd(); ++it) {
            const auto frag = it.fragment();
            QTextCharFormat f;
            f.setFontPointSize(base.fontPointSize());
            if (!structured::is_bold(frag.charFormat())) f.setFontWeight(base.fontWeight());
            QTextCursor run(doc);
            run.setPosition(frag.position());
            run.setPosition(frag.position() + frag.length(), QTextCursor::KeepAnchor);
            run.mergeCharFormat(f);
        }
        if (shown == Style::bullet_item || shown == Style::number_item) {
            if (list) {
                list->add(b);
            } else {
                QTextListFormat lf;
                lf.setIndent(1);
                lf.setStyle(shown == Style::bullet_item ? QTextListFormat::ListDisc : QTextListFormat::ListDecimal);
                list = edit.createList(lf);
            }
        }
    }
    edit.endEditBlock();
}

namespace {

// Whether all of the cursor's selection (or, without one, what is typed next)
// has a char format property. A style is turned on when any of the
// selection lacks it, as word processors do.
template <typename Has>
bool all_of_selection(const QTextCursor& c, QTextDocument* doc, Has has) {
    if (!c.hasSelection()) return has(c.charFormat());
    for (auto b = doc->findBlock(c.selectionStart()); b.isValid() && b.position() < c.selectionEnd(); b = b.next())
        for (auto it = b.begin(); !it.atEnd(); ++it) {
            const auto frag = it.fragment();
            if (frag.position() + frag.length() <= c.selectionStart() || frag.position() >= c.selectionEnd()) continue;
            if (!has(frag.charFormat())) return false;
        }
    return true;
}

}  // namespace

void EditorWidget::toggle_emphasis(std::uint8_t emphasis) {
    if (!structured() || !layout_) return;
    auto c = print_->textCursor();
    const auto has = [emphasis](const QTextCharFormat& f) {
        return emphasis == document::emphasis_bold        ? structured::is_bold(f)
               : emphasis == document::emphasis_underline ? f.fontUnderline()
                                                          : f.fontItalic();
    };
    const bool all = all_of_selection(c, print_->document(), has);
    QTextCharFormat f;
    if (emphasis == document::emphasis_bold) {
        const bool heading = structured::style_of(c.block()) == structured::Style::heading;
        f.setFontWeight(all ? (heading ? QFont::DemiBold : QFont::Normal) : QFont::Bold);
    } else if (emphasis == document::emphasis_underline) {
        f.setFontUnderline(!all);
    } else {
        f.setFontItalic(!all);
    }
    if (c.hasSelection()) c.mergeCharFormat(f);
    else print_->mergeCurrentCharFormat(f);  // what is typed next
}

void EditorWidget::toggle_position(document::Position position) {
    if (!structured() || !layout_ || position == document::Position::baseline) return;
    auto c = print_->textCursor();
    const auto has = [position](const QTextCharFormat& f) {
        return !f.boolProperty(structured::kNoteRef) && f.hasProperty(structured::kPosition) &&
               f.intProperty(structured::kPosition) == static_cast<int>(position);
    };
    const bool all = all_of_selection(c, print_->document(), has);
    // Off is the baseline, said as a property (a merge cannot take one away).
    const auto now = all ? document::Position::baseline : position;
    QTextCharFormat f;
    f.setProperty(structured::kPosition, static_cast<int>(now));
    f.setVerticalAlignment(now == document::Position::superscript ? QTextCharFormat::AlignSuperScript
                           : now == document::Position::subscript ? QTextCharFormat::AlignSubScript
                                                                  : QTextCharFormat::AlignNormal);
    if (c.hasSelection()) c.mergeCharFormat(f);
    else print_->mergeCurrentCharFormat(f);
}

void EditorWidget::set_language(const QString& tag, bool paragraph) {
    if (!structured() || !layout_) return;
    auto* doc = print_->document();
    const auto c = print_->textCursor();
    // The mark as a property with the tag; "" takes it away (a merge cannot
    // take a property away, and an empty tag is no language: structured::line_of).
    QTextCharFormat f;
    f.setProperty(structured::kLanguage, tag);
    QTextCursor edit(doc);
    if (paragraph) {
        const auto first = doc->findBlock(c.selectionStart());
        const auto last = doc->findBlock(c.selectionEnd());
        edit.setPosition(first.position());
        edit.setPosition(last.position() + last.length() - 1, QTextCursor::KeepAnchor);
    } else if (c.hasSelection()) {
        edit = c;
    } else {
        // No selection: the word the cursor is in, as a word processor does;
        // between words, what is typed next.
        edit = c;
        edit.select(QTextCursor::WordUnderCursor);
        static const QRegularExpression letter(QStringLiteral("[\\p{L}\\p{N}]"));
        if (!edit.selectedText().contains(letter)) {
            print_->mergeCurrentCharFormat(f);
            return;
        }
    }
    edit.beginEditBlock();
    if (edit.hasSelection()) edit.mergeCharFormat(f);
    // An empty paragraph's own format: what is typed in it.
    if (paragraph)
        for (auto b = doc->findBlock(edit.selectionStart()); b.isValid() && b.position() <= edit.selectionEnd(); b = b.next())
            if (b.length() <= 1) QTextCursor(b).mergeBlockCharFormat(f);
    edit.endEditBlock();
    if (!c.hasSelection()) print_->mergeCurrentCharFormat(f);  // typed at the cursor next
}

QString EditorWidget::language_at_cursor() const {
    if (!structured()) return {};
    auto c = print_->textCursor();
    c.clearSelection();
    if (!c.atBlockEnd()) c.movePosition(QTextCursor::NextCharacter);
    return c.charFormat().stringProperty(structured::kLanguage);
}

void EditorWidget::insert_page_break() {
    if (!structured() || !layout_) return;
    const auto block = print_->textCursor().block();
    QTextCursor edit(block);  // at the paragraph's start
    edit.beginEditBlock();
    // The paragraph moves down a block as it was; the empty block left above it is the break.
    edit.insertBlock(block.blockFormat(), block.charFormat());
    edit.movePosition(QTextCursor::PreviousBlock);
    if (auto* list = edit.block().textList()) list->remove(edit.block());
    auto bf = structured::block_format(structured::Style::print_page_break, 0);
    bf.setProperty(structured::kCode, QStringLiteral("<!-- pagebreak -->"));
    edit.setBlockFormat(bf);
    edit.setBlockCharFormat(structured::base_char_format(structured::Style::body, 0, print_->font()));
    edit.endEditBlock();
}

bool EditorWidget::insert_picture(document::Image image, const QString& description) {
    if (!layout_ || layout_->dialect() != edit::Dialect::markdown || print_->isReadOnly()) return false;
    const auto name = layout_->add_picture(std::move(image));
    auto c = print_->textCursor();
    if (c.hasSelection()) c.setPosition(c.selectionEnd());
    c.beginEditBlock();
    if (!structured()) {
        // The codes view: the picture's mark, a line of its own.
        c.movePosition(QTextCursor::EndOfBlock);
        c.insertText(QStringLiteral("\n") + QString::fromStdString(edit::picture_mark(description.toStdString(), name)));
        c.endEditBlock();
        print_->setTextCursor(c);
        return true;
    }
    using structured::Style;
    const auto base = structured::base_char_format(Style::body, 0, print_->font());
    if (!c.block().text().isEmpty() || structured::style_of(c.block()) != Style::body) {
        c.movePosition(QTextCursor::EndOfBlock);
        c.insertBlock(structured::block_format(Style::body, 0), base);
        if (auto* list = c.block().textList()) list->remove(c.block());
    }
    structured::insert_picture(c, name, description.toStdString(), &layout_->pictures());
    c.endEditBlock();
    print_->setTextCursor(c);
    print_->setCurrentCharFormat(base);
    return true;
}

QString EditorWidget::insert_note() {
    if (!structured() || !layout_ || print_->isReadOnly()) return {};
    using structured::Style;
    auto* doc = print_->document();
    auto c = print_->textCursor();
    if (c.hasSelection()) c.setPosition(c.selectionEnd());
    // Not inside a line that stands for no text (a page break, a box line),
    // nor a note's own text: a note has no notes.
    const auto here = structured::style_of(c.block());
    if (here == Style::note || here == Style::print_page_break || here == Style::braille_page_break ||
        here == Style::box_start || here == Style::box_end || here == Style::table_delimiter || here == Style::braille)
        return {};
    // The next number after every numbered reference in the document.
    int next = 1;
    for (auto b = doc->begin(); b.isValid(); b = b.next())
        for (auto it = b.begin(); !it.atEnd(); ++it) {
            const auto frag = it.fragment();
            if (!frag.charFormat().boolProperty(structured::kNoteRef)) continue;
            bool ok = false;
            const int n = frag.text().toInt(&ok);
            if (ok && n >= next) next = n + 1;
        }
    const auto reference = QString::number(next);
    const auto raised = [](QTextCharFormat f) {
        f.setProperty(structured::kNoteRef, true);
        f.setVerticalAlignment(QTextCharFormat::AlignSuperScript);
        return f;
    };
    c.beginEditBlock();
    auto ref_format = c.charFormat();
    ref_format.clearProperty(structured::kPosition);
    c.insertText(reference, raised(ref_format));
    QTextCursor at(c.block());
    at.movePosition(QTextCursor::EndOfBlock);
    const auto base = structured::base_char_format(Style::note, 0, print_->font());
    at.insertBlock(structured::block_format(Style::note, 0), base);
    if (auto* list = at.block().textList()) list->remove(at.block());
    at.insertText(reference, raised(base));
    at.insertText(QStringLiteral(" "), base);
    c.endEditBlock();
    print_->setTextCursor(at);
    print_->setCurrentCharFormat(base);  // the note's text, not its raised reference
    return reference;
}

void EditorWidget::toggle_box() {
    if (!structured() || !layout_) return;
    using structured::Style;
    auto* doc = print_->document();
    const auto c = print_->textCursor();
    auto first = doc->findBlock(c.selectionStart());
    auto last = doc->findBlock(c.selectionEnd());
    // A box line selected on its own stands for its box.
    if (structured::style_of(first) == Style::box_end && first.blockNumber() == last.blockNumber()) first = first.previous();
    // The box the first paragraph is in: a box line above it with no end between.
    QTextBlock open, close;
    int depth = 0;
    for (auto b = structured::style_of(first) == Style::box_start ? first : first.previous(); b.isValid(); b = b.previous()) {
        const auto s = structured::style_of(b);
        if (s == Style::box_end) ++depth;
        if (s == Style::box_start && depth-- == 0) {
            open = b;
            break;
        }
    }
    if (open.isValid()) {
        depth = 0;
        for (auto b = open.next(); b.isValid(); b = b.next()) {
            const auto s = structured::style_of(b);
            if (s == Style::box_start) ++depth;
            if (s == Style::box_end && depth-- == 0) {
                close = b;
                break;
            }
        }
    }
    const auto box_line = [this](Style style) {
        auto bf = structured::block_format(style, 0);
        bf.setProperty(structured::kCode, QString::fromUtf8(style == Style::box_start ? "<!-- box -->" : "<!-- /box -->"));
        return bf;
    };
    QTextCursor edit(doc);
    edit.beginEditBlock();
    if (open.isValid()) {
        // Out of the box: its lines go, its paragraphs stay.
        for (auto b : {close, open}) {
            if (!b.isValid()) continue;
            if (const auto above = b.previous(); above.isValid()) {
                // Joined to the paragraph above, which keeps its format.
                const auto format = above.blockFormat();
                const auto chars = above.charFormat();
                edit.setPosition(above.position() + above.length() - 1);
                edit.setPosition(b.position() + b.length() - 1, QTextCursor::KeepAnchor);
                edit.removeSelectedText();
                edit.setBlockFormat(format);
                edit.setBlockCharFormat(chars);
            } else if (const auto below = b.next(); below.isValid()) {
                // The document's first line: the paragraph below takes its place, with its own format.
                const auto format = below.blockFormat();
                const auto chars = below.charFormat();
                edit.setPosition(b.position());
                edit.setPosition(below.position(), QTextCursor::KeepAnchor);
                edit.removeSelectedText();
                edit.setBlockFormat(format);
                edit.setBlockCharFormat(chars);
            }
        }
    } else {
        const auto body = structured::base_char_format(Style::body, 0, print_->font());
        // The line below first, so the first paragraph's position holds.
        edit.setPosition(last.position() + last.length() - 1);
        edit.insertBlock(box_line(Style::box_end), body);
        edit.setPosition(first.position());
        edit.insertBlock(first.blockFormat(), first.charFormat());
        edit.movePosition(QTextCursor::PreviousBlock);
        if (auto* list = edit.block().textList()) list->remove(edit.block());
        edit.setBlockFormat(box_line(Style::box_start));
        edit.setBlockCharFormat(body);
    }
    edit.endEditBlock();
}

std::string EditorWidget::line_text(const QTextBlock& block) const {
    return structured() ? structured::line_of(block) : block.text().toStdString();
}

std::size_t EditorWidget::cell_at(const QTextBlock& block, int position) const {
    const auto i = static_cast<std::size_t>(block.blockNumber());
    const auto cells = i < layout_->line_count() ? layout_->braille_of(i) : document::BrailleLine{};
    const auto& line = i < layout_->line_count() ? layout_->line(i) : std::string();
    if (edit::is_braille_line(line)) return std::min(static_cast<std::size_t>(position), cells.size());
    const auto content = QString::fromStdString(edit::editor_line_content(line, layout_->dialect())).toStdU32String();
    const int column = structured() ? structured::content_column(block, position)
                                    : content_column(block.text(), position, layout_->dialect());
    return edit::print_to_braille(content, static_cast<std::size_t>(column), cells);
}

int EditorWidget::position_at(const QTextBlock& block, std::size_t cell) const {
    const auto i = static_cast<std::size_t>(block.blockNumber());
    const auto& line = layout_->line(i);
    if (edit::is_braille_line(line)) return std::min(static_cast<int>(cell), block.length() - 1);
    const auto content = QString::fromStdString(edit::editor_line_content(line, layout_->dialect())).toStdU32String();
    const auto col = static_cast<int>(edit::braille_to_print(layout_->braille_of(i), cell, content));
    const int at = structured() ? structured::block_position(block, col) : line_column(block.text(), col, layout_->dialect());
    return std::min(at, block.length() - 1);
}

void EditorWidget::on_contents_change(int position, int removed, int added) {
    if (!layout_) return;
    Q_UNUSED(removed);
    auto* doc = print_->document();
    const int first = doc->findBlock(position).blockNumber();
    // A format change reports the block's end too: past the last block at the document's end.
    const auto end_block = doc->findBlock(position + added);
    const int last = end_block.isValid() ? end_block.blockNumber() : doc->lastBlock().blockNumber();
    // A list's items renumbered by an edit are reported with it (QTextList
    // marks them changed), so their lines are written again with their numbers.
    const int now = doc->blockCount();
    const int count = std::max(0, last - first + 1);
    const int old_count = count - (now - known_blocks_);
    known_blocks_ = now;
    std::vector<std::string> lines;
    lines.reserve(static_cast<std::size_t>(count));
    for (auto b = doc->findBlockByNumber(first); b.isValid() && b.blockNumber() <= last; b = b.next())
        lines.push_back(line_text(b));
    last_stats_ = layout_->replace(static_cast<std::size_t>(first), static_cast<std::size_t>(std::max(0, old_count)),
                                   std::move(lines));
    replace_braille_blocks(first, std::max(0, old_count), count);
    // Lines around the edit whose braille changed with it: the other lines of
    // a hard-wrapped text paragraph (brailled as one), a table's header row.
    const bool was = syncing_;
    syncing_ = true;
    for (auto i = last_stats_.braille_first; i < last_stats_.braille_end && i < layout_->line_count(); ++i) {
        if (i >= static_cast<std::size_t>(first) && i < static_cast<std::size_t>(first + count)) continue;
        const auto block = braille_->document()->findBlockByNumber(static_cast<int>(i));
        if (block.isValid()) replace_changed_cells(block, braille_text(i));
    }
    syncing_ = was;
    Q_EMIT layout_changed();
}

void EditorWidget::replace_braille_blocks(int first, int removed, int count) {
    const bool was = syncing_;
    syncing_ = true;
    auto* doc = braille_->document();
    QStringList lines;
    for (int i = first; i < first + count; ++i) lines << braille_text(static_cast<std::size_t>(i));
    QTextCursor c(doc);
    const auto start = doc->findBlockByNumber(first);
    if (removed == count && start.isValid()) {
        // The same paragraphs changed in place: change only the cells that differ.
        // A six-key chord then inserts its one cell, which is what a screen reader
        // echoes; replacing the paragraph made Orca say nothing and moved the caret.
        auto block = start;
        for (const auto& line : lines) {
            replace_changed_cells(block, line);
            block = block.next();
        }
    } else if (removed > 0 && start.isValid()) {
        const auto end = doc->findBlockByNumber(first + removed - 1);
        c.setPosition(start.position());
        c.setPosition(end.position() + end.length() - 1, QTextCursor::KeepAnchor);
        c.insertText(lines.join(QLatin1Char('\n')));
    } else if (start.isValid()) {
        c.setPosition(start.position());
        c.insertText(lines.join(QLatin1Char('\n')) + QLatin1Char('\n'));
    } else {
        c.movePosition(QTextCursor::End);
        c.insertText(QLatin1Char('\n') + lines.join(QLatin1Char('\n')));
    }
    syncing_ = was;
}

void EditorWidget::replace_changed_cells(const QTextBlock& block, const QString& text) {
    const auto old = block.text();
    qsizetype prefix = 0;
    const auto shorter = std::min(old.size(), text.size());
    while (prefix < shorter && old[prefix] == text[prefix]) ++prefix;
    qsizetype suffix = 0;
    while (suffix < shorter - prefix && old[old.size() - 1 - suffix] == text[text.size() - 1 - suffix]) ++suffix;
    if (prefix == old.size() && prefix == text.size()) return;  // unchanged: no event at all
    QTextCursor c(block);
    c.setPosition(block.position() + static_cast<int>(prefix));
    c.setPosition(block.position() + static_cast<int>(old.size() - suffix), QTextCursor::KeepAnchor);
    c.insertText(text.mid(prefix, text.size() - prefix - suffix));
}

int EditorWidget::current_line() const { return print_->textCursor().blockNumber(); }

std::size_t EditorWidget::current_cell() const {
    if (!layout_) return 0;
    const auto c = print_->textCursor();
    if (static_cast<std::size_t>(c.blockNumber()) >= layout_->line_count()) return 0;
    return cell_at(c.block(), c.positionInBlock());
}

edit::PagePosition EditorWidget::current_position() const {
    if (!layout_) return {};
    return layout_->position_of(static_cast<std::size_t>(current_line()), current_cell());
}

void EditorWidget::sync_from_print() {
    if (syncing_ || !layout_) return;
    syncing_ = true;
    const auto pc = print_->textCursor();
    const auto map_pos = [&](int pos) {
        const auto block = print_->document()->findBlock(pos);
        const auto cell = cell_at(block, pos - block.position());
        const auto bb = braille_->document()->findBlockByNumber(block.blockNumber());
        return bb.isValid() ? bb.position() + std::min(static_cast<int>(cell), bb.length() - 1) : 0;
    };
    QTextCursor bc(braille_->document());
    bc.setPosition(map_pos(pc.anchor()));
    bc.setPosition(map_pos(pc.position()), QTextCursor::KeepAnchor);
    braille_->setTextCursor(bc);
    braille_->ensureCursorVisible();
    syncing_ = false;
    Q_EMIT position_changed(current_position());
    // Coming to a page break line, the reader hears what it is.
    const int line = pc.blockNumber();
    if (line != cursor_line_) {
        cursor_line_ = line;
        if (const auto spoken = page_break_text(line); !spoken.isEmpty()) Q_EMIT page_break_reached(spoken);
        else if (const auto said = structure_text(line); !said.isEmpty()) Q_EMIT structure_reached(said);
    }
}

void EditorWidget::sync_from_braille() {
    if (syncing_ || !layout_) return;
    syncing_ = true;
    const auto bc = braille_->textCursor();
    const auto map_pos = [&](int pos) {
        const auto bblock = braille_->document()->findBlock(pos);
        const auto i = static_cast<std::size_t>(bblock.blockNumber());
        const auto pblock = print_->document()->findBlockByNumber(bblock.blockNumber());
        if (!pblock.isValid() || i >= layout_->line_count()) return 0;
        return pblock.position() + position_at(pblock, static_cast<std::size_t>(pos - bblock.position()));
    };
    QTextCursor pc(print_->document());
    pc.setPosition(map_pos(bc.anchor()));
    pc.setPosition(map_pos(bc.position()), QTextCursor::KeepAnchor);
    print_->setTextCursor(pc);
    print_->ensureCursorVisible();
    syncing_ = false;
    if (layout_) {
        const auto i = static_cast<std::size_t>(bc.blockNumber());
        Q_EMIT position_changed(layout_->position_of(i, static_cast<std::size_t>(bc.positionInBlock())));
    }
}

void EditorWidget::edit_braille(std::size_t line, std::size_t from, std::size_t to, const document::BrailleLine& cells) {
    if (!layout_ || line >= layout_->line_count()) return;
    auto current = layout_->braille_of(line);
    from = std::min(from, current.size());
    to = std::clamp(to, from, current.size());
    current.erase(current.begin() + static_cast<std::ptrdiff_t>(from), current.begin() + static_cast<std::ptrdiff_t>(to));
    current.insert(current.begin() + static_cast<std::ptrdiff_t>(from), cells.begin(), cells.end());
    // The paragraph becomes verbatim braille: the print line holds its cells.
    const auto block = print_->document()->findBlockByNumber(static_cast<int>(line));
    QTextCursor c(block);
    c.beginEditBlock();
    c.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
    if (structured()) {
        // Shown as what it is now: cells, in the pane's own font.
        if (auto* list = block.textList()) list->remove(block);
        auto bf = structured::block_format(structured::Style::braille, 0);
        c.setBlockFormat(bf);
        c.insertText(QString::fromStdString(document::to_unicode_text(current)),
                     structured::base_char_format(structured::Style::body, 0, print_->font()));
    } else {
        c.insertText(QString::fromStdString(document::to_unicode_text(current)));
    }
    c.endEditBlock();
    // Put the braille caret after what was typed.
    const auto bb = braille_->document()->findBlockByNumber(static_cast<int>(line));
    QTextCursor bc(bb);
    bc.setPosition(bb.position() + static_cast<int>(from + cells.size()));
    braille_->setTextCursor(bc);
}

void EditorWidget::braille_typed(const document::BrailleLine& cells) {
    // The braille pane edits the print text: not while that is read only (a
    // graphic's description, a re-layout under way).
    if (print_->isReadOnly()) return;
    const auto c = braille_->textCursor();
    const auto line = static_cast<std::size_t>(braille_->document()->findBlock(c.selectionStart()).blockNumber());
    const auto start_block = braille_->document()->findBlock(c.selectionStart());
    const auto end_block = braille_->document()->findBlock(c.selectionEnd());
    const auto from = static_cast<std::size_t>(c.selectionStart() - start_block.position());
    // A selection running over several paragraphs is cut at the end of the first.
    const auto to = end_block == start_block ? static_cast<std::size_t>(c.selectionEnd() - start_block.position())
                                             : static_cast<std::size_t>(start_block.length() - 1);
    edit_braille(line, from, to, cells);
    // Space types a blank cell: echoed as a chord is, since a screen reader
    // says nothing for the blank braille pattern.
    if (cells.size() == 1 && cells.front().blank()) Q_EMIT cell_entered(tr("blank cell"));
    if (cells.size() == 1 && !cells.front().blank() && layout_) {
        // "dots 1 2", not "1-2": a screen reader reads the dash as "minus" or a range.
        const auto dots = QString::fromStdString(document::dot_numbers(cells.front())).replace(QLatin1Char('-'), QLatin1Char(' '));
        auto spoken = tr("dots %1").arg(dots);
        if (const auto print = QString::fromStdString(layout_->back_translate(cells)).trimmed(); !print.isEmpty())
            spoken += QStringLiteral(", ") + print;
        Q_EMIT cell_entered(spoken);
    }
}

void EditorWidget::braille_erase(bool backward) {
    if (print_->isReadOnly()) return;
    const auto c = braille_->textCursor();
    const auto block = c.block();
    const auto line = static_cast<std::size_t>(block.blockNumber());
    if (c.hasSelection()) {
        braille_typed({});
        return;
    }
    const auto at = static_cast<std::size_t>(c.positionInBlock());
    if (backward && at == 0) {
        // At the start of a paragraph backspace joins it to the one above, as in print.
        if (line == 0) return;
        QTextCursor pc(print_->document()->findBlockByNumber(static_cast<int>(line)));
        pc.deletePreviousChar();
        return;
    }
    if (backward) edit_braille(line, at - 1, at, {});
    else if (at < static_cast<std::size_t>(block.length() - 1)) edit_braille(line, at, at + 1, {});
    if (!backward) {
        QTextCursor bc(block);
        bc.setPosition(block.position() + static_cast<int>(at));
        braille_->setTextCursor(bc);
    }
}

void EditorWidget::braille_new_paragraph() {
    const auto line = braille_->textCursor().blockNumber();
    QTextCursor pc(print_->document()->findBlockByNumber(line));
    pc.movePosition(QTextCursor::EndOfBlock);
    pc.insertText(QStringLiteral("\n"));
    const auto bb = braille_->document()->findBlockByNumber(line + 1);
    braille_->setTextCursor(QTextCursor(bb));
}

}  // namespace tactus::gui
