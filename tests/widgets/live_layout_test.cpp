// SPDX-License-Identifier: GPL-3.0-or-later
// The editor's incremental layout gives exactly the pages core's pipeline gives,
// after any sequence of edits, while re-translating only the edited lines.
#include <QtTest>
#include <random>

#include "export/export.hpp"
#include "gui_test_support.hpp"
#include "live_layout.hpp"

using namespace tactus;
using namespace tactus::gui;

namespace {

LiveLayout make(const std::vector<std::string>& lines, const std::string& table = "en-ueb-g2.ctb",
                layout::LayoutOptions options = {}) {
    auto l = LiveLayout::create(table, options);
    if (!l) qFatal("%s", l.error().to_string().c_str());
    l->reset(lines);
    return std::move(*l);
}

std::vector<std::string> lines_of(const LiveLayout& l) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < l.line_count(); ++i) out.push_back(l.line(i));
    return out;
}

}  // namespace

class LiveLayoutTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void same_pages_as_the_cli_pipeline_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("table");
        QTest::newRow("welcome g2") << QStringLiteral("welcome.md") << QStringLiteral("en-ueb-g2.ctb");
        QTest::newRow("welcome g1") << QStringLiteral("welcome.md") << QStringLiteral("en-ueb-g1.ctb");
        QTest::newRow("zh-tw") << QStringLiteral("chinese-tw.txt") << QStringLiteral("zh-tw.ctb");
    }
    void same_pages_as_the_cli_pipeline() {
        QFETCH(QString, file);
        QFETCH(QString, table);
        pipeline::PipelineOptions options;
        options.tables = table.toStdString();
        auto expected = pipeline::lay_out_file(test::sample(file.toLatin1().constData()).toStdString(), options);
        QVERIFY(expected.has_value());
        const auto live = make(test::sample_lines(file.toLatin1().constData()), options.tables);
        QCOMPARE(live.paged().pages.size(), expected->pages.size());
        QVERIFY(live.paged().pages == expected->pages);
        QCOMPARE(*exporter::to_brf(live.paged()), *exporter::to_brf(*expected));
    }

    void edits_give_the_same_pages_as_a_fresh_layout() {
        auto lines = test::synthetic_book(300);
        auto live = make(lines);
        QVERIFY(live.paged().pages.size() > 30);
        std::mt19937 rng(42);
        const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
        for (int step = 0; step < 90; ++step) {
            const auto at = pick(lines.size());
            std::vector<std::string> replacement;
            std::size_t removed = 1;
            switch (step % 6) {
                case 0: replacement = {lines[at] + " more words typed here"}; break;   // typing
                case 1: replacement = {lines[at].substr(0, lines[at].size() / 2)}; break;  // deleting
                case 2: {  // Enter in the middle of a line
                    const auto cut = lines[at].find(' ', lines[at].size() / 2);
                    replacement = {lines[at].substr(0, cut), cut == std::string::npos ? "" : lines[at].substr(cut + 1)};
                    break;
                }
                case 3: replacement = {}; break;  // line deleted
                case 4: replacement = {"## A new heading", lines[at]}; break;
                case 5: replacement = {lines[at], "<!-- pagebreak -->"}; break;
            }
            if (lines.size() < 3 && replacement.empty()) continue;
            const auto stats = live.replace(at, removed, replacement);
            lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(at));
            lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), replacement.begin(), replacement.end());
            QCOMPARE(lines_of(live), lines);
            const auto fresh = make(lines);
            QVERIFY2(live.paged().pages == fresh.paged().pages,
                     qPrintable(QStringLiteral("step %1 (kind %2) at line %3").arg(step).arg(step % 6).arg(at)));
            QVERIFY(stats.lines_translated <= replacement.size() + 40);
        }
    }

    void typing_touches_only_the_paragraph_and_its_pages() {
        auto lines = test::synthetic_book(1500);
        auto live = make(lines);
        const auto pages = live.paged().pages.size();
        QVERIFY(pages > 150);
        const std::size_t at = lines.size() / 2;
        QVERIFY(lines[at].find("pagebreak") == std::string::npos);
        std::string line = lines[at];
        int converged = 0;
        for (char c : std::string("abc")) {
            line.insert(line.size() / 2, 1, c);
            const auto stats = live.replace(at, 1, {line});
            QCOMPARE(stats.lines_translated, std::size_t{1});
            // Restarted at the sheet the line is on, not at the start of the book.
            QVERIFY(stats.first_page_relaid + 4 >= live.position_of(at).page);
            if (stats.converged) {
                ++converged;
                QVERIFY2(stats.pages_relaid <= 3, qPrintable(QString::number(stats.pages_relaid)));
            }
        }
        QVERIFY(converged >= 2);
        lines[at] = line;
        QVERIFY(live.paged().pages == make(lines).paged().pages);
    }

    void positions_point_at_the_paragraphs_cells() {
        const auto lines = test::synthetic_book(200);
        const auto live = make(lines);
        int checked = 0;
        for (std::size_t i = 0; i < live.line_count(); ++i) {
            const auto cells = live.braille_of(i);
            if (lines[i].starts_with("<!--") || lines[i].starts_with("#") || cells.empty()) continue;
            for (std::size_t c : {std::size_t{0}, cells.size() / 2}) {
                while (c < cells.size() && cells[c].blank()) ++c;
                if (c >= cells.size()) continue;
                const auto pos = live.position_of(i, c);
                const auto& page = live.paged().pages.at(pos.page);
                QVERIFY(pos.line < static_cast<int>(page.lines.size()));
                const auto& row = page.lines[static_cast<std::size_t>(pos.line)];
                QVERIFY2(pos.cell < static_cast<int>(row.size()),
                         qPrintable(QStringLiteral("line %1 cell %2").arg(i).arg(c)));
                QCOMPARE(row[static_cast<std::size_t>(pos.cell)], cells[c]);
                ++checked;
            }
            QCOMPARE(live.line_at(live.position_of(i).page, live.position_of(i).line) <= i, true);
        }
        QVERIFY(checked > 300);
    }

    void unlabelled_page_breaks_continue_the_numbering() {
        auto live = make({"one", "<!-- pagebreak 7 -->", "two", "---", "three"});
        QCOMPARE(live.print_page_at(2), std::string("7"));
        QCOMPARE(live.print_page_at(4), std::string("8"));
        live.replace(1, 1, {"<!-- pagebreak 20 -->"});
        QCOMPARE(live.print_page_at(4), std::string("21"));
    }

    void long_braille_lines_wrap_at_word_spaces() {
        std::string line;
        for (int w = 0; w < 12; ++w) line += (w ? "\u2800" : "") + std::string("\u2813\u2811\u2807\u2807\u2815");
        const auto live = make({line});
        const auto& page = live.paged().pages.front();
        QCOMPARE(page.lines[0].size(), std::size_t{5 * 4 + 3});  // four words of five cells on 27
        QVERIFY(!page.lines[1].empty() && !page.lines[1][0].blank());
    }

    void bad_table_is_an_error_not_a_crash() {
        auto l = LiveLayout::create("no-such-table.ctb", {});
        QVERIFY(!l.has_value());
        QVERIFY(!l.error().message.empty());
        auto ok = make({"hello"});
        QVERIFY(!ok.set_tables("no-such-table.ctb").has_value());
        QCOMPARE(ok.tables(), std::string("en-ueb-g2.ctb"));  // unchanged
        QCOMPARE(ok.paged().pages.size(), std::size_t{1});
    }
};

QTEST_GUILESS_MAIN(LiveLayoutTest)
#include "live_layout_test.moc"
