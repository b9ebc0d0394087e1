// SPDX-License-Identifier: GPL-3.0-or-later
// A book in the app: an EPUB (Jekyll and Hyde, Standard Ebooks, public
// domain) opens in the book layout; the preview moves by volume and says
// "Volume 2 of N, page t1"; the printer panel embosses a chosen volume or
// page range, and the built-in simulator strikes exactly those sheets.
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QPushButton>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThreadPool>
#include <QTimer>
#include <QtTest>

#include <set>

#include "announcer.hpp"
#include "book_settings.hpp"
#include "book_view.hpp"
#include "controller/builtin_sim.hpp"
#include "emboss_choice.hpp"
#include "gui_test_support.hpp"
#include "main_window.hpp"
#include "pipeline/page_range.hpp"
#include "preview_panel.hpp"
#include "printer_panel.hpp"
#include "profile/profile.hpp"
#include "spool/spool.hpp"

using namespace tactus;
using namespace tactus::gui;

namespace {

QString jekyll() {
    return QString::fromLatin1(TACTUS_TEST_DATA) + QStringLiteral("/import/books/jekyll-and-hyde.epub");
}

std::size_t dots_of(const layout::PagedDocument& doc, std::size_t first, std::size_t last) {
    std::size_t n = 0;
    for (std::size_t i = first - 1; i < last; ++i)
        for (const auto& line : doc.pages[i].lines)
            for (const auto c : line) n += static_cast<std::size_t>(__builtin_popcount(c.dots));
    return n;
}

}  // namespace

