// SPDX-License-Identifier: GPL-3.0-or-later
// A drawing opened in the app: File > Open of an SVG or a PNG lays it out by
// the CLI's core function, so the preview shows the dots `tactus-cli layout
// --summary` counts, front and back (the back of the graphic's sheet carries
// nothing); the print pane and the preview's accessible text say what the
// graphic is; embossing it on the simulator strikes those dots through the
// spool, as any document's.
#include <QAccessible>
#include <QDoubleSpinBox>
#include "announcer.hpp"
#include "braille_pane.hpp"
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "editor_widget.hpp"
#include "gui_test_support.hpp"
#include "main_window.hpp"
#include "preview_panel.hpp"
#include "printer_panel.hpp"
#include "profile_editor.hpp"
#include "spool/print_job.hpp"
#include "spool/snapshot.hpp"
#include "spool/spool.hpp"

using namespace tactus;
using namespace tactus::gui;

namespace {

// The graphic's dots as the CLI counts them ("graphic:    N dots on 1 graphic page").
std::size_t cli_graphic_dots(const QString& file, const QString& table) {
    QProcess p;
    p.start(QStringLiteral(TACTUS_CLI), {QStringLiteral("layout"), QStringLiteral("--summary"), QStringLiteral("--table"),
                                         table, file});
    if (!p.waitForFinished(60000) || p.exitCode() != 0) return 0;
    const auto out = QString::fromUtf8(p.readAllStandardOutput());
    const auto m = QRegularExpression(QStringLiteral("graphic: +(\\d+) dots on 1 graphic page")).match(out);
    return m.hasMatch() ? m.captured(1).toULongLong() : 0;
}

}  // namespace

class GraphicOpenTest : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // Opens `file`, checks the preview against the CLI, returns the dots.
    std::size_t check_preview(MainWindow& w, const QString& file) {
        if (!w.open_file_now(file)) return 0;
        const auto* graphic = w.graphic();
        if (!graphic) return 0;
        const auto want = cli_graphic_dots(file, QString::fromStdString(w.editor()->layout().tables()));
        auto* sp = w.preview_panel()->preview();
        sp->set_sheet(1);
        sp->set_mode(SideMode::front);
        const auto front = sp->shown_dot_count();
        // The back of the graphic's sheet is blank: its pits add nothing.
        sp->set_mode(SideMode::both);
        const auto both = sp->shown_dot_count();
        sp->set_mode(SideMode::back);
        const auto back = sp->shown_dot_count();
        sp->set_mode(SideMode::front);
        if (want == 0 || front != want || both != want || back != 0 || graphic->dots != want) {
            qWarning("%s: CLI %zu, preview front %zu, both %zu, back %zu, graphic %zu", qPrintable(file), want, front,
                     both, back, graphic->dots);
            return 0;
        }
        return want;
    }

