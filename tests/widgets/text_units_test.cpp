// SPDX-License-Identifier: GPL-3.0-or-later
// The units a screen reader reads the app's own text interfaces by: they tile
// the text for every boundary type (so reading on by "the unit after" always
// ends), and a blank braille cell separates words as a space does.
#include <QtTest>

#include "text_units.hpp"

using namespace tactus::gui;

namespace {

const QAccessible::TextBoundaryType kAll[] = {QAccessible::CharBoundary, QAccessible::WordBoundary,
                                              QAccessible::SentenceBoundary, QAccessible::LineBoundary,
                                              QAccessible::ParagraphBoundary};

QString braille(const char32_t* s) { return QString::fromStdU32String(s); }

}  // namespace

class TextUnitsTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void braille_words_end_at_blank_cells() {
        // "⠠⠃⠗⠇ ⠊⠎ ⠞⠁⠉⠞" with blank cells (U+2800) between words.
        const auto t = braille(U"\u2820\u2803\u2817\u2807\u2800\u280a\u280e\u2800\u281e\u2801\u2809\u281e");
        int s = -1, e = -1;
        QCOMPARE(text_at_offset(t, 0, QAccessible::WordBoundary, &s, &e), t.mid(0, 5));
        QCOMPARE(s, 0);
        QCOMPARE(e, 5);
        QCOMPARE(text_at_offset(t, 6, QAccessible::WordBoundary, &s, &e), t.mid(5, 3));
        QCOMPARE(text_after_offset(t, 6, QAccessible::WordBoundary, &s, &e), t.mid(8));
        QCOMPARE(text_before_offset(t, 6, QAccessible::WordBoundary, &s, &e), t.mid(0, 5));
        QCOMPARE(next_word_start(t, 0), 5);
        QCOMPARE(next_word_start(t, 5), 8);
        QCOMPARE(next_word_start(t, 8), 12);
        QCOMPARE(previous_word_start(t, 12), 8);
        QCOMPARE(previous_word_start(t, 8), 5);
        QCOMPARE(previous_word_start(t, 5), 0);
    }

    void a_line_of_cells_without_any_word_answers() {
        // The preview's line at its first cell: what once never returned.
        const auto t = braille(U"\u2800\u2800\u2801\u2800");
        int s = -1, e = -1;
        QCOMPARE(text_at_offset(t, 0, QAccessible::WordBoundary, &s, &e), t.mid(0, 2));
        QCOMPARE(text_at_offset(t, 2, QAccessible::WordBoundary, &s, &e), t.mid(2));
        QCOMPARE(text_at_offset(t, 4, QAccessible::WordBoundary, &s, &e), t.mid(2));
        QCOMPARE(text_at_offset(t, 4, QAccessible::CharBoundary, &s, &e), QString());
        QCOMPARE(text_before_offset(t, 4, QAccessible::CharBoundary, &s, &e), t.mid(3, 1));
    }

    void sentences_and_paragraphs() {
        const QString t = QStringLiteral("One two. Three 3.5 four!\nNext line");
        int s = -1, e = -1;
        QCOMPARE(text_at_offset(t, 2, QAccessible::SentenceBoundary, &s, &e), QStringLiteral("One two. "));
        QCOMPARE(text_at_offset(t, 12, QAccessible::SentenceBoundary, &s, &e), QStringLiteral("Three 3.5 four!\n"));
        QCOMPARE(text_at_offset(t, 3, QAccessible::ParagraphBoundary, &s, &e),
                 QStringLiteral("One two. Three 3.5 four!\n"));
        QCOMPARE(text_after_offset(t, 3, QAccessible::LineBoundary, &s, &e), QStringLiteral("Next line"));
    }

    // Property: for every boundary and offset the unit holds the offset, the unit
    // after starts where it ends and the unit before ends where it starts.
    void units_tile_every_text() {
        const QString texts[] = {QString(), QStringLiteral(" "), QStringLiteral("a"), QStringLiteral("  lead and trail  "),
                                 braille(U"\u2800\u2800\u2800"), braille(U"\u2801\u2803\u2809"),
                                 QStringLiteral("Para one. Two!\n\nPara three?\n"), braille(U"\u2801\n\u2800\n\u2803")};
        for (const auto& t : texts) {
            const int n = static_cast<int>(t.size());
            for (const auto b : kAll) {
                for (int o = 0; o <= n; ++o) {
                    int s = -1, e = -1;
                    const auto at = text_at_offset(t, o, b, &s, &e);
                    QVERIFY2(0 <= s && s <= e && e <= n, qPrintable(QStringLiteral("%1 @%2 b%3").arg(t).arg(o).arg(b)));
                    QCOMPARE(at, t.mid(s, e - s));
                    if (o < n) QVERIFY(s <= o && o < e);
                    int as = -1, ae = -1;
                    text_after_offset(t, o, b, &as, &ae);
                    if (as < n) QCOMPARE(as, e);
                    int bs = -1, be = -1;
                    text_before_offset(t, o, b, &bs, &be);
                    if (be > 0 && o < n) QCOMPARE(be, s);
                }
                // Reading on from the start reaches the end in at most n + 1 units.
                int at = 0, steps = 0, s = 0, e = 0;
                text_at_offset(t, 0, b, &s, &e);
                for (at = e; at < n && steps <= n; ++steps) {
                    text_after_offset(t, s, b, &s, &e);
                    QVERIFY(e > at || e == n);
                    at = e;
                }
                QVERIFY(steps <= n);
            }
        }
    }
};

QTEST_GUILESS_MAIN(TextUnitsTest)
#include "text_units_test.moc"