class BookViewTest : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // The book in volumes of 20 sheets: several volumes from a short novel.
    static void open_book(MainWindow& w) {
        QVERIFY(w.open_file_now(jekyll()));
        pipeline::BookOptions options;
        options.sheets_per_volume = 20;
        QSignalSpy ended(w.book_view(), &BookView::ended);
        w.book_view()->set_options(options);
        QVERIFY(ended.wait(60000));
        QVERIFY2(w.book_view()->active(), qPrintable(w.book_view()->error()));
    }

    static bool same_pages(const layout::PagedDocument& a, const layout::PagedDocument& b) {
        if (a.pages.size() != b.pages.size() || a.sections.size() != b.sections.size()) return false;
        for (std::size_t i = 0; i < a.pages.size(); ++i) {
            if (a.pages[i].lines != b.pages[i].lines || a.pages[i].braille_number != b.pages[i].braille_number)
                return false;
        }
        return true;
    }

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("TactusTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tactus-test"));
        QSettings().clear();
        install_accessibility();
    }
    void init() { test::fresh_spool(dir_.path()); }

    // Every rule and title line the dialog shows comes back from it as
    // given; the rules (not the title page's lines) are kept in the settings,
    // and a value out of range there is the rule's default.
    void book_settings_keep_every_rule() {
        pipeline::BookOptions o;
        o.sheets_per_volume = 33;
        o.split_level = 1;
        o.title_page = false;
        o.contents = false;
        o.contents_depth = 4;
        o.running_heads = false;
        o.title = "The Strange Case";
        o.author = "R. L. Stevenson";
        o.publisher = "Standard Ebooks";
        o.year = "1886";
        o.transcriber = "A Teacher";
        BookSettingsDialog dialog(o);
        const auto shown = dialog.options();
        QCOMPARE(shown.sheets_per_volume, 33);
        QCOMPARE(shown.split_level, 1);
        QCOMPARE(shown.title_page, false);
        QCOMPARE(shown.contents, false);
        QCOMPARE(shown.contents_depth, 4);
        QCOMPARE(shown.running_heads, false);
        QCOMPARE(shown.title, o.title);
        QCOMPARE(shown.author, o.author);
        QCOMPARE(shown.publisher, o.publisher);
        QCOMPARE(shown.year, o.year);
        QCOMPARE(shown.transcriber, o.transcriber);
        auto* depth = dialog.findChild<QSpinBox*>(QStringLiteral("bookContentsDepth"));
        QVERIFY(depth && !depth->isEnabled());  // no contents, no depth to choose
        dialog.findChild<QCheckBox*>(QStringLiteral("bookContents"))->setChecked(true);
        QVERIFY(depth->isEnabled());
        // Restore Defaults: the rules' defaults, the title page's lines as typed.
        auto* buttons = dialog.findChild<QDialogButtonBox*>();
        QVERIFY(buttons);
        buttons->button(QDialogButtonBox::RestoreDefaults)->click();
        const auto restored = dialog.options();
        QCOMPARE(restored.sheets_per_volume, pipeline::BookOptions{}.sheets_per_volume);
        QCOMPARE(restored.contents_depth, pipeline::BookOptions{}.contents_depth);
        QCOMPARE(restored.running_heads, true);
        QCOMPARE(restored.title, o.title);
        QCOMPARE(restored.transcriber, o.transcriber);

        QSettings s;
        save_book_rules(s, o);
        auto back = load_book_rules(s);
        QCOMPARE(back.sheets_per_volume, 33);
        QCOMPARE(back.split_level, 1);
        QCOMPARE(back.title_page, false);
        QCOMPARE(back.contents, false);
        QCOMPARE(back.contents_depth, 4);
        QCOMPARE(back.running_heads, false);
        QVERIFY(back.title.empty() && back.author.empty() && back.transcriber.empty());
        s.setValue(QStringLiteral("book/sheets_per_volume"), 1);
        s.setValue(QStringLiteral("book/contents_depth"), QStringLiteral("deep"));
        back = load_book_rules(s);
        QCOMPARE(back.sheets_per_volume, pipeline::BookOptions{}.sheets_per_volume);
        QCOMPARE(back.contents_depth, pipeline::BookOptions{}.contents_depth);
        s.remove(QStringLiteral("book"));
    }

    // Book Settings lays the open book out again: smaller volumes give more
    // of them, and the title typed is on every volume's title page; the
    // rules stay for the next window, the title does not stay for the next
    // document.
    void book_settings_lay_the_book_out_again() {
        QSettings().remove(QStringLiteral("book"));
        std::size_t volumes_before = 0;
        {
            MainWindow w;
            QVERIFY(w.open_file_now(jekyll()));
            auto* book = w.book_view();
            QSignalSpy ended(book, &BookView::ended);
            book->start();
            QVERIFY(ended.wait(60000));
            QVERIFY(book->active());
            volumes_before = book->volumes().size();
            QCOMPARE(book->options().sheets_per_volume, pipeline::BookOptions{}.sheets_per_volume);

            auto options = book->options();
            options.sheets_per_volume = 20;
            w.apply_book_settings(options);
            QVERIFY(ended.wait(60000));
            QVERIFY2(book->active(), qPrintable(book->error()));
            QVERIFY2(book->volumes().size() > volumes_before,
                     qPrintable(QStringLiteral("%1 volumes, %2 before").arg(book->volumes().size()).arg(volumes_before)));
            const auto from_metadata = book->shown(nullptr)->pages[book->volumes()[0].first_page].lines;
            const auto volumes = book->volumes().size();
            options.title = "A Teacher's Copy";
            w.apply_book_settings(options);
            QVERIFY(ended.wait(60000));
            QCOMPARE(book->volumes().size(), volumes);
            // The title page (t1) is no longer the one made from the EPUB's metadata.
            QVERIFY(book->shown(nullptr)->pages[book->volumes()[0].first_page].lines != from_metadata);
        }
        MainWindow again;
        QCOMPARE(again.book_view()->options().sheets_per_volume, 20);
        QVERIFY(again.book_view()->options().title.empty());
        {
            MainWindow w;
            auto options = w.book_view()->options();
            options.title = "Not for the next document";
            w.apply_book_settings(options);
            QVERIFY(w.open_file_now(jekyll()));
            QVERIFY(w.book_view()->options().title.empty());
            QCOMPARE(w.book_view()->options().sheets_per_volume, 20);
        }
        QSettings().remove(QStringLiteral("book"));
    }

    void a_short_text_is_not_a_book() {
        MainWindow w;
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        w.book_view()->refresh_now();
        QVERIFY(!w.book_view()->active());
        auto* chooser = w.preview_panel()->findChild<QComboBox*>(QStringLiteral("volumeChooser"));
        QVERIFY(chooser);
        QVERIFY(!w.preview_panel()->next_volume_action()->isEnabled());
        QVERIFY(!w.preview_panel()->label_text().contains(QStringLiteral("Volume")));
    }

    // The book is laid out on a worker: the event loop turns meanwhile (a
    // timer ticks, as the screen reader's requests are answered), and the
    // book shown is the one the same layout gives on the calling thread.
    void the_book_is_laid_out_while_the_event_loop_turns() {
        MainWindow w;
        QVERIFY(w.open_file_now(jekyll()));
        auto* book = w.book_view();
        QSignalSpy ended(book, &BookView::ended);
        QSignalSpy progressed(book, &BookView::progressed);
        int ticks = 0;
        QTimer tick;
        tick.setInterval(0);
        connect(&tick, &QTimer::timeout, [&] { ++ticks; });
        tick.start();
        book->start();
        QVERIFY(book->running());
        QVERIFY(ended.wait(60000));
        tick.stop();
        QCOMPARE(ended.last()[0].toBool(), true);
        QVERIFY2(ticks > 0, "the GUI thread was blocked while the book was laid out");
        QVERIFY(!progressed.isEmpty());
        QVERIFY(book->active());
        const auto shown = *book->shown(nullptr);
        const auto volumes = book->volumes();
        const auto labels = book->labels();
        // The same layout on this thread.
        book->refresh_now();
        QVERIFY(book->active());
        QVERIFY(same_pages(shown, *book->shown(nullptr)));
        QCOMPARE(volumes.size(), book->volumes().size());
        for (std::size_t v = 0; v < volumes.size(); ++v) {
            QCOMPARE(volumes[v].first_page, book->volumes()[v].first_page);
            QCOMPARE(volumes[v].end_page, book->volumes()[v].end_page);
        }
        QCOMPARE(labels, book->labels());
        QCOMPARE(w.preview_panel()->preview()->document(), book->shown(nullptr));
    }

    // A layout still running when another document opens is dropped: its
    // book never replaces the new document's pages.
    void a_layout_overtaken_by_another_document_is_not_shown() {
        MainWindow w;
        QVERIFY(w.open_file_now(jekyll()));
        auto* book = w.book_view();
        QSignalSpy changed(book, &BookView::changed);
        book->start();
        QVERIFY(book->running());
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        QVERIFY(!book->running());
        QVERIFY(!book->active());
        // Let the dropped job end: nothing it made is shown.
        QThreadPool::globalInstance()->waitForDone();
        QCoreApplication::processEvents();
        QVERIFY(!book->active());
        QCOMPARE(book->labels(), pipeline::page_labels(w.paged()));
        QCOMPARE(w.preview_panel()->preview()->document(), &w.paged());
    }

    // Cancel stops the layout; the pages shown stay as they were and the
    // app's state says no layout is running.
    void a_cancelled_layout_leaves_the_pages_shown() {
        MainWindow w;
        open_book(w);
        auto* book = w.book_view();
        const auto before = *book->shown(nullptr);
        QSignalSpy ended(book, &BookView::ended);
        pipeline::BookOptions options = book->options();
        options.sheets_per_volume = 30;
        book->set_options(options);
        QVERIFY(book->running());
        book->cancel();
        QVERIFY(!book->running());
        QCOMPARE(ended.size(), 1);
        QCOMPARE(ended[0][0].toBool(), false);
        QThreadPool::globalInstance()->waitForDone();
        QCoreApplication::processEvents();
        QCOMPARE(ended.size(), 1);
        QVERIFY(same_pages(before, *book->shown(nullptr)));
    }

    void the_preview_moves_by_volume_and_says_where_it_is() {
        MainWindow w;
        w.show();
        open_book(w);
        auto* book = w.book_view();
        const auto volumes = book->volumes().size();
        QVERIFY2(volumes >= 2, qPrintable(QString::number(volumes)));
        auto* panel = w.preview_panel();
        auto* sp = panel->preview();
        // The preview shows the book: the title page first.
        QCOMPARE(sp->document(), book->shown(nullptr));
        QVERIFY2(panel->label_text().startsWith(QStringLiteral("Volume 1 of %1, page t1; Sheet 1 of").arg(volumes)),
                 qPrintable(panel->label_text()));
        QSignalSpy said(w.announcer(), &Announcer::announced);
        panel->next_volume_action()->trigger();
        QCOMPARE(panel->volume(), std::size_t{1});
        const auto second = book->volumes()[1];
        QCOMPARE(sp->sheet(), sp->document()->geometry.sheet_of_page(second.first_page));
        QVERIFY2(!said.isEmpty() && said.last()[0].toString().startsWith(
                                        QStringLiteral("Volume 2 of %1, page t1; Sheet").arg(volumes)),
                 qPrintable(said.isEmpty() ? QString() : said.last()[0].toString()));
        auto* chooser = panel->findChild<QComboBox*>(QStringLiteral("volumeChooser"));
        QCOMPARE(chooser->accessibleName(), QStringLiteral("Volume"));
        QCOMPARE(chooser->count(), static_cast<int>(volumes));
        QCOMPARE(chooser->currentIndex(), 1);
        // The next sheet of volume 2 is its contents page, numbered p1.
        sp->set_sheet(sp->document()->geometry.sheet_of_page(second.contents_first_page));
        QVERIFY2(panel->label_text().startsWith(QStringLiteral("Volume 2 of %1, page p1").arg(volumes)),
                 qPrintable(panel->label_text()));
        // The last volume says so; back goes to volume 1.
        for (std::size_t v = 1; v < volumes; ++v) panel->next_volume_action()->trigger();
        QVERIFY(said.last()[0].toString().contains(QStringLiteral("is the last")));
        chooser->activated(0);
        QCOMPARE(panel->volume(), std::size_t{0});
        QCOMPARE(sp->sheet(), std::size_t{1});
    }

    void a_page_range_embosses_exactly_its_sheets() {
        MainWindow w;
        open_book(w);
        auto* book = w.book_view();
        auto* printer = w.printer_panel();
        auto* choice = printer->emboss_choice();
        const auto& pages = *book->shown(nullptr);
        // Every control has a name a screen reader says.
        for (auto* c : choice->findChildren<QWidget*>())
            if (c->focusPolicy() != Qt::NoFocus && !qobject_cast<QLabel*>(c))
                QVERIFY2(!c->accessibleName().isEmpty(), qPrintable(c->objectName()));
        // The range is passed over by Tab until "Page range" is chosen (End
        // in the choice, as Orca's user does); then Tab goes to it.
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        w.show_panel(QStringLiteral("printer"));
        auto* scope = choice->findChild<QComboBox*>(QStringLiteral("embossScope"));
        auto* pages_field = choice->findChild<QLineEdit*>(QStringLiteral("embossPages"));
        scope->setFocus(Qt::ShortcutFocusReason);
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
        QVERIFY(QApplication::focusWidget() != pages_field);
        scope->setFocus(Qt::ShortcutFocusReason);
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_End);
        QCOMPARE(scope->currentIndex(), scope->count() - 1);
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
        QVERIFY2(QApplication::focusWidget() == choice->findChild<QLineEdit*>(QStringLiteral("embossPages")),
                 qPrintable(QApplication::focusWidget() ? QApplication::focusWidget()->objectName() + QLatin1Char(' ') +
                                                              QApplication::focusWidget()->accessibleName()
                                                        : QStringLiteral("none")));
        // Typed as a user types it, the range is said on Enter.
        QSignalSpy said(w.announcer(), &Announcer::announced);
        QTest::keyClicks(QApplication::focusWidget(), QStringLiteral("3-10"));
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return);
        QVERIFY(!said.isEmpty());
        QVERIFY2(said.last()[0].toString().startsWith(QStringLiteral("Pages 3 to 10: 4 sheet")),
                 qPrintable(said.last()[0].toString()));
        const auto range = choice->chosen();
        QVERIFY(range);
        // Body pages 3 to 10 are eight pages after the title and contents.
        QCOMPARE(book->labels()[range->first - 1], std::string("3"));
        QCOMPARE(book->labels()[range->second - 1], std::string("10"));
        QCOMPARE(range->second - range->first + 1, std::size_t{8});
        // "4 sheet(s)" untranslated, "4 sheets" in English.
        QVERIFY2(choice->summary().startsWith(QStringLiteral("Pages 3 to 10: 4 sheet")), qPrintable(choice->summary()));
        printer->select_device(QStringLiteral("sim?speed=max"));
        QSignalSpy finished(printer, &PrinterPanel::job_finished);
        const auto id = printer->submit(QStringLiteral("jekyll"), pages, profile::default_profile());
        QVERIFY(id > 0);
        QVERIFY(finished.wait(120000));
        QVERIFY2(finished[0][1].toBool(), qPrintable(finished[0][2].toString()));
        auto spool = spool::Spool::open(printer->spool_path().string(), {.create = false});
        QVERIFY(spool);
        const auto job = spool->job(id);
        QVERIFY(job);
        QCOMPARE(job->sheets_per_copy, std::size_t{4});
        // The simulator struck four sheets, every dot of those pages and no other.
        std::set<int> sheets;
        std::size_t strikes = 0;
        for (const auto& s : printer->simulator().strikes()) {
            sheets.insert(s.sheet);
            ++strikes;
        }
        QCOMPARE(sheets.size(), std::size_t{4});
        QCOMPARE(strikes, dots_of(pages, range->first, range->second));

        // A range that names no page queues nothing and says why.
        choice->choose_range(QStringLiteral("900-990"));
        QVERIFY(choice->summary().contains(QStringLiteral("page 900 is not in the document")));
        QCOMPARE(printer->submit(QStringLiteral("jekyll"), pages, profile::default_profile()), spool::JobId{0});
        // A volume: its own sheets, title page first.
        choice->choose_volume(1);
        const auto v = choice->chosen();
        QVERIFY(v);
        QCOMPARE(v->first - 1, book->volumes()[1].first_page);
        QCOMPARE(v->second, book->volumes()[1].end_page);
        QVERIFY(choice->summary().startsWith(QStringLiteral("Volume 2 of")));
    }
};

QTEST_MAIN(BookViewTest)
#include "book_view_test.moc"
