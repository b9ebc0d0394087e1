// SPDX-License-Identifier: GPL-3.0-or-later
// The editor's line format: every block of every sample survives render -> parse,
// and Markdown-looking print text is escaped rather than reinterpreted.
#include <QtTest>

#include "editor_lines.hpp"
#include "gui_test_support.hpp"

using namespace tactus;
using namespace tactus::gui;

class EditorLinesTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void samples_round_trip_data() {
        QTest::addColumn<QString>("file");
        QTest::newRow("welcome.md") << QStringLiteral("welcome.md");
        QTest::newRow("chinese-tw.txt") << QStringLiteral("chinese-tw.txt");
        QTest::newRow("chinese-cn.txt") << QStringLiteral("chinese-cn.txt");
    }
    void samples_round_trip() {
        QFETCH(QString, file);
        auto doc = import::import_file(test::sample(file.toLatin1().constData()).toStdString());
        QVERIFY(doc.has_value());
        const auto lines = render_editor_lines(*doc);
        std::vector<document::Block> parsed;
        for (const auto& l : lines)
            if (auto b = parse_editor_line(l)) parsed.push_back(*b);
        std::vector<document::Block> expected;
        for (auto b : doc->blocks) {
            b.source_line = 0;
            expected.push_back(b);
        }
        QCOMPARE(parsed.size(), expected.size());
        for (std::size_t i = 0; i < parsed.size(); ++i) {
            QCOMPARE(static_cast<int>(parsed[i].kind), static_cast<int>(expected[i].kind));
            QCOMPARE(parsed[i].level, expected[i].level);
            QCOMPARE(QString::fromStdString(parsed[i].text()), QString::fromStdString(expected[i].text()));
            QCOMPARE(parsed[i].label, expected[i].label);
            QVERIFY2(parsed[i].spans == expected[i].spans, lines[i].c_str());
        }
    }

    void kinds_from_marks() {
        auto h = parse_editor_line("## Reading tips");
        QVERIFY(h && h->kind == document::BlockKind::heading && h->level == 2 && h->text() == "Reading tips");
        auto nested = parse_editor_line("  - Beginners");
        QVERIFY(nested && nested->kind == document::BlockKind::list_item && nested->level == 2);
        auto numbered = parse_editor_line("3. Preview");
        QVERIFY(numbered && numbered->kind == document::BlockKind::list_item && numbered->text() == "3. Preview");
        auto brk = parse_editor_line("<!-- pagebreak 12 -->");
        QVERIFY(brk && brk->kind == document::BlockKind::print_page_break && brk->label == "12");
        auto rule = parse_editor_line("---");
        QVERIFY(rule && rule->kind == document::BlockKind::print_page_break && rule->label.empty());
        QVERIFY(!parse_editor_line("   "));
        auto emph = parse_editor_line("a **bold** and *italic* word");
        QVERIFY(emph && emph->spans.size() == 5);
        QCOMPARE(int(emph->spans[1].emphasis), int(document::emphasis_bold));
        QCOMPARE(int(emph->spans[3].emphasis), int(document::emphasis_italic));
    }

    void braille_lines_are_verbatim() {
        auto b = parse_editor_line("\u2813\u2811\u2800\u2807");
        QVERIFY(b && b->kind == document::BlockKind::braille);
        QCOMPARE(b->braille_lines.size(), std::size_t{1});
        QCOMPARE(document::dot_numbers(b->braille_lines[0][0]), std::string("1-2-5"));
        QVERIFY(b->braille_lines[0][2].blank());
    }

    void print_that_looks_like_markdown_is_escaped() {
        for (const std::string text : {"# not a heading", "1. not a list", "- not a bullet", "5 * 3 = 15",
                                       "<!-- pagebreak 3 -->", "a_b_c and \\ backslash", "---"}) {
            document::Block b;
            b.spans = {document::Span{text}};
            const auto line = render_editor_line(b);
            const auto back = parse_editor_line(line);
            QVERIFY2(back.has_value(), line.c_str());
            QCOMPARE(int(back->kind), int(document::BlockKind::paragraph));
            QCOMPARE(QString::fromStdString(back->text()), QString::fromStdString(text));
        }
    }
};

QTEST_GUILESS_MAIN(EditorLinesTest)
#include "editor_lines_test.moc"
