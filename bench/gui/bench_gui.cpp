// SPDX-License-Identifier: GPL-3.0-or-later
// The desktop app on a 1,000-page book (the KJV's first verses, one paragraph
// each): keystroke-to-updated-preview latency (median, 95th percentile; goal
// under 16 ms median), time to open the book against `tactus-cli layout` on the
// same file, and resident memory with it open. Runs offscreen.
// With --text the book is a hard-wrapped plain text file (72 columns, a blank
// line between verses, as Project Gutenberg writes books): the editor's text
// dialect, where a paragraph is several editor lines brailled as one.
// With a .pef the book is that ready-made braille, opened as it is (its own
// pages, sections and volumes kept by layout::keep_braille_pages after every
// edit): each keystroke types or erases a braille cell in a row.
// Usage: bench_gui BOOK.txt [PAGES] [--text] | bench_gui BOOK.pef
#include <sys/wait.h>
#include <unistd.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "braille_pane.hpp"
#include "editor_widget.hpp"
#include "edit/live_layout.hpp"
#include "main_window.hpp"
#include "preview_panel.hpp"

using namespace tactus;
using namespace tactus::gui;
using Clock = std::chrono::steady_clock;

namespace {

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

long rss_kb() {
    std::ifstream f("/proc/self/status");
    std::string key;
    long value = 0;
    while (f >> key) {
        if (key == "VmRSS:") {
            f >> value;
            return value;
        }
        f.ignore(1 << 12, '\n');
    }
    return 0;
}

double time_cli(const std::string& file) {
    const auto t0 = Clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::execl(TACTUS_CLI, TACTUS_CLI, "layout", "--preset", "a4", "--interpoint", "--to", "brf", "-o", "/dev/null",
                file.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) std::fprintf(stderr, "tactus-cli layout failed\n");
    return ms_since(t0);
}

double percentile(std::vector<double> v, double p) {
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
}

// Keystrokes in a ready-made braille book: a cell typed into a row, then erased.
int bench_pef(const std::string& file) {
    const long rss_empty = rss_kb();
    MainWindow window;
    window.resize(1400, 900);
    window.show();
    auto options = window.editor()->layout().options();
    options.geometry.cells_per_line = 40;  // room for the file's own page
    options.geometry.lines_per_page = 30;
    if (!window.editor()->set_layout_options(options)) return 1;
    QSignalSpy opened(&window, &MainWindow::opened);
    const auto t_open = Clock::now();
    window.open_file(QString::fromStdString(file));
    if (!opened.wait(600000)) {
        std::fprintf(stderr, "open timed out\n");
        return 1;
    }
    const double open_ms = ms_since(t_open);
    QApplication::processEvents();
    const long rss_open = rss_kb();
    const auto& layout = window.editor()->layout();
    if (!layout.pages_kept()) {
        std::fprintf(stderr, "the file's pages are not kept (do they fit 40 x 30?)\n");
        return 1;
    }
    auto* print = window.editor()->print_pane();
    auto* preview = window.preview_panel()->preview();
    std::mt19937 rng(1);
    std::vector<double> latency;
    for (int k = 0; k < 300; ++k) {
        int line = 0;  // a row: not a page break line, not an empty row
        do line = std::uniform_int_distribution<int>(0, print->document()->blockCount() - 1)(rng);
        while (print->document()->findBlockByNumber(line).text().startsWith(QLatin1Char('<')) ||
               print->document()->findBlockByNumber(line).text().size() < 2);
        const auto block = print->document()->findBlockByNumber(line);
        QTextCursor c(block);
        c.movePosition(QTextCursor::EndOfBlock);
        QApplication::processEvents();
        const auto t0 = Clock::now();
        c.insertText(QString(QChar(0x2811)));  // one cell, as the braille pane types it
        c.deletePreviousChar();
        preview->repaint();
        latency.push_back(ms_since(t0) / 2);
    }
    if (!layout.pages_kept()) std::fprintf(stderr, "the pages were laid out again\n");
    // The autosave of the edited book: PEF (edit::structured_braille_pef), on the GUI thread every 30 s while unsaved.
    std::vector<double> autosave;
    for (int k = 0; k < 5; ++k) {
        const auto t0 = Clock::now();
        if (!window.autosave_now()) std::fprintf(stderr, "autosave failed\n");
        autosave.push_back(ms_since(t0));
    }
    const bool autosaved_pef = window.autosave_path().endsWith(QLatin1String(".pef"));
    QFile::remove(window.autosave_path());  // leave no recovery behind
    QFile::remove(window.autosave_path() + QStringLiteral(".json"));
    std::printf("document: %s, %d editor lines, %zu braille pages, %zu sheets, %zu sections (kept as they are)\n",
                file.c_str(), print->document()->blockCount(), layout.paged().pages.size(), layout.paged().sheet_count(),
                layout.paged().sections.size());
    std::printf("braille cell typed -> updated preview: median %.2f ms, p95 %.2f ms, max %.2f ms (goal: median < 16 ms)\n",
                percentile(latency, 0.5), percentile(latency, 0.95), percentile(latency, 1.0));
    std::printf("open: tactus %.0f ms\n", open_ms);
    std::printf("autosave%s: median %.1f ms, max %.1f ms\n", autosaved_pef ? " as PEF" : " (not PEF!)",
                percentile(autosave, 0.5), percentile(autosave, 1.0));
    std::printf("resident memory: %.1f MB with the book open (%.1f MB before opening)\n",
                static_cast<double>(rss_open) / 1024.0, static_cast<double>(rss_empty) / 1024.0);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    const bool text = argc > 2 && std::string(argv[argc - 1]) == "--text";
    if (text) --argc;
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s BOOK.txt [PAGES] [--text]\n", argv[0]);
        return 2;
    }
    const std::size_t target_pages = argc > 2 ? std::stoul(argv[2]) : 1000;
    const bool pef = std::string_view(argv[1]).ends_with(".pef");
    if (pef) return bench_pef(argv[1]);

