// SPDX-License-Identifier: GPL-3.0-or-later
// The print pane's structured view on real Word and OpenDocument files
// (pandoc's test suite, LibreOffice's own output): no Markdown markup is
// shown, headings have their level, lists their numbers, tables their cells;
// the view read back gives the same document model; styles set from the
// Styles menu change the model, keep the braille pane in step and undo.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QLabel>
#include <QStatusBar>
#include <QTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTextList>
#include <algorithm>
#include <cctype>
#include <QtTest>

#include "announcer.hpp"
#include "braille_pane.hpp"
#include "document_loader.hpp"
#include "edit/editor_lines.hpp"
#include "editor_widget.hpp"
#include "gui_test_support.hpp"
#include "import/import.hpp"
#include "main_window.hpp"
#include "structured_print.hpp"
#include "translate/translator.hpp"

using namespace tactus;
using namespace tactus::gui;

namespace {

// The editor line of the first paragraph of body text; -1 when none.
int first_paragraph(const std::vector<std::string>& lines) {
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (const auto p = edit::parse_editor_line(lines[i]); p && p->kind == document::BlockKind::paragraph)
            return static_cast<int>(i);
    return -1;
}

QString data(const char* name) { return QStringLiteral(TACTUS_TEST_DATA "/import/") + QLatin1String(name); }

std::vector<std::string> model_lines(const EditorWidget& e) {
    std::vector<std::string> out;
    for (const auto& l : e.text().split(QLatin1Char('\n'))) out.push_back(l.toStdString());
    return out;
}

QString braille(const std::string& table, const std::string& text) {
    auto t = translate::Translator::open(table);
    auto cells = t->translate(QString::fromStdString(text).toStdU32String());
    return QString::fromStdString(document::to_unicode_text(*cells));
}

}  // namespace

class StructuredPrintTest : public QObject {
    Q_OBJECT
    std::unique_ptr<EditorWidget> editor;

    void open(const QString& path) {
        auto loaded = load_file_now(path, "en-ueb-g2.ctb", {});
        QVERIFY2(loaded->layout.has_value(), qPrintable(path));
        editor = std::make_unique<EditorWidget>();
        editor->adopt(std::move(*loaded->layout));
        editor->resize(1000, 700);
    }
    QTextBlock block(int n) const { return editor->print_pane()->document()->findBlockByNumber(n); }

private Q_SLOTS:
    void cleanup() { editor.reset(); }