private Q_SLOTS:
    void initTestCase() {
        install_accessibility();
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void an_svg_shows_its_dots_and_says_what_it_is() {
        MainWindow w;
        w.set_interactive(false);
        const auto file = QStringLiteral(TACTUS_TEST_DATA "/graphics/shapes.svg");
        const auto dots = check_preview(w, file);
        QVERIFY(dots > 100);
        const auto* graphic = w.graphic();
        QCOMPARE(graphic->title, QStringLiteral("Test shapes"));
        QVERIFY(graphic->description.startsWith(QStringLiteral("A circle, a labelled triangle")));
        QVERIFY(!graphic->labels.isEmpty());
        // The print pane: what the graphic is, read-only.
        auto* pane = w.editor()->print_pane();
        QVERIFY(pane->isReadOnly());
        QVERIFY2(pane->toPlainText().startsWith(QStringLiteral("Graphic: Test shapes. A circle, a labelled triangle")),
                 qPrintable(pane->toPlainText()));
        QVERIFY(pane->toPlainText().contains(QStringLiteral("Labels: ")));
        QVERIFY2(pane->accessibleDescription().startsWith(QStringLiteral("What the tactile graphic is")),
                 qPrintable(pane->accessibleDescription()));
        QVERIFY(pane->toPlainText().contains(QStringLiteral("\n%1 dot").arg(dots)));
        // What a screen reader hears on the preview.
        auto* sp = w.preview_panel()->preview();
        auto* iface = QAccessible::queryAccessibleInterface(sp);
        QVERIFY(iface);
        const auto said = iface->text(QAccessible::Description);
        QVERIFY2(said.startsWith(QStringLiteral("Sheet 1 front: Graphic: Test shapes. A circle")), qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral(" %1 dot").arg(dots)), qPrintable(said));
        // Another document afterwards is text again, editable, and its own pages are shown.
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        QVERIFY(!w.graphic());
        QVERIFY(!pane->isReadOnly());
        QVERIFY(!pane->accessibleDescription().startsWith(QStringLiteral("What the tactile graphic is")));
        QCOMPARE(sp->document(), &w.editor()->layout().paged());
    }

    // Saving would write the print pane's summary as Markdown over (or beside) the drawing.
    void a_drawing_is_not_saved_as_text() {
        MainWindow w;
        w.set_interactive(false);
        const auto copy = dir_.filePath(QStringLiteral("shapes.svg"));
        QFile::remove(copy);
        QVERIFY(QFile::copy(QStringLiteral(TACTUS_TEST_DATA "/graphics/shapes.svg"), copy));
        QFile before(copy);
        QVERIFY(before.open(QIODevice::ReadOnly));
        const auto bytes = before.readAll();
        before.close();
        QVERIFY(w.open_file_now(copy));
        QVERIFY(w.graphic());
        QVERIFY(!w.save_to(copy));
        const auto markdown = dir_.filePath(QStringLiteral("shapes.md"));
        QVERIFY(!w.save_to(markdown));
        QVERIFY(!QFile::exists(markdown));
        QFile after(copy);
        QVERIFY(after.open(QIODevice::ReadOnly));
        QCOMPARE(after.readAll(), bytes);
    }

    void a_png_shows_the_dots_the_cli_counts() {
        MainWindow w;
        w.set_interactive(false);
        const auto file = QStringLiteral(TACTUS_TEST_DATA "/graphics/pictures/shapes.png");
        QVERIFY(check_preview(w, file) > 100);
        QCOMPARE(w.graphic()->title, QStringLiteral("shapes.png"));  // a picture has no title: its name
    }

    // The profile's graphic spacing is the dots' rule: a wider line spacing
    // (still under the dotted line's 3 mm / 1.5), fewer dots.
    void a_profile_change_lays_the_graphic_out_again() {
        MainWindow w;
        w.set_interactive(false);
        const auto file = QStringLiteral(TACTUS_TEST_DATA "/graphics/line-drawing.svg");
        QVERIFY(w.open_file_now(file));
        const auto before = w.graphic()->dots;
        w.profile_editor()->field(QStringLiteral("graphic.line_dot_spacing_mm"))->setValue(2.0);
        QVERIFY(w.profile_editor()->error().isEmpty());
        QVERIFY(w.graphic());
        QVERIFY2(w.graphic()->dots < before, qPrintable(QStringLiteral("%1 -> %2").arg(before).arg(w.graphic()->dots)));
        QCOMPARE(w.preview_panel()->preview()->shown_dot_count(), w.graphic()->dots);
    }

    void embossing_a_graphic_on_the_simulator_strikes_its_dots() {
        const auto db = test::fresh_spool(dir_.path());
        MainWindow w;
        w.set_interactive(false);
        QVERIFY(w.open_file_now(QStringLiteral(TACTUS_TEST_DATA "/graphics/firmware-shapes.svg")));
        const auto dots = w.graphic()->dots;
        QVERIFY(dots > 0);
        w.printer_panel()->select_device(QStringLiteral("sim"));
        QVERIFY(w.emboss());
        auto s = spool::Spool::open(db, {.create = false});
        QVERIFY(s);
        const auto jobs = s->jobs(true);
        QVERIFY2(jobs, jobs ? "" : jobs.error().to_string().c_str());
        QCOMPARE(jobs->size(), std::size_t{1});
        const auto snapshot = s->document_snapshot(jobs->front().id);
        QVERIFY(snapshot);
        const auto pages = spool::from_snapshot(*snapshot);
        QVERIFY2(pages, pages ? "" : pages.error().to_string().c_str());
        QCOMPARE(pages->pages.front().graphic.size(), dots);
        const auto job = spool::make_print_job(*pages, w.profile_editor()->profile(), "");
        QVERIFY2(job, job ? "" : job.error().to_string().c_str());
        std::size_t front = 0, back = 0;
        for (const auto& pass : job->plan.sheets.front().passes)
            for (const auto& strike : pass.strikes) ++(strike.side == plan::Side::front ? front : back);
        QCOMPARE(front, dots);
        QCOMPARE(back, std::size_t{0});
    }
};

QTEST_MAIN(GraphicOpenTest)
#include "graphic_open_test.moc"
