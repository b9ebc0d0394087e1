// SPDX-License-Identifier: GPL-3.0-or-later
// The interpoint preview: where back dots land (mirrored, offset), when front and
// back collide, what a screen reader hears, and the PDF proof.
#include <QAccessible>
#include <QtTest>
#include <cmath>

#include "announcer.hpp"
#include "gui_test_support.hpp"
#include "live_layout.hpp"
#include "sheet_geometry.hpp"
#include "sheet_preview.hpp"

using namespace tactus;
using namespace tactus::gui;

namespace {

layout::Page full_page(int lines, int cells, document::Cell c = document::Cell{0x3F}) {
    layout::Page p;
    p.lines.assign(static_cast<std::size_t>(lines), document::BrailleLine(static_cast<std::size_t>(cells), c));
    return p;
}

}  // namespace

class PreviewTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { install_accessibility(); }

    void back_dots_are_mirrored_and_offset() {
        SheetGeometry g;
        layout::Page p;
        p.lines = {document::BrailleLine{document::Cell{0x01 | 0x08}}};  // dots 1 and 4 of the first cell
        const auto front = front_dots(p, g);
        const auto back = back_dots(p, g);
        QCOMPARE(front.size(), std::size_t{2});
        QCOMPARE(front[0].x_mm, g.left_margin_mm);
        QCOMPARE(front[1].x_mm, g.left_margin_mm + g.dot_pitch_mm);
        // Seen from the front, the back's first cell is at the right edge, dot 4 left of dot 1.
        QCOMPARE(back[0].x_mm, g.paper_width_mm - g.left_margin_mm + g.back_offset_x_mm);
        QCOMPARE(back[1].x_mm, back[0].x_mm - g.dot_pitch_mm);
        QCOMPARE(back[0].y_mm, g.top_margin_mm + g.back_offset_y_mm);
    }

    void full_sheets_clear_with_the_default_offset() {
        // Every dot of every cell raised on both sides: the worst case for crushing.
        SheetGeometry g;
        const auto page = full_page(24, 27);
        layout::Sheet s{1, &page, &page};
        QCOMPARE(find_conflicts(s, g).size(), std::size_t{0});
        // Closest pair: half a dot pitch across and down.
        g.min_separation_mm = std::hypot(g.back_offset_x_mm, g.back_offset_y_mm) + 0.01;
        QVERIFY(!find_conflicts(s, g).empty());
    }

    void zero_offset_puts_back_dots_on_front_dots() {
        SheetGeometry g;
        g.back_offset_x_mm = 0;
        g.back_offset_y_mm = 0;
        // Mirrored grid coincides with the front grid when 2 * margin + k * cell pitch
        // + dot pitch equals the paper width: choose the paper to make it so.
        g.paper_width_mm = 2 * g.left_margin_mm + 10 * g.cell_pitch_mm + g.dot_pitch_mm;
        const auto page = full_page(1, 11, document::Cell{0x01});
        layout::Sheet s{1, &page, &page};
        const auto conflicts = find_conflicts(s, g);
        QCOMPARE(conflicts.size(), std::size_t{0});  // only dot 1s: 2.5 mm apart at best
        const auto page4 = full_page(1, 11, document::Cell{0x08});
        layout::Sheet s2{1, &page, &page4};
        QCOMPARE(find_conflicts(s2, g).size(), std::size_t{11});  // each back dot 4 on a front dot 1
        for (const auto& c : find_conflicts(s2, g)) QVERIFY(c.distance_mm < 1e-9);
    }

    void accessible_preview_speaks_the_cell() {
        auto layout = LiveLayout::create("en-ueb-g1.ctb", {});
        layout->reset({"hello world"});
        SheetPreview preview;
        preview.set_document(&layout->paged());
        preview.set_back_translator([&](const document::BrailleLine& cells) {
            return QString::fromStdString(layout->back_translate(cells));
        });
        preview.show();
        // Paragraph indent 2: "hello" starts at cell 3.
        preview.show_position(0, 0, 2);
        const auto description = preview.cursor_description();
        QVERIFY2(description.contains(QStringLiteral("dots 1-2-5")), qPrintable(description));
        QVERIFY2(description.contains(QStringLiteral("\u201chello\u201d")), qPrintable(description));
        QVERIFY(description.contains(QStringLiteral("line 1, cell 3")));

        QAccessibleInterface* a = QAccessible::queryAccessibleInterface(&preview);
        QVERIFY(a);
        QCOMPARE(a->role(), QAccessible::Graphic);
        QVERIFY(!a->text(QAccessible::Name).isEmpty());
        QCOMPARE(a->text(QAccessible::Description), description);
        QVERIFY(a->state().focusable);
        auto* text = a->textInterface();
        QVERIFY(text);
        QCOMPARE(text->cursorPosition(), 2);
        QCOMPARE(text->text(2, 3), QString(QChar(0x2813)));  // h
        QSignalSpy moved(&preview, &SheetPreview::cursor_moved);
        preview.setFocus();
        QTest::keyClick(&preview, Qt::Key_Right);
        QCOMPARE(text->text(text->cursorPosition(), text->cursorPosition() + 1), QString(QChar(0x2811)));  // e
        QVERIFY(moved.last().first().toString().contains(QStringLiteral("dots 1-5")));
    }

    void keyboard_turns_sheets_and_sides() {
        auto layout = LiveLayout::create("en-ueb-g2.ctb", {});
        layout->reset(test::synthetic_book(120));
        SheetPreview preview;
        preview.set_document(&layout->paged());
        preview.show();
        preview.setFocus();
        QVERIFY(preview.sheet_count() > 3);
        QTest::keyClick(&preview, Qt::Key_PageDown);
        QTest::keyClick(&preview, Qt::Key_PageDown);
        QCOMPARE(preview.sheet(), std::size_t{3});
        QTest::keyClick(&preview, Qt::Key_PageUp);
        QCOMPARE(preview.sheet(), std::size_t{2});
        preview.set_mode(SideMode::front);
        QTest::keyClick(&preview, Qt::Key_Space);
        QCOMPARE(preview.mode(), SideMode::back);
        QCOMPARE(preview.cursor_page(), std::size_t{3});  // sheet 2's back is page 4
        QVERIFY(preview.cursor_description().contains(QStringLiteral("back")));
    }

    void notification_role_announcer() {
        Announcer announcer;
        announcer.show();
        QAccessibleInterface* a = QAccessible::queryAccessibleInterface(&announcer);
        QVERIFY(a);
        QCOMPARE(a->role(), QAccessible::Notification);
        announcer.announce(QStringLiteral("Sheet 3 of 9 embossed"));
        QCOMPARE(a->text(QAccessible::Name), QStringLiteral("Sheet 3 of 9 embossed"));
        QCOMPARE(announcer.count(), 1);
    }

    void pdf_proof_has_one_page_per_sheet() {
        auto layout = LiveLayout::create("en-ueb-g2.ctb", {});
        layout->reset(test::synthetic_book(60));
        const auto sheets = layout->paged().sheet_count();
        QVERIFY(sheets >= 3);
        QTemporaryDir dir;
        const auto path = dir.filePath(QStringLiteral("proof.pdf"));
        QString error;
        QVERIFY(print_to_pdf(layout->paged(), SheetGeometry{}, SideMode::both, path, &error));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const auto pdf = f.readAll();
        QVERIFY(pdf.startsWith("%PDF-"));
        const auto pages = pdf.count("/Type /Page\n") + pdf.count("/Type /Page ") + pdf.count("/Type /Page>");
        QCOMPARE(static_cast<std::size_t>(pages), sheets);
        QVERIFY(!print_to_pdf(layout->paged(), SheetGeometry{}, SideMode::both,
                              QStringLiteral("/nonexistent-dir/proof.pdf"), &error));
        QVERIFY(!error.isEmpty());
    }
};

QTEST_MAIN(PreviewTest)
#include "preview_test.moc"