    void shows_structure_not_markup_data() {
        QTest::addColumn<QString>("file");
        for (const char* f : {"public/pandoc-headers.docx", "public/pandoc-lists.docx", "public/pandoc-inline_formatting.docx",
                              "public/pandoc-notes.docx", "public/pandoc-block_quotes.docx",
                              "public/pandoc-table_captions_with_field.docx", "public/pandoc-tableWithContents.odt",
                              "public/pandoc-footnote.odt", "public/pandoc-listContinueNumbering.odt",
                              "public/pandoc-referenceAllInOne.odt", "constructs/constructs.docx",
                              "constructs/constructs.odt", "lesson.docx", "lesson.odt"})
            QTest::newRow(f) << data(f);
    }
    void shows_structure_not_markup() {
        QFETCH(QString, file);
        open(file);
        const auto lines = model_lines(*editor);
        auto* doc = editor->print_pane()->document();
        QCOMPARE(static_cast<std::size_t>(doc->blockCount()), lines.size());
        int headings = 0, items = 0, rows = 0, styled = 0;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const auto b = block(static_cast<int>(i));
            // A picture is an image object, read as its description (the words said for it).
            auto shown = b.text();
            for (const auto& description : structured::picture_descriptions(b))
                shown.replace(shown.indexOf(QChar::ObjectReplacementCharacter), 1, description);
            QVERIFY(!shown.contains(QChar::ObjectReplacementCharacter));
            const auto why = QStringLiteral("line %1: model \"%2\", shown \"%3\"")
                                 .arg(i + 1)
                                 .arg(QString::fromStdString(lines[i]), shown);
            QVERIFY2(!shown.contains(QStringLiteral("![")), qPrintable(why));
            // No Markdown markup is visible.
            QVERIFY2(!shown.startsWith(QLatin1Char('#')), qPrintable(why));
            QVERIFY2(!shown.contains(QStringLiteral("**")), qPrintable(why));
            QVERIFY2(!shown.contains(QStringLiteral("<!--")), qPrintable(why));
            QVERIFY2(!shown.contains(QStringLiteral("| ---")) && !shown.contains(QStringLiteral("|---")), qPrintable(why));
            QVERIFY2(!shown.contains(QStringLiteral("[^")), qPrintable(why));
            QVERIFY2(!shown.startsWith(QStringLiteral("- ")) && !shown.startsWith(QStringLiteral("> ")), qPrintable(why));
            QVERIFY2(!shown.contains(QLatin1Char('\\')) || lines[i].find("\\\\") != std::string::npos, qPrintable(why));
            for (auto it = b.begin(); !it.atEnd(); ++it) {
                const auto f = it.fragment().charFormat();
                if (structured::is_bold(f) || f.fontItalic() || f.boolProperty(structured::kNoteRef)) ++styled;
            }
            // Each line's structure is the block's.
            const auto parsed = edit::parse_editor_line(lines[i]);
            if (!parsed) continue;
            switch (parsed->kind) {
                case document::BlockKind::heading:
                    ++headings;
                    QVERIFY2(b.blockFormat().headingLevel() == parsed->level, qPrintable(why));
                    QCOMPARE(shown.trimmed(), QString::fromStdString(parsed->text()).trimmed());
                    break;
                case document::BlockKind::list_item: {
                    ++items;
                    // The number or bullet is the list's, not the text's (or, counting
                    // from another number than 1, the text's number itself).
                    const auto text = QString::fromStdString(parsed->text());
                    if (const auto* list = b.textList()) {
                        const auto mark = list->format().style() == QTextListFormat::ListDecimal
                                              ? list->itemText(b) + QLatin1Char(' ')
                                              : QStringLiteral("\u2022 ");
                        QVERIFY2(text.startsWith(mark), qPrintable(why + QStringLiteral(" mark ") + mark));
                        QCOMPARE(mark + shown, text);
                    } else {
                        QVERIFY2(b.blockFormat().boolProperty(structured::kNumberText), qPrintable(why));
                        QCOMPARE(shown, text);
                    }
                    break;
                }
                case document::BlockKind::table_row: {
                    ++rows;
                    QStringList cells;
                    // A cell's paragraphs are shown as line breaks in the row's one block.
                    for (const auto& c : edit::parse_table_cells(lines[i]))
                        cells << QString::fromStdString(c.text()).replace(QLatin1Char('\n'), QChar::LineSeparator);
                    QCOMPARE(shown.split(QLatin1Char('\t')), cells);
                    break;
                }
                case document::BlockKind::print_page_break:
                    QVERIFY2(shown.isEmpty(), qPrintable(why));
                    break;
                default:
                    if (document::is_text_kind(parsed->kind))
                        QCOMPARE(shown, QString::fromStdString(parsed->text()));
                    break;
            }
        }
        QVERIFY(headings + items + rows + styled > 0);
        // The braille pane is line for line the print's.
        QCOMPARE(editor->braille_pane()->document()->blockCount(), doc->blockCount());
    }

    // Open -> structure -> model -> the same model: every block read back
    // gives its line's block, and the lines read back lay out the same document.
    void the_view_reads_back_to_the_same_model_data() { shows_structure_not_markup_data(); }
    void the_view_reads_back_to_the_same_model() {
        QFETCH(QString, file);
        open(file);
        const auto lines = model_lines(*editor);
        std::vector<std::string> back;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            back.push_back(structured::line_of(block(static_cast<int>(i))));
            QVERIFY2(edit::parse_editor_line(back.back()) == edit::parse_editor_line(lines[i]) ||
                         (edit::is_table_delimiter(lines[i]) && back.back() == lines[i]),
                     qPrintable(QStringLiteral("line %1: \"%2\" read back as \"%3\"")
                                    .arg(i + 1)
                                    .arg(QString::fromStdString(lines[i]), QString::fromStdString(back.back()))));
            if (edit::parse_editor_line(lines[i]) && edit::parse_editor_line(lines[i])->kind == document::BlockKind::table_row)
                QCOMPARE(edit::parse_table_cells(back.back()), edit::parse_table_cells(lines[i]));
        }
        auto again = edit::LiveLayout::create("en-ueb-g2.ctb", {});
        QVERIFY(again.has_value());
        again->set_pictures(editor->layout().pictures());  // the lines' picture marks name them
        again->reset(back);
        auto a = again->document(), b = editor->layout().document();
        QCOMPARE(a.blocks.size(), b.blocks.size());
        QVERIFY(a.blocks == b.blocks);
        // Showing the codes and the structure again changes nothing in the model.
        editor->set_codes_shown(true);
        QCOMPARE(editor->print_pane()->toPlainText(), editor->text());
        editor->set_codes_shown(false);
        QCOMPARE(model_lines(*editor), lines);
    }

    // The Styles menu's styles change the model's lines, the braille follows
    // them, and undo takes each back.
    void styles_change_the_model_and_undo() {
        MainWindow w;
        QVERIFY(w.open_file_now(data("public/pandoc-headers.docx")));
        auto* e = w.editor();
        auto* print = e->print_pane();
        const auto before = e->text();
        const auto lines = model_lines(*e);
        // The first paragraph of body text.
        const int body = first_paragraph(lines);
        QVERIFY(body >= 0);
        const auto text = print->document()->findBlockByNumber(body).text();
        const auto act = [&w](const char* name) {
            auto* a = w.findChild<QAction*>(QString::fromLatin1(name));
            QVERIFY2(a && a->isEnabled() && !a->shortcut().isEmpty(), name);
            a->trigger();
        };
        const auto line = [e, body] { return model_lines(*e)[static_cast<std::size_t>(body)]; };
        const auto braille_line = [e, body] { return e->braille_pane()->document()->findBlockByNumber(body).text(); };
        print->setTextCursor(QTextCursor(print->document()->findBlockByNumber(body)));

        act("formatHeading2");
        QCOMPARE(QString::fromStdString(line()), QStringLiteral("## ") + text);
        QCOMPARE(print->document()->findBlockByNumber(body).blockFormat().headingLevel(), 2);
        QCOMPARE(braille_line(), QString::fromStdString(document::to_unicode_text(e->layout().braille_of(static_cast<std::size_t>(body)))));

        act("formatNumbered");
        QCOMPARE(QString::fromStdString(line()), QStringLiteral("1. ") + text);
        QVERIFY(print->document()->findBlockByNumber(body).textList());

        act("formatBulleted");
        QCOMPARE(QString::fromStdString(line()), QStringLiteral("- ") + text);

        act("formatQuotation");
        QCOMPARE(QString::fromStdString(line()), QStringLiteral("> ") + text);

        act("formatBody");
        QCOMPARE(QString::fromStdString(line()), text);

        // Bold on the paragraph's first word.
        auto c = QTextCursor(print->document()->findBlockByNumber(body));
        c.movePosition(QTextCursor::EndOfWord, QTextCursor::KeepAnchor);
        const auto word = c.selectedText();
        print->setTextCursor(c);
        act("formatBold");
        QVERIFY2(line().starts_with("**" + word.toStdString() + "**"), line().c_str());
        QVERIFY(e->braille_pane()->document()->findBlockByNumber(body).text() != braille("en-ueb-g2.ctb", text.toStdString()));
        act("formatBold");
        QCOMPARE(QString::fromStdString(line()), text);
        act("formatItalic");
        QVERIFY2(line().starts_with("*" + word.toStdString() + "*"), line().c_str());
        act("formatItalic");
        QCOMPARE(QString::fromStdString(line()), text);
        // Raised and lowered: on, off, and one in place of the other; the
        // model's span and the braille (its level indicator) follow.
        const auto braille_before = braille_line();
        act("formatRaised");
        QVERIFY2(line().starts_with("<sup>" + word.toStdString() + "</sup>"), line().c_str());
        QCOMPARE(e->layout().document().blocks[static_cast<std::size_t>(body)].spans.front().position,
                 document::Position::superscript);
        QVERIFY(braille_line() != braille_before);
        act("formatRaised");
        QCOMPARE(QString::fromStdString(line()), text);
        QCOMPARE(braille_line(), braille_before);
        act("formatLowered");
        QVERIFY2(line().starts_with("<sub>" + word.toStdString() + "</sub>"), line().c_str());
        act("formatRaised");
        QVERIFY2(line().starts_with("<sup>" + word.toStdString() + "</sup>"), line().c_str());
        act("formatRaised");
        QCOMPARE(QString::fromStdString(line()), text);

        // A page break before the paragraph: a line of its own, shown as no text.
        print->setTextCursor(QTextCursor(print->document()->findBlockByNumber(body)));
        act("formatPageBreak");
        QCOMPARE(model_lines(*e)[static_cast<std::size_t>(body)], std::string("<!-- pagebreak -->"));
        QCOMPARE(model_lines(*e)[static_cast<std::size_t>(body) + 1], text.toStdString());
        QVERIFY(print->document()->findBlockByNumber(body).text().isEmpty());
        QCOMPARE(e->braille_pane()->document()->blockCount(), print->document()->blockCount());
        QVERIFY(e->layout().document().blocks.size() > 0);

        // Return after a heading starts body text, not a second heading.
        print->setTextCursor(QTextCursor(print->document()->findBlockByNumber(0)));
        print->moveCursor(QTextCursor::EndOfBlock);
        QTest::keyClick(print, Qt::Key_Return);
        QTest::keyClicks(print, "Typed");
        QCOMPARE(model_lines(*e)[1], std::string("Typed"));

        // Undo takes every step back, to the file as opened.
        while (e->undo_stack()->canUndo()) e->undo_stack()->undo();
        QCOMPARE(e->text(), before);
        QCOMPARE(e->braille_pane()->document()->blockCount(), print->document()->blockCount());

        // With the codes shown the styles do nothing: the marks are typed there.
        w.findChild<QAction*>(QStringLiteral("viewShowCodes"))->setChecked(true);
        QVERIFY(print->toPlainText().startsWith(QLatin1Char('#')));
        QVERIFY(!w.findChild<QAction*>(QStringLiteral("formatHeading1"))->isEnabled());
        QCOMPARE(e->text(), before);
    }

    // Styles > Language marks a passage as a word processor does (the
    // selection, else the word at the cursor, or the whole paragraph): the
    // model's span has the language, the braille of the passage comes from
    // that language's table, the status bar names the language at the
    // cursor, the change is said and is one step of undo; "document
    // default" takes the mark away.
    void a_passage_is_marked_in_a_language() {
        MainWindow w;
        QVERIFY(w.open_file_now(data("public/pandoc-headers.docx")));
        auto* e = w.editor();
        auto* print = e->print_pane();
        const auto before = e->text();
        const int body = first_paragraph(model_lines(*e));
        QVERIFY(body >= 0);
        const auto text = print->document()->findBlockByNumber(body).text();
        const auto line = [e, body] { return model_lines(*e)[static_cast<std::size_t>(body)]; };
        const auto braille_line = [e, body] { return e->braille_pane()->document()->findBlockByNumber(body).text(); };
        const auto laid_out = [e, body] {
            return QString::fromStdString(document::to_unicode_text(e->layout().braille_of(static_cast<std::size_t>(body))));
        };
        const auto spans = [e, body] { return e->layout().document().blocks[static_cast<std::size_t>(body)].spans; };
        auto* status = w.statusBar()->findChild<QLabel*>(QStringLiteral("positionLabel"));
        QVERIFY(status);
        const auto braille_before = braille_line();

        // The action, reached by its key, asks in a dialog that lists the
        // languages of the tables (the catalogue's, none other).
        auto* action = w.findChild<QAction*>(QStringLiteral("formatLanguage"));
        QVERIFY(action && action->isEnabled());
        QCOMPARE(action->shortcut(), QKeySequence(QStringLiteral("Ctrl+Alt+G")));
        QStringList listed;
        const auto choose = [&](const QString& tag, bool paragraph) {
            QTimer::singleShot(50, [&, tag, paragraph] {
                auto* dialog = w.findChild<QDialog*>(QStringLiteral("languageDialog"));
                QVERIFY(dialog && dialog->isVisible());
                auto* list = dialog->findChild<QComboBox*>(QStringLiteral("languageList"));
                listed.clear();
                for (int i = 0; i < list->count(); ++i) listed << list->itemData(i).toString();
                list->setCurrentIndex(list->findData(tag));
                dialog->findChild<QCheckBox*>(QStringLiteral("languageParagraph"))->setChecked(paragraph);
                dialog->accept();
            });
            action->trigger();
        };

        // The first word selected, marked Chinese (Taiwan).
        auto c = QTextCursor(print->document()->findBlockByNumber(body));
        c.movePosition(QTextCursor::EndOfWord, QTextCursor::KeepAnchor);
        const auto word = c.selectedText();
        print->setTextCursor(c);
        const int steps = e->undo_stack()->count();
        QSignalSpy spoken(w.announcer(), &Announcer::announced);
        choose(QStringLiteral("zh-TW"), false);
        QCOMPARE(listed, (QStringList{QString(), QStringLiteral("en"), QStringLiteral("zh-TW"), QStringLiteral("zh-CN")}));
        QVERIFY2(line() == "<span lang=\"zh-TW\">" + word.toStdString() + "</span>" + text.mid(word.size()).toStdString(),
                 line().c_str());
        QCOMPARE(spans().front().text, word.toStdString());
        QCOMPARE(spans().front().language, std::string("zh-TW"));
        QCOMPARE(spans().back().language, std::string());
        // Its braille is the Chinese table's, as layout gives it.
        QVERIFY(braille_line() != braille_before);
        QCOMPARE(braille_line(), laid_out());
        QVERIFY2(braille_line().contains(braille("zh-tw.ctb", word.toStdString())), qPrintable(braille_line()));
        QCOMPARE(e->undo_stack()->count(), steps + 1);
        QVERIFY(w.announcer()->message().contains(QStringLiteral("Language: Chinese (Taiwan)")));
        QVERIFY(!spoken.isEmpty());
        // At the cursor in the passage the status bar names its language, after it not.
        c.setPosition(c.selectionStart() + 1);
        print->setTextCursor(c);
        QTRY_VERIFY2(status->text().endsWith(QStringLiteral(" | Language: Chinese (Taiwan)")), qPrintable(status->text()));
        QCOMPARE(e->language_at_cursor(), QStringLiteral("zh-TW"));
        print->moveCursor(QTextCursor::EndOfBlock);
        QTRY_VERIFY2(!status->text().contains(QStringLiteral("Language")), qPrintable(status->text()));

        // One undo takes it away, braille and all.
        e->undo_stack()->undo();
        QCOMPARE(QString::fromStdString(line()), text);
        QCOMPARE(braille_line(), braille_before);

        // No selection: the word the cursor is in (the second word).
        c = QTextCursor(print->document()->findBlockByNumber(body));
        c.movePosition(QTextCursor::NextWord);
        c.movePosition(QTextCursor::NextCharacter);
        print->setTextCursor(c);
        auto second = c;
        second.select(QTextCursor::WordUnderCursor);
        e->set_language(QStringLiteral("zh-CN"));
        QVERIFY2(line().find("<span lang=\"zh-CN\">" + second.selectedText().toStdString() + "</span>") != std::string::npos,
                 line().c_str());
        QCOMPARE(std::ranges::count_if(spans(), [](const document::Span& s) { return !s.language.empty(); }), 1);
        QCOMPARE(braille_line(), laid_out());
        e->undo_stack()->undo();

        // The whole paragraph, then "document default" on it: no mark left.
        print->setTextCursor(QTextCursor(print->document()->findBlockByNumber(body)));
        choose(QStringLiteral("zh-TW"), true);
        QCOMPARE(line(), "<span lang=\"zh-TW\">" + text.toStdString() + "</span>");
        QCOMPARE(braille_line(), laid_out());
        choose(QString(), true);
        QCOMPARE(QString::fromStdString(line()), text);
        QVERIFY(w.announcer()->message().contains(QStringLiteral("Language: document default")));
        QCOMPARE(braille_line(), braille_before);
        while (e->undo_stack()->canUndo()) e->undo_stack()->undo();
        QCOMPARE(e->text(), before);
    }

    // Styles > Note inserts a footnote as a word processor does: the next
    // number raised at the cursor, the note's paragraph after the cursor's,
    // the cursor in it; the model has the reference and the note; one undo
    // step takes both away.
    void a_note_is_inserted_where_the_cursor_is() {
        MainWindow w;
        QVERIFY(w.open_file_now(data("public/pandoc-headers.docx")));
        auto* e = w.editor();
        auto* print = e->print_pane();
        const auto before = e->text();
        const auto lines = model_lines(*e);
        const int body = first_paragraph(lines);
        QVERIFY(body >= 0);
        const auto b = static_cast<std::size_t>(body);
        auto c = QTextCursor(print->document()->findBlockByNumber(body));
        c.movePosition(QTextCursor::EndOfWord);
        const auto word = print->document()->findBlockByNumber(body).text().left(c.positionInBlock());
        print->setTextCursor(c);
        auto* note = w.findChild<QAction*>(QStringLiteral("formatNote"));
        QVERIFY(note && note->isEnabled() && !note->shortcut().isEmpty());
        note->trigger();
        QCOMPARE(w.announcer()->message(), QStringLiteral("Note 1: type its text"));
        QVERIFY2(model_lines(*e)[b].starts_with(word.toStdString() + "[^1]"), model_lines(*e)[b].c_str());
        QCOMPARE(model_lines(*e)[b + 1], std::string("[^1]: "));
        QCOMPARE(print->textCursor().blockNumber(), body + 1);
        QTest::keyClicks(print, "A note typed here.");
        QCOMPARE(model_lines(*e)[b + 1], std::string("[^1]: A note typed here."));
        // The model: a reference in the paragraph, a note block after it.
        const auto& blocks = e->layout().document().blocks;
        const auto is_note = [](const document::Block& k) { return k.kind == document::BlockKind::note; };
        const auto n = std::find_if(blocks.begin(), blocks.end(), is_note);
        QVERIFY(n != blocks.end());
        QVERIFY(!n->spans.empty() && n->spans.front().note_reference && n->spans.front().text == "1");
        QCOMPARE(n->text(), std::string("1 A note typed here."));
        QCOMPARE(e->braille_pane()->document()->blockCount(), print->document()->blockCount());
        // A second note, in the same paragraph, is number 2.
        print->setTextCursor(QTextCursor(print->document()->findBlockByNumber(body)));
        note->trigger();
        QCOMPARE(w.announcer()->message(), QStringLiteral("Note 2: type its text"));
        QVERIFY(model_lines(*e)[b].starts_with("[^2]"));
        // Not in a note's own text.
        print->setTextCursor(QTextCursor(print->document()->findBlockByNumber(body + 1)));
        const auto with_two = e->text();
        note->trigger();
        QCOMPARE(e->text(), with_two);
        // Undo takes every step back, to the file as opened.
        while (e->undo_stack()->canUndo()) e->undo_stack()->undo();
        QCOMPARE(e->text(), before);
    }

    // A screen reader hears what a paragraph is as the cursor comes to it:
    // Qt's text interface gives a heading's font, not its level.
    void the_cursor_says_what_a_paragraph_is() {
        open(data("lesson.docx"));
        editor->show();
        QVERIFY(QTest::qWaitForWindowExposed(editor.get()));
        QSignalSpy said(editor.get(), &EditorWidget::structure_reached);
        QSignalSpy broke(editor.get(), &EditorWidget::page_break_reached);
        auto* print = editor->print_pane();
        const auto lines = model_lines(*editor);
        QStringList heard;
        for (int i = static_cast<int>(lines.size()) - 1; i >= 0; --i) {  // from the end: the first line is a change too
            print->setTextCursor(QTextCursor(block(i)));
            heard << (said.isEmpty() ? QString() : said.takeFirst().at(0).toString());
        }
        std::reverse(heard.begin(), heard.end());
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const auto p = edit::parse_editor_line(lines[i]);
            const auto why = QString::fromStdString(lines[i]) + QStringLiteral(" -> ") + heard[static_cast<int>(i)];
            if (!p) continue;
            if (p->kind == document::BlockKind::heading)
                QVERIFY2(heard[static_cast<int>(i)] == QStringLiteral("Heading level %1").arg(p->level), qPrintable(why));
            if (p->kind == document::BlockKind::list_item) {
                QVERIFY2(heard[static_cast<int>(i)].startsWith(QStringLiteral("List item")), qPrintable(why));
                if (const auto n = lines[i].find_first_not_of(' '); std::isdigit(static_cast<unsigned char>(lines[i][n])))
                    QVERIFY2(heard[static_cast<int>(i)] ==
                                 QStringLiteral("List item ") + QString::fromStdString(lines[i].substr(n, lines[i].find(' ', n) - n)),
                             qPrintable(why));
            }
            if (p->kind == document::BlockKind::table_row)
                QVERIFY2(heard[static_cast<int>(i)].startsWith(QStringLiteral("Table")), qPrintable(why));
            if (p->kind == document::BlockKind::paragraph) QVERIFY2(heard[static_cast<int>(i)].isEmpty(), qPrintable(why));
        }
        QVERIFY(heard.contains(QStringLiteral("Heading level 1")));
        QVERIFY(!broke.isEmpty());  // the page break says itself, as before
        // With the codes shown the marks are read: nothing more is said.
        editor->set_codes_shown(true);
        said.clear();
        print->setTextCursor(QTextCursor(block(2)));
        print->setTextCursor(QTextCursor(block(0)));
        QVERIFY(said.isEmpty());
    }

    // A new item in a numbered list: the items after it are numbered on, in
    // the model as on screen.
    void a_new_list_item_renumbers_the_items_after_it() {
        open(data("public/pandoc-lists.docx"));
        editor->show();
        auto* print = editor->print_pane();
        int first = -1;
        for (int i = 0; i + 1 < print->document()->blockCount() && first < 0; ++i) {
            const auto* list = block(i).textList();
            if (list && list->format().style() == QTextListFormat::ListDecimal && block(i + 1).textList() == list)
                first = i;
        }
        QVERIFY(first >= 0);
        const auto* list = block(first).textList();
        const auto count = list->count();
        const auto lines = model_lines(*editor);
        QTextCursor c(block(first));
        c.movePosition(QTextCursor::EndOfBlock);
        print->setTextCursor(c);
        QTest::keyClick(print, Qt::Key_Return);
        QTest::keyClicks(print, "New");
        const auto now = model_lines(*editor);
        QCOMPARE(now.size(), lines.size() + 1);
        QCOMPARE(block(first).textList()->count(), count + 1);
        for (int k = 0; k <= count; ++k) {
            const auto& line = now[static_cast<std::size_t>(first + k)];
            const auto number = std::to_string(k + 1) + ". ";
            QVERIFY2(line.substr(line.find_first_not_of(' ')).starts_with(number), line.c_str());
        }
        QVERIFY(now[static_cast<std::size_t>(first + 1)].ends_with(" New"));
        // The item after it is the old second item, numbered 3 now.
        const auto old_second = lines[static_cast<std::size_t>(first + 1)];
        QCOMPARE(now[static_cast<std::size_t>(first + 2)].substr(now[static_cast<std::size_t>(first + 2)].find(". ")),
                 old_second.substr(old_second.find(". ")));
        QCOMPARE(editor->braille_pane()->document()->blockCount(), print->document()->blockCount());
    }

    // Cursor and selection map through the structure: a numbered item's text
    // (its number drawn by the list) to its braille.
    void the_cursor_maps_through_a_list_number() {
        open(data("public/pandoc-lists.docx"));
        const auto lines = model_lines(*editor);
        int item = -1;
        for (std::size_t i = 0; i < lines.size() && item < 0; ++i)
            if (block(static_cast<int>(i)).textList()) item = static_cast<int>(i);
        QVERIFY(item >= 0);
        const auto b = block(item);
        auto* print = editor->print_pane();
        QTextCursor c(b);
        c.movePosition(QTextCursor::EndOfBlock);
        print->setTextCursor(c);
        // The end of the print paragraph is the end of its braille.
        const auto bc = editor->braille_pane()->textCursor();
        QCOMPARE(bc.blockNumber(), item);
        QCOMPARE(bc.positionInBlock(), editor->braille_pane()->document()->findBlockByNumber(item).length() - 1);
    }

    // A DOCX with a box and raised and lowered text, opened in the app, a word
    // underlined with Ctrl+U and a paragraph boxed from the Styles menu, saved
    // as DOCX and opened again: the same model, with all of them.
    void underline_boxes_and_raised_text_survive_a_docx_save() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const auto path = dir.filePath(QStringLiteral("constructs.docx"));
        QVERIFY(QFile::copy(data("constructs/constructs.docx"), path));
        QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
        const auto original = import::import_file(path.toStdString());
        QVERIFY(original.has_value());
        MainWindow w;
        QVERIFY(w.open_file_now(path));
        auto* e = w.editor();
        auto* print = e->print_pane();
        auto* doc = print->document();
        const auto act = [&w](const char* name) {
            auto* a = w.findChild<QAction*>(QString::fromLatin1(name));
            QVERIFY2(a && a->isEnabled() && !a->shortcut().isEmpty(), name);
            a->trigger();
        };
        const auto find = [doc](const QString& text) {
            for (auto b = doc->begin(); b.isValid(); b = b.next())
                if (b.text() == text) return b.blockNumber();
            return -1;
        };
        // The box and the raised text are shown without markup, the box's
        // lines named for a screen reader.
        const auto lines = model_lines(*e);
        int box = -1;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const auto shown = block(doc, static_cast<int>(i)).text();
            QVERIFY2(!shown.contains(QLatin1Char('<')), qPrintable(shown));
            if (lines[i] == "<!-- box -->" && box < 0) box = static_cast<int>(i);
        }
        QVERIFY(box >= 0);
        QCOMPARE(e->structure_text(box), QStringLiteral("Box"));
        const int area = find(QStringLiteral("Area m2 and mass m2."));
        QVERIFY(area >= 0);
        bool raised = false, lowered = false;
        for (auto it = block(doc, area).begin(); !it.atEnd(); ++it) {
            const auto v = it.fragment().charFormat().verticalAlignment();
            raised = raised || v == QTextCharFormat::AlignSuperScript;
            lowered = lowered || v == QTextCharFormat::AlignSubScript;
        }
        QVERIFY(raised && lowered);

        // Ctrl+U on the first word of "After the box.", and on again off.
        const int after = find(QStringLiteral("After the box."));
        QVERIFY(after >= 0);
        QTextCursor c(block(doc, after));
        c.movePosition(QTextCursor::EndOfWord, QTextCursor::KeepAnchor);
        print->setTextCursor(c);
        act("formatUnderline");
        QCOMPARE(model_lines(*e)[static_cast<std::size_t>(after)], std::string("<u>After</u> the box."));
        act("formatUnderline");
        QCOMPARE(model_lines(*e)[static_cast<std::size_t>(after)], std::string("After the box."));
        act("formatUnderline");
        // The Box style on the paragraph: a box line above and below it; undone and done again.
        const auto before_box = e->text();
        print->setTextCursor(QTextCursor(block(doc, after)));
        act("formatBox");
        auto now = model_lines(*e);
        QCOMPARE(now[static_cast<std::size_t>(after)], std::string("<!-- box -->"));
        QCOMPARE(now[static_cast<std::size_t>(after) + 1], std::string("<u>After</u> the box."));
        QCOMPARE(now[static_cast<std::size_t>(after) + 2], std::string("<!-- /box -->"));
        QCOMPARE(e->braille_pane()->document()->blockCount(), doc->blockCount());
        QVERIFY(block(doc, after).text().isEmpty());
        e->undo_stack()->undo();
        QCOMPARE(e->text(), before_box);
        e->undo_stack()->redo();
        QCOMPARE(model_lines(*e)[static_cast<std::size_t>(after)], std::string("<!-- box -->"));
        // Box again, inside the box: out of it.
        print->setTextCursor(QTextCursor(block(doc, after + 1)));
        act("formatBox");
        QCOMPARE(e->text(), before_box);
        act("formatBox");

        // Saved beside the file, with its picture
        // (MainWindowTest::pictures_are_kept_through_edit_and_save).
        const auto saved = dir.filePath(QStringLiteral("saved.docx"));
        QVERIFY(w.save_to(saved));
        MainWindow again;
        QVERIFY(again.open_file_now(saved));
        // A picture's name is where it came from: the saved package names its part anew.
        const auto unnamed = [](document::Document d) {
            for (auto& b : d.blocks)
                for (auto& image : b.images) image.name.clear();
            return d.blocks;
        };
        QVERIFY(unnamed(again.editor()->layout().document()) == unnamed(e->layout().document()));
        QCOMPARE(again.editor()->text(), e->text());
        // What the file held is there, and the new underline and box besides.
        const auto reopened = import::import_file(saved.toStdString());
        QVERIFY(reopened.has_value());
        const auto texts = [](const document::Document& d, auto&& has) {
            QStringList out;
            for (const auto& b : d.blocks)
                for (const auto& s : b.spans)
                    if (has(b, s)) out << QString::fromStdString(s.text);
            return out;
        };
        const auto in_box = [](const document::Block& b, const document::Span&) { return b.box != 0; };
        const auto up = [](const document::Block&, const document::Span& s) {
            return s.position == document::Position::superscript;
        };
        const auto down = [](const document::Block&, const document::Span& s) {
            return s.position == document::Position::subscript;
        };
        const auto underlined = [](const document::Block&, const document::Span& s) {
            return (s.emphasis & document::emphasis_underline) != 0;
        };
        QVERIFY(!texts(*original, in_box).isEmpty() && !texts(*original, up).isEmpty());
        const QStringList new_box{QStringLiteral("After"), QStringLiteral(" the box.")};
        QCOMPARE(texts(*reopened, in_box), texts(*original, in_box) + new_box);
        QCOMPARE(texts(*reopened, up), texts(*original, up));
        QCOMPARE(texts(*reopened, down), texts(*original, down));
        QCOMPARE(texts(*reopened, underlined), texts(*original, underlined) + QStringList{QStringLiteral("After")});
    }

    // Show codes shows the tags the structure hides.
    void show_codes_shows_the_tags() {
        open(data("lesson.docx"));
        QVERIFY(!editor->print_pane()->toPlainText().contains(QStringLiteral("<u>")));
        editor->set_codes_shown(true);
        QVERIFY(editor->print_pane()->toPlainText().contains(QStringLiteral("<u>water cycle</u>")));
    }

private:
    static QTextBlock block(QTextDocument* doc, int n) { return doc->findBlockByNumber(n); }
};

QTEST_MAIN(StructuredPrintTest)
#include "structured_print_test.moc"
