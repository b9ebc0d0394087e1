// SPDX-License-Identifier: GPL-3.0-or-later
// tactus: the desktop app. Parses the command line, loads the translation for the
// user's language, and shows the main window.
#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QLibraryInfo>
#include <QLocale>
#include <QTimer>
#include <QSocketNotifier>
#include <QTranslator>
#include <cstdio>

#include "announcer.hpp"
#include "editor_widget.hpp"
#include "main_window.hpp"
#include "pipeline/translation_workers.hpp"
#include "platform/termination.hpp"
#include "preview_panel.hpp"
#include "printer_panel.hpp"

using namespace tactus::gui;

namespace {

// --help and --version must work without a display (scripts, packaging checks).
bool wants_text_only(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const QByteArray a(argv[i]);
        if (a == "--help" || a == "-h" || a == "--help-all" || a == "--version" || a == "-v") return true;
    }
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    // Started again as a translation worker (Windows): that and nothing else, no window.
    if (const auto worker = tactus::pipeline::run_translation_worker(argc, argv)) return *worker;
    if (wants_text_only(argc, argv)) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Tactus"));
    QApplication::setApplicationName(QStringLiteral("tactus"));
    QApplication::setApplicationDisplayName(QStringLiteral("Tactus"));
    QApplication::setApplicationVersion(QStringLiteral(TACTUS_VERSION));
    QApplication::setDesktopFileName(QStringLiteral("tactus"));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/tactus.svg")));

    QCommandLineParser cli;
    cli.setApplicationDescription(QApplication::translate(
        "main", "Braille editor and embosser print manager: edit print and braille side by side, "
                "preview interpoint sheets, emboss."));
    cli.addHelpOption();
    cli.addVersionOption();
    cli.addPositionalArgument(QStringLiteral("file"),
                              QApplication::translate("main", "Document to open (Markdown, text, DOCX, BRF, PEF)."),
                              QStringLiteral("[file]"));
    const QCommandLineOption table({QStringLiteral("t"), QStringLiteral("table")},
                                   QApplication::translate("main", "liblouis table, e.g. en-ueb-g2.ctb or zh-tw.ctb."),
                                   QStringLiteral("table"));
    const QCommandLineOption side(QStringLiteral("side"),
                                  QApplication::translate("main", "Preview side: front, back or both."),
                                  QStringLiteral("side"));
    const QCommandLineOption sheet(QStringLiteral("sheet"), QApplication::translate("main", "Sheet to preview."),
                                   QStringLiteral("n"));
    const QCommandLineOption language(QStringLiteral("lang"),
                                      QApplication::translate("main", "User interface language, e.g. zh_TW."),
                                      QStringLiteral("locale"));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                        QApplication::translate("main", "Save a picture of the window and quit."),
                                        QStringLiteral("png"));
    const QCommandLineOption panel_name(QStringLiteral("panel"),
                                   QApplication::translate("main", "Panel to show: preview, motion, vibration, profile, printer."),
                                   QStringLiteral("name"));
    const QCommandLineOption emboss_option(QStringLiteral("emboss"),
                                           QApplication::translate("main", "Emboss the file on the last used embosser once it is open."));
    const QCommandLineOption no_recovery(QStringLiteral("no-recovery"),
                                         QApplication::translate("main", "Do not offer to recover autosaved work."));
    const QCommandLineOption device_option(QStringLiteral("device"),
                                           QApplication::translate("main", "Embosser device string for Ctrl+P and --emboss, e.g. sim, serial:/dev/ttyUSB0, pty:/dev/pts/3 or a CUPS queue ipp://server/printers/Embosser."),
                                           QStringLiteral("device"));
    cli.addOptions({table, side, sheet, language, screenshot, panel_name, emboss_option, no_recovery, device_option});
    cli.process(app);

    const QLocale locale = cli.isSet(language) ? QLocale(cli.value(language)) : QLocale::system();
    QLocale::setDefault(locale);  // widgets name languages and format numbers in it
    QTranslator qt_translator, translator;
    if (qt_translator.load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                           QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(&qt_translator);
    // Without a translation for the language the English source strings are
    // shown, with their English plural forms ("1 sheet", not "1 sheet(s)").
    if (translator.load(locale, QStringLiteral("tactus"), QStringLiteral("_"), QStringLiteral(":/i18n")) ||
        translator.load(QStringLiteral("tactus_en"), QStringLiteral(":/i18n")))
        QApplication::installTranslator(&translator);

    install_accessibility();
    // SIGTERM and SIGINT (a session ending, a script) quit the event loop; the
    // window's destructor then stops its spool runner, so the job it was embossing
    // waits in the queue. No question is asked: nobody is there to answer.
    if (const auto notice = tactus::platform::termination_notice(); notice >= 0) {
        auto* quit_notifier = new QSocketNotifier(static_cast<qintptr>(notice), QSocketNotifier::Read, &app);
        QObject::connect(quit_notifier, &QSocketNotifier::activated, &app, [] { QApplication::quit(); });
    }
    MainWindow window;
    if (cli.isSet(device_option)) window.printer_panel()->select_device(cli.value(device_option));
    const bool shooting = cli.isSet(screenshot);
    window.set_interactive(!shooting);
    if (cli.isSet(table)) window.set_table(cli.value(table));
    window.show();

    auto* panel = window.preview_panel();
    const auto& panel_option = panel_name;
    const auto apply_view = [&] {
        const auto s = cli.value(side);
        if (s == QLatin1String("front")) panel->front_action()->trigger();
        else if (s == QLatin1String("back")) panel->back_action()->trigger();
        else if (s == QLatin1String("both")) panel->both_action()->trigger();
        if (cli.isSet(sheet)) panel->preview()->set_sheet(cli.value(sheet).toULongLong());
        if (cli.isSet(panel_option)) window.show_panel(cli.value(panel_option));
    };
    const auto shoot = [&] {
        if (!shooting) return;
        QTimer::singleShot(400, &window, [&] {
            const bool ok = window.grab().save(cli.value(screenshot));
            if (!ok) std::fprintf(stderr, "tactus: cannot write %s\n", qPrintable(cli.value(screenshot)));
            QApplication::exit(ok ? 0 : 1);
        });
    };
    // A picture is taken once the document is open and planned (the motion views need the plan).
    const bool embossing = cli.isSet(emboss_option);
    QObject::connect(&window, &MainWindow::opened, &window, [&] {
        apply_view();
        if (embossing && !window.emboss()) QApplication::exit(4);
    });
    QObject::connect(&window, &MainWindow::planned, &window, [&, shot = false]() mutable {
        if (shot || embossing) return;
        shot = true;
        apply_view();
        shoot();
    });
    // With --emboss the picture waits for the job (the printer panel has something to show).
    QObject::connect(&window, &MainWindow::job_finished, &window, [&] {
        if (embossing) shoot();
    });
    QObject::connect(&window, &MainWindow::failed, &window, [&](const QString& message) {
        std::fprintf(stderr, "tactus: %s\n", qPrintable(message));
        if (shooting) QApplication::exit(3);
    });
    const auto files = cli.positionalArguments();
    if (!files.isEmpty()) {
        window.open_file(files.front());
    } else {
        apply_view();
        if (!cli.isSet(no_recovery) && !shooting) QTimer::singleShot(0, &window, [&] { window.offer_recovery(); });
    }
    return QApplication::exec();
}