    // The first verses of the book, one paragraph each, until they fill the pages.
    std::ifstream in(argv[1]);
    std::vector<std::string> verses;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) verses.push_back(line);
    auto created = edit::LiveLayout::create("en-ueb-g2.ctb", {});
    if (!created) return 1;
    auto probe = std::make_unique<edit::LiveLayout>(std::move(*created));
    std::size_t n = std::min<std::size_t>(verses.size(), target_pages * 5);
    probe->reset(std::vector<std::string>(verses.begin(), verses.begin() + static_cast<std::ptrdiff_t>(n)));
    while (probe->paged().pages.size() > target_pages && n > 10) {
        n = n * target_pages / probe->paged().pages.size();
        probe->reset(std::vector<std::string>(verses.begin(), verses.begin() + static_cast<std::ptrdiff_t>(n)));
    }
    while (probe->paged().pages.size() < target_pages && n + 10 <= verses.size()) {
        n += 10;
        probe->reset(std::vector<std::string>(verses.begin(), verses.begin() + static_cast<std::ptrdiff_t>(n)));
    }
    QTemporaryDir dir;
    const auto book = dir.filePath(text ? QStringLiteral("book.txt") : QStringLiteral("book.md")).toStdString();
    {
        std::ofstream out(book);
        for (std::size_t i = 0; i < n; ++i) {
            if (!text) {
                out << verses[i] << "\n\n";
                continue;
            }
            // Wrapped at the last space before column 72.
            std::string_view rest = verses[i];
            while (rest.size() > 72) {
                auto cut = rest.rfind(' ', 72);
                if (cut == std::string_view::npos || cut == 0) cut = 72;
                out << rest.substr(0, cut) << "\n";
                rest.remove_prefix(std::min(rest.size(), cut + 1));
            }
            out << rest << "\n\n";
        }
    }
    probe.reset();

    const long rss_empty = rss_kb();
    MainWindow window;
    window.resize(1400, 900);
    window.show();
    QSignalSpy opened(&window, &MainWindow::opened);
    const auto t_open = Clock::now();
    window.open_file(QString::fromStdString(book));
    if (!opened.wait(600000)) {
        std::fprintf(stderr, "open timed out\n");
        return 1;
    }
    const double open_ms = ms_since(t_open);
    const double cli_ms = time_cli(book);
    QApplication::processEvents();
    const long rss_open = rss_kb();
    const auto pages = window.editor()->layout().paged().pages.size();

    // Keystrokes at random places; each is timed until the preview has repainted.
    auto* print = window.editor()->print_pane();
    auto* preview = window.preview_panel()->preview();
    print->setFocus();
    std::mt19937 rng(1);
    std::vector<double> latency;
    std::size_t relaid = 0;
    for (int k = 0; k < 300; ++k) {
        auto line = std::uniform_int_distribution<int>(0, print->document()->blockCount() - 1)(rng);
        // In a text: a line of words (a letter typed into the blank line between
        // two paragraphs joins them, and the pages after it move).
        while (text && print->document()->findBlockByNumber(line).text().trimmed().isEmpty())
            line = std::uniform_int_distribution<int>(0, print->document()->blockCount() - 1)(rng);
        const auto block = print->document()->findBlockByNumber(line);
        QTextCursor c(block);
        c.setPosition(block.position() + std::max(0, block.length() - 1) / 2);
        print->setTextCursor(c);
        QApplication::processEvents();
        const auto t0 = Clock::now();
        QTest::keyClick(print, k % 2 ? Qt::Key_Backspace : Qt::Key_E);
        preview->repaint();
        latency.push_back(ms_since(t0));
        relaid += window.editor()->last_stats().pages_relaid;
    }

    std::printf("document: %zu verses%s, %d editor lines, %zu braille pages, %zu sheets (en-ueb-g2, 27x24 interpoint)\n", n,
                text ? " (hard-wrapped .txt)" : "", print->document()->blockCount(), pages,
                window.editor()->layout().paged().sheet_count());
    std::printf("keystroke -> updated preview: median %.2f ms, p95 %.2f ms, max %.2f ms (goal: median < 16 ms)\n",
                percentile(latency, 0.5), percentile(latency, 0.95), percentile(latency, 1.0));
    std::printf("  pages re-laid per keystroke: %.1f on average\n", static_cast<double>(relaid) / 300.0);
    std::printf("open: tactus %.0f ms, tactus-cli layout %.0f ms, ratio %.2f\n", open_ms, cli_ms, open_ms / cli_ms);
    std::printf("resident memory: %.1f MB with the book open (%.1f MB before opening)\n", static_cast<double>(rss_open) / 1024.0,
                static_cast<double>(rss_empty) / 1024.0);
    return 0;
}
