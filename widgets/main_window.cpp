// SPDX-License-Identifier: GPL-3.0-or-later
#include "main_window.hpp"
#include "menu_bar_keys.hpp"
#include "message_label.hpp"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLineEdit>
#include <QHeaderView>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTableWidget>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>
#include <filesystem>

#include "announcer.hpp"
#include "book_progress.hpp"
#include "book_settings.hpp"
#include "book_view.hpp"
#include "ask.hpp"
#include "atomic_write.hpp"
#include "braille_pane.hpp"
#include "editor_widget.hpp"
#include "emboss_choice.hpp"
#include "edit/braille_carrier.hpp"
#include "edit/editor_lines.hpp"
#include "edit/editor_pictures.hpp"
#include "edit/print_word.hpp"
#include "export/export.hpp"
#include "export/text_export.hpp"
#include "import/import.hpp"
#include "import/picture_part.hpp"
#include "layout/braille_pages.hpp"
#include "profile/page_geometry.hpp"
#include "find_replace.hpp"
#include "focus_return.hpp"
#include "language_choice.hpp"
#include "motion_view.hpp"
#include "printer_panel.hpp"
#include "profile_editor.hpp"
#include "save_formats.hpp"
#include "vibration_view.hpp"
#include "preview_panel.hpp"
#include "sheet_geometry.hpp"
#include "status_label.hpp"
#include "system_look.hpp"
#include "table_picker.hpp"
#include "visible_focus.hpp"
#include "translate/catalogue.hpp"
#include "translate/script_check.hpp"

namespace tactus::gui {
namespace {

constexpr int kMaxRecent = 8;
constexpr std::size_t kSynchronousRelayoutLines = 3000;  // above: new tables re-lay off-thread

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName(QStringLiteral("mainWindow"));
    setAccessibleName(tr("Tactus"));
    setAcceptDrops(true);
    announcer_ = new Announcer(this);

    editor_ = new EditorWidget(this);
    setCentralWidget(editor_);
    auto empty = edit::LiveLayout::create(translate::kDefaultTable, {});
    if (empty) editor_->adopt(std::move(*empty));

    preview_ = new PreviewPanel(this);
    add_dock(tr("Preview"), QStringLiteral("previewDock"), preview_, Qt::RightDockWidgetArea);
    motion_ = new MotionView(this);
    vibration_ = new VibrationView(this);
    profile_ = new ProfileEditor(this);
    // The technicians' views share the right-hand area with the preview, as tabs:
    // a teacher sees print, braille and the sheet; one key brings up the others.
    auto* preview_dock = findChild<QDockWidget*>(QStringLiteral("previewDock"));
    auto* motion_dock = add_dock(tr("Motion"), QStringLiteral("motionDock"), motion_, Qt::RightDockWidgetArea);
    auto* vibration_dock = add_dock(tr("Vibration"), QStringLiteral("vibrationDock"), vibration_, Qt::RightDockWidgetArea);
    auto* profile_dock = add_dock(tr("Printer profile"), QStringLiteral("profileDock"), profile_, Qt::RightDockWidgetArea);
    tabifyDockWidget(preview_dock, motion_dock);
    tabifyDockWidget(motion_dock, vibration_dock);
    tabifyDockWidget(vibration_dock, profile_dock);
    printer_ = new PrinterPanel(this);
    auto* printer_dock = add_dock(tr("Printer"), QStringLiteral("printerDock"), printer_, Qt::RightDockWidgetArea);
    tabifyDockWidget(profile_dock, printer_dock);
    connect(printer_, &PrinterPanel::message, this, [this](const QString& m, bool) { report(m, false); });
    connect(printer_, &PrinterPanel::job_finished, this,
            [this](qint64, bool completed, const QString& text) { Q_EMIT job_finished(completed, text); });
    // Connect configures the controller with the profile being edited, as the jobs are planned.
    printer_->set_profile_source([this] { return profile_->profile(); });
    preview_dock->raise();
    plan_timer_.setSingleShot(true);
    plan_timer_.setInterval(700);  // plan after a pause in typing, not on every key
    connect(&plan_timer_, &QTimer::timeout, this, &MainWindow::start_plan);
    connect(profile_, &ProfileEditor::profile_changed, this, [this](const profile::PrinterProfile& p) {
        // The document is laid out for the machine's page, as tactus-cli lays it out for a profile.
        if (editor_->has_layout()) {
            auto options = editor_->layout().options();
            if (const auto page = profile::page_geometry(p); options.geometry != page) {
                options.geometry = page;
                if (auto ok = editor_->set_layout_options(options); !ok)
                    report(tr("The document cannot be laid out for this printer's page: %1")
                               .arg(QString::fromStdString(ok.error().to_string())),
                           true);
            }
        }
        preview_->preview()->set_geometry(sheet_geometry(p));
        if (graphic_) lay_out_graphic_again();
        vibration_->set_profile(p);
        schedule_plan();
    });
    // Profile problems are spoken and shown in the status bar, not in a box: the technician is typing.
    connect(profile_, &ProfileEditor::message, this, [this](const QString& m, bool) { report(m, false); });

    tables_ = new TablePicker(this);
    auto* bar = addToolBar(tr("Braille"));
    bar->setObjectName(QStringLiteral("brailleBar"));
    bar->setAccessibleName(tr("Braille toolbar"));
    auto* label = new QLabel(tr("&Table:"), this);
    label->setBuddy(tables_);
    bar->addWidget(label);
    bar->addWidget(tables_);

    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("positionLabel"));
    expose_status(status_, tr("Position"));
    message_ = new MessageLabel(this);
    statusBar()->addWidget(message_, 1);
    statusBar()->addPermanentWidget(status_);
    statusBar()->setSizeGripEnabled(false);  // a grip has no accessible role; the window manager resizes
    statusBar()->setAccessibleName(tr("Status"));

    find_ = new FindReplaceDialog(editor_->print_pane(), this);
    connect(find_, &FindReplaceDialog::message, this, [this](const QString& m) { report(m); });

    auto* sp = preview_->preview();
    // A book (an EPUB, a long text) is previewed and embossed in its book layout.
    book_ = new BookView(this);
    book_->set_source([this] { return editor_->has_layout() ? &editor_->layout() : nullptr; },
                      [this] { return source_name_; });
    preview_->set_book(book_);
    book_progress_ = new BookProgress(book_, announcer_, [this](const QString& said) {
        // The end of a book's layout swaps the preview's pages: the same burst of events as an open's end.
        const bool was = std::exchange(word_after_burst_, true);
        report(said);
        word_after_burst_ = was;
    }, this);
    statusBar()->addPermanentWidget(book_progress_);
    connect(preview_, &PreviewPanel::announce, announcer_, &Announcer::announce);
    connect(book_, &BookView::changed, this, [this, sp] {
        const auto* shown = book_->shown(&paged());
        sp->set_document(shown);
        printer_->emboss_choice()->set_pages(book_->labels(), book_->volumes(), shown->geometry);
    });
    sp->set_back_translator([this](const document::BrailleLine& cells) {
        return editor_->has_layout() ? QString::fromStdString(editor_->layout().back_translate(cells)) : QString{};
    });
    sp->set_print_word([this](std::size_t page, int line, int cell) {
        // The editor's print words are on its own pages, not a book's.
        return editor_->has_layout() && !book_->active()
                   ? QString::fromStdU32String(edit::print_word_at(editor_->layout(), edit::PagePosition{page, line, cell}))
                   : QString{};
    });
    connect(editor_, &EditorWidget::layout_changed, this, [this, sp] {
        lay_out_pictures();
        sp->set_document(book_->shown(&paged()));
        book_->schedule();
        update_status();
        schedule_plan();
        tell_pages_kept();
    });
    connect(editor_, &EditorWidget::position_changed, this, [this, sp](const edit::PagePosition& p) {
        if (!sp->hasFocus() && !book_->active()) sp->show_position(p.page, p.line, p.cell);
        update_status();
    });
    connect(editor_, &EditorWidget::cell_entered, announcer_, &Announcer::announce);
    connect(editor_, &EditorWidget::page_break_reached, this, [this](const QString& spoken) {
        if (editor_->print_pane()->hasFocus()) announcer_->announce(spoken);
    });
    connect(editor_, &EditorWidget::structure_reached, this, [this](const QString& spoken) {
        if (editor_->print_pane()->hasFocus()) announcer_->announce(spoken);
    });
    connect(sp, &SheetPreview::cursor_moved, this, [this, sp](const QString& text) {
        if (sp->hasFocus()) announcer_->announce(text);
    });
    connect(preview_, &PreviewPanel::print_pdf_requested, this, &MainWindow::print_pdf_dialog);
    connect(editor_, &EditorWidget::files_dropped, this, [this](const QStringList& paths) {
        if (!paths.isEmpty() && maybe_save()) open_file(paths.front());
    });
    connect(tables_, &TablePicker::table_chosen, this, &MainWindow::set_table);
    connect(editor_->undo_stack(), &QUndoStack::cleanChanged, this, &MainWindow::update_title);

    build_actions();
    build_format_actions();
    build_menus();
    restore_settings();
    apply_system_look(*preview_);
    sp->set_document(&paged());
    book_->refresh_now();

    connect(&autosave_, &Autosave::due, this, [this] {
        if (!editor_->undo_stack()->isClean()) autosave_now();
    });
    autosave_.start();
    update_title();
    update_status();
}

MainWindow::~MainWindow() = default;

void MainWindow::build_actions() {
    const auto make = [this](const QString& text, const QKeySequence& key, const QString& name, auto slot) {
        auto* a = new QAction(text, this);
        a->setShortcut(key);
        a->setObjectName(name);
        a->setStatusTip(QString(text).remove(QLatin1Char('&')).remove(QStringLiteral("...")));
        connect(a, &QAction::triggered, this, slot);
        addAction(a);
        return a;
    };
    new_ = make(tr("&New"), QKeySequence::New, QStringLiteral("fileNew"), [this] {
        if (maybe_save()) new_document();
    });
    open_ = make(tr("&Open or Import..."), QKeySequence::Open, QStringLiteral("fileOpen"), [this] { open_dialog(); });
    save_ = make(tr("&Save"), QKeySequence::Save, QStringLiteral("fileSave"), [this] { save(); });
    save_as_ = make(tr("Save &As..."), QKeySequence(tr("Ctrl+Shift+S")), QStringLiteral("fileSaveAs"), [this] { save_as(); });
    export_brf_ = make(tr("Export &BRF..."), QKeySequence(tr("Ctrl+E")), QStringLiteral("exportBrf"),
                       [this] { export_dialog(QStringLiteral("brf")); });
    export_pef_ = make(tr("Export &PEF..."), QKeySequence(tr("Ctrl+Shift+E")), QStringLiteral("exportPef"),
                       [this] { export_dialog(QStringLiteral("pef")); });
    book_settings_ = make(tr("Boo&k Settings..."), QKeySequence(tr("Ctrl+Shift+K")), QStringLiteral("fileBookSettings"),
                          [this] { book_settings(); });
    insert_graphic_ = make(tr("Gr&aphic..."), QKeySequence(tr("Ctrl+Alt+I")), QStringLiteral("insertGraphic"),
                           [this] { insert_graphic_dialog(); });
    pictures_as_graphics_ = make(tr("Emboss Pictures as &Graphics"), QKeySequence(tr("Ctrl+Shift+G")),
                                 QStringLiteral("filePicturesAsGraphics"), [this](bool on) {
                                     set_picture_choice(on ? PictureChoice::graphics : PictureChoice::descriptions);
                                 });
    pictures_as_graphics_->setCheckable(true);
    quit_ = make(tr("&Quit"), QKeySequence(tr("Ctrl+Q")), QStringLiteral("fileQuit"), [this] { close(); });
    undo_ = editor_->undo_stack()->createUndoAction(this, tr("&Undo"));
    undo_->setShortcut(QKeySequence::Undo);
    undo_->setObjectName(QStringLiteral("editUndo"));
    redo_ = editor_->undo_stack()->createRedoAction(this, tr("&Redo"));
    redo_->setShortcut(QKeySequence::Redo);
    redo_->setObjectName(QStringLiteral("editRedo"));
    // The text comes back without a word from the screen reader: say what was undone.
    connect(undo_, &QAction::triggered, this,
            [this] { announcer_->announce(tr("Undone: %1").arg(editor_->undo_stack()->redoText())); });
    connect(redo_, &QAction::triggered, this,
            [this] { announcer_->announce(tr("Redone: %1").arg(editor_->undo_stack()->undoText())); });
    addActions({undo_, redo_});
    find_action_ = make(tr("&Find and Replace..."), QKeySequence::Find, QStringLiteral("editFind"), [this] {
        find_->set_find_text(editor_->print_pane()->textCursor().selectedText());
        find_->show();
        find_->raise();
        find_->activateWindow();
    });
    find_next_ = make(tr("Find &Next"), QKeySequence::FindNext, QStringLiteral("editFindNext"),
                      [this] { find_->find_next(); });
    focus_print_ = make(tr("Go to &print text"), QKeySequence(tr("Ctrl+1")), QStringLiteral("focusPrint"),
                        [this] { editor_->print_pane()->setFocus(Qt::ShortcutFocusReason); });
    focus_braille_ = make(tr("Go to &braille"), QKeySequence(tr("Ctrl+2")), QStringLiteral("focusBraille"),
                          [this] { editor_->braille_pane()->setFocus(Qt::ShortcutFocusReason); });
    focus_preview_ = make(tr("Go to pre&view"), QKeySequence(tr("Ctrl+3")), QStringLiteral("focusPreview"),
                          [this] {
                              show_panel(QStringLiteral("preview"));
                              preview_->preview()->setFocus(Qt::ShortcutFocusReason);
                          });
    focus_table_ = make(tr("Choose braille &table"), QKeySequence(tr("Ctrl+T")), QStringLiteral("focusTable"), [this] {
        tables_->setFocus(Qt::ShortcutFocusReason);
        tables_->showPopup();
    });
    focus_motion_ = make(tr("Go to &motion"), QKeySequence(tr("Ctrl+4")), QStringLiteral("focusMotion"), [this] {
        show_panel(QStringLiteral("motion"));
        if (auto* first = motion_->findChild<QSpinBox*>()) first->setFocus(Qt::ShortcutFocusReason);
    });
    focus_vibration_ = make(tr("Go to vibratio&n"), QKeySequence(tr("Ctrl+5")), QStringLiteral("focusVibration"), [this] {
        show_panel(QStringLiteral("vibration"));
        vibration_->metrics()->setFocus(Qt::ShortcutFocusReason);
    });
    focus_profile_ = make(tr("Go to printer pro&file"), QKeySequence(tr("Ctrl+6")), QStringLiteral("focusProfile"), [this] {
        show_panel(QStringLiteral("profile"));
        profile_->field(QStringLiteral("paper.width_mm"))->setFocus(Qt::ShortcutFocusReason);
    });
    focus_printer_ = make(tr("Go to p&rinter"), QKeySequence(tr("Ctrl+7")), QStringLiteral("focusPrinter"), [this] {
        show_panel(QStringLiteral("printer"));
        printer_->setFocus(Qt::ShortcutFocusReason);
        if (auto* first = printer_->findChild<QComboBox*>()) first->setFocus(Qt::ShortcutFocusReason);
    });
    emboss_ = make(tr("&Emboss"), QKeySequence(tr("Ctrl+P")), QStringLiteral("fileEmboss"), [this] { emboss(); });
    shortcuts_ = make(tr("&Keyboard Shortcuts"), QKeySequence(tr("Ctrl+F1")), QStringLiteral("helpShortcuts"),
                      [this] { show_shortcuts(); });
    about_ = make(tr("&About Tactus"), QKeySequence(tr("Shift+F1")), QStringLiteral("helpAbout"), [this] { show_about(); });
    for (auto* a : preview_->view_actions()) addAction(a);
    // F10 opens the menu bar, as in GTK and Windows applications (Qt has no such key).
    menus_ = make(tr("Open the menu bar"), QKeySequence(Qt::Key_F10), QStringLiteral("openMenus"), [this] {
        if (!menuBar()->actions().isEmpty()) menuBar()->setActiveAction(menuBar()->actions().front());
    });
}

void MainWindow::build_format_actions() {
    const auto make = [this](const QString& text, const QString& key, const QString& name, auto slot) {
        auto* a = new QAction(text, this);
        a->setShortcut(QKeySequence(key));
        a->setObjectName(name);
        a->setStatusTip(QString(text).remove(QLatin1Char('&')));
        // Only while the print text has the focus: the braille pane's keys are its own.
        a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        connect(a, &QAction::triggered, this, slot);
        format_actions_ << a;
        return a;
    };
    using Style = EditorWidget::ParagraphStyle;
    make(tr("&Body text"), tr("Ctrl+Alt+0"), QStringLiteral("formatBody"),
         [this] { editor_->set_paragraph_style(Style::body); });
    for (int level = 1; level <= 6; ++level)
        make(tr("Heading &%1").arg(level), tr("Ctrl+Alt+%1").arg(level), QStringLiteral("formatHeading%1").arg(level),
             [this, level] { editor_->set_paragraph_style(Style::heading, level); });
    make(tr("B&ulleted list"), tr("Ctrl+Alt+L"), QStringLiteral("formatBulleted"),
         [this] { editor_->set_paragraph_style(Style::bulleted); });
    make(tr("&Numbered list"), tr("Ctrl+Alt+N"), QStringLiteral("formatNumbered"),
         [this] { editor_->set_paragraph_style(Style::numbered); });
    make(tr("&Quotation"), tr("Ctrl+Alt+Q"), QStringLiteral("formatQuotation"),
         [this] { editor_->set_paragraph_style(Style::quotation); });
    make(tr("&Page break"), tr("Ctrl+Return"), QStringLiteral("formatPageBreak"), [this] { editor_->insert_page_break(); });
    make(tr("Bol&d"), tr("Ctrl+B"), QStringLiteral("formatBold"),
         [this] { editor_->toggle_emphasis(document::emphasis_bold); });
    make(tr("&Italic"), tr("Ctrl+I"), QStringLiteral("formatItalic"),
         [this] { editor_->toggle_emphasis(document::emphasis_italic); });
    make(tr("Und&erline"), tr("Ctrl+U"), QStringLiteral("formatUnderline"),
         [this] { editor_->toggle_emphasis(document::emphasis_underline); });
    make(tr("&Raised"), tr("Ctrl+Shift+P"), QStringLiteral("formatRaised"),
         [this] { editor_->toggle_position(document::Position::superscript); });
    make(tr("&Lowered"), tr("Ctrl+Shift+B"), QStringLiteral("formatLowered"),
         [this] { editor_->toggle_position(document::Position::subscript); });
    make(tr("Lan&guage..."), tr("Ctrl+Alt+G"), QStringLiteral("formatLanguage"), [this] {
        if (!editor_->structured()) return;
        std::optional<LanguageChoice> choice;
        {
            FocusReturn back(this, editor_->print_pane());
            choice = ask_language(this, editor_->language_at_cursor());
        }
        if (!choice) return;
        editor_->set_language(choice->tag, choice->paragraph);
        report(language_set_text(choice->tag));
    });
    make(tr("Bo&x"), tr("Ctrl+Alt+X"), QStringLiteral("formatBox"), [this] { editor_->toggle_box(); });
    make(tr("No&te"), tr("Ctrl+Alt+E"), QStringLiteral("formatNote"), [this] {
        if (const auto reference = editor_->insert_note(); !reference.isEmpty())
            report(tr("Note %1: type its text").arg(reference));
    });
    show_codes_ = new QAction(tr("Show &codes"), this);
    show_codes_->setObjectName(QStringLiteral("viewShowCodes"));
    show_codes_->setCheckable(true);
    show_codes_->setShortcut(QKeySequence(tr("Ctrl+Alt+C")));
    show_codes_->setStatusTip(tr("Show the print text's Markdown codes instead of its styles"));
    connect(show_codes_, &QAction::toggled, this, [this](bool on) {
        editor_->set_codes_shown(on);
        for (auto* a : format_actions_) a->setEnabled(!on);
    });
    addAction(show_codes_);
}

void MainWindow::build_menus() {
    keep_lone_alt_out_of_menus(menuBar());
    auto* file = menuBar()->addMenu(tr("&File"));
    file->addActions({new_, open_});
    recent_menu_ = file->addMenu(tr("Open &Recent"));
    recent_menu_->setObjectName(QStringLiteral("recentMenu"));
    file->addSeparator();
    file->addActions({save_, save_as_, export_brf_, export_pef_, preview_->pdf_action()});
    file->addSeparator();
    file->addActions({book_settings_, pictures_as_graphics_});
    if (emboss_) file->addAction(emboss_);
    file->addSeparator();
    file->addAction(quit_);
    auto* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addActions({undo_, redo_});
    edit->addSeparator();
    edit->addActions({find_action_, find_next_});
    editor_->print_pane()->addActions({undo_, redo_, find_action_});
    auto* format = menuBar()->addMenu(tr("St&yles"));
    format->addActions(format_actions_);
    editor_->print_pane()->addActions(format_actions_);
    format->addSeparator();
    format->addAction(insert_graphic_);
    auto* view = menuBar()->addMenu(tr("&View"));
    view->addAction(show_codes_);
    view->addSeparator();
    view->addActions({focus_print_, focus_braille_, focus_preview_, focus_table_, focus_motion_, focus_vibration_,
                      focus_profile_});
    if (focus_printer_) view->addAction(focus_printer_);
    view->addSeparator();
    for (auto* a : preview_->view_actions())
        if (a != preview_->pdf_action()) view->addAction(a);
    auto* help = menuBar()->addMenu(tr("&Help"));
    help->addActions({shortcuts_, about_});
    update_recent_menu();
}

QList<QAction*> MainWindow::all_actions() const {
    QList<QAction*> out;
    for (auto* a : actions())
        if (!a->text().isEmpty()) out << a;
    out << format_actions_;
    return out;
}

void MainWindow::restore_settings() {
    QSettings s;
    book_->keep_options(load_book_rules(s));
    picture_choice_ = picture_choice_named(s.value(QStringLiteral("layout/images")).toString());
    pictures_as_graphics_->setChecked(picture_choice_ == PictureChoice::graphics);
    resize(1280, 800);
    resizeDocks({findChild<QDockWidget*>(QStringLiteral("previewDock"))}, {700}, Qt::Horizontal);
    restoreGeometry(s.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(s.value(QStringLiteral("window/state")).toByteArray());
    // Six-key entry: the keys for dots 1 to 6, e.g. "FDSJKL" (the default).
    const auto keys = s.value(QStringLiteral("braille/six_keys")).toString();
    if (keys.size() == 6) {
        SixKeyChord::Mapping m{};
        bool ok = true;
        for (int i = 0; i < 6; ++i) {
            const QKeySequence k(QString(keys[i]));
            ok = ok && !k.isEmpty();
            if (ok) m[static_cast<std::size_t>(i)] = k[0].key();
        }
        if (ok) editor_->braille_pane()->chord().set_mapping(m);
    }
    const auto table = s.value(QStringLiteral("braille/table"), QString::fromLatin1(translate::kDefaultTable)).toString();
    if (table != QString::fromStdString(editor_->layout().tables())) set_table(table);
}

void MainWindow::set_table(const QString& table) {
    tables_->set_table(table);
    if (!editor_->has_layout() || table.toStdString() == editor_->layout().tables()) return;
    QSettings().setValue(QStringLiteral("braille/table"), table);
    if (editor_->layout().line_count() > kSynchronousRelayoutLines) {
        std::vector<std::string> lines;
        for (std::size_t i = 0; i < editor_->layout().line_count(); ++i) lines.push_back(editor_->layout().line(i));
        start_busy(tr("Translating with %1").arg(tables_->currentText()),
                   lay_out_lines(std::move(lines), table.toStdString(), editor_->layout().options(),
                                 editor_->layout().dialect(), editor_->layout().braille_structure()),
                   false);
        return;
    }
    if (auto ok = editor_->set_tables(table.toStdString()); !ok) {
        report(tr("Cannot use table %1: %2").arg(table, QString::fromStdString(ok.error().to_string())), true);
        return;
    }
    if (graphic_) lay_out_graphic_again();  // its labels are in the table's braille
    const auto& warnings = editor_->layout().paged().warnings;
    report(tr("Braille table: %1").arg(tables_->currentText()) +
           (warnings.empty() ? QString() : QLatin1Char(' ') + table_warning(QString::fromStdString(warnings.front()))));
}

QString MainWindow::table_warning(const QString& detail) const {
    // The core words a script mismatch for the command line (with --table); here
    // it is a sentence in the interface's language.
    QString said = detail;
    if (const auto m = translate::find_script_mismatch(editor_->layout().document(), editor_->layout().tables())) {
        const auto better = QString::fromStdString(m->better);
        said = !m->chinese_text ? tr("the text is mostly in Latin letters; for English, Unified English Braille (%1) suits it")
                                      .arg(better)
               : m->traditional ? tr("the text is mostly Traditional Chinese; Taiwanese bopomofo braille (%1) suits it").arg(better)
                                : tr("the text is mostly Simplified Chinese; Chinese double-phonic braille (%1) suits it")
                                      .arg(better);
    }
    return tr("Warning: the table %1 does not suit all of this text (%2). Ctrl+T chooses another table.")
        .arg(tables_->currentText(), said);
}

const layout::PagedDocument& MainWindow::paged() const {
    if (graphic_) return graphic_->paged;
    return pictured_ ? *pictured_ : editor_->layout().paged();
}

void MainWindow::lay_out_pictures() {
    pictured_.reset();
    if (picture_choice_ != PictureChoice::graphics || graphic_ || !editor_->has_layout()) return;
    auto laid = lay_out_with_pictures(editor_->layout(), profile_->profile());
    if (!laid) return;  // no picture: the editor's pages
    if (!*laid) {
        report(tr("Pictures not embossed as graphics: %1").arg(QString::fromStdString(laid->error().to_string())), true);
        return;
    }
    pictured_ = std::move(**laid);
}

void MainWindow::set_picture_choice(PictureChoice choice) {
    picture_choice_ = choice;
    QSettings().setValue(QStringLiteral("layout/images"), picture_choice_name(choice));
    if (pictures_as_graphics_) {
        const QSignalBlocker quiet(pictures_as_graphics_);
        pictures_as_graphics_->setChecked(choice == PictureChoice::graphics);
    }
    lay_out_pictures();
    preview_->preview()->set_document(book_->shown(&paged()));
    update_status();
    schedule_plan();
    report(choice == PictureChoice::graphics ? tr("Pictures are embossed as graphics, each after its description")
                                             : tr("Pictures are embossed as their descriptions only"));
}

void MainWindow::insert_graphic_dialog() {
    if (graphic_) return;
    FocusReturn back(this, editor_->print_pane());
    const auto path = QFileDialog::getOpenFileName(this, tr("Insert graphic"), {},
                                                   tr("Pictures (*.svg *.png *.jpg *.jpeg)"));
    if (path.isEmpty()) return;
    bool ok = false;
    const auto description =
        QInputDialog::getText(this, tr("Insert graphic"),
                              tr("Description of %1 (what a reader who cannot see it needs to know):")
                                  .arg(QFileInfo(path).fileName()),
                              QLineEdit::Normal, {}, &ok);
    if (!ok) return;
    insert_graphic(path, description);
}

bool MainWindow::insert_graphic(const QString& path, const QString& description) {
    const QFileInfo info(path);
    const auto text = description.simplified();
    // A picture's description is what the braille reader gets of it: it is required.
    if (text.isEmpty()) {
        report(tr("Not inserted: %1 needs a description, which is what a braille reader reads of it")
                   .arg(info.fileName()),
               true);
        return false;
    }
    // The importers' rule for a picture a document names: PNG, JPEG or SVG.
    std::string why;
    auto image = import::detail::picture_file(info.absolutePath().toStdString(), info.fileName().toStdString(), why);
    if (!image) {
        report(tr("Cannot insert %1: %2").arg(info.fileName(), QString::fromStdString(why)), true);
        return false;
    }
    if (graphic_ || !editor_->insert_picture(std::move(*image), text)) {
        report(tr("Cannot insert %1: only a document (not a text file or a graphic) holds pictures").arg(info.fileName()),
               true);
        return false;
    }
    report(tr("Graphic %1 inserted: %2").arg(info.fileName(), text));
    return true;
}

void MainWindow::show_graphic(std::optional<GraphicView> graphic, const QString& path) {
    graphic_ = std::move(graphic);
    graphic_path_ = graphic_ ? path : QString();
    auto* sp = preview_->preview();
    sp->set_graphic_summary(graphic_ ? graphic_->summary() : QString());
    editor_->print_pane()->set_graphic(graphic_.has_value());
    sp->set_document(&paged());
    if (!graphic_) editor_->print_pane()->setReadOnly(false);
}

void MainWindow::lay_out_graphic_again() {
    auto r = load_file_now(graphic_path_, editor_->layout().tables(), editor_->layout().options(), profile_->profile());
    if (!r->graphic || !r->layout) {
        report(tr("Cannot lay out %1 again: %2")
                   .arg(QDir::toNativeSeparators(graphic_path_),
                        r->error ? QString::fromStdString(r->error->to_string()) : tr("cancelled")),
               true);
        return;
    }
    show_graphic(std::move(r->graphic), r->path);
    editor_->adopt(std::move(*r->layout));
    editor_->print_pane()->setReadOnly(true);
    schedule_plan();
}

void MainWindow::new_document() {
    auto layout = edit::LiveLayout::create(editor_->layout().tables(), editor_->layout().options());
    if (!layout) return;
    autosave_.remove();
    show_graphic(std::nullopt, {});
    editor_->adopt(std::move(*layout));
    path_.clear();
    update_title();
}

void MainWindow::open_dialog() {
    if (!maybe_save()) return;
    FocusReturn back(this, editor_->print_pane());
    const auto path = QFileDialog::getOpenFileName(
        this, tr("Open or import"), QFileInfo(path_).absolutePath(),
        tr("Documents (*.md *.markdown *.txt *.docx *.odt *.brf *.pef *.svg *.png *.jpg *.jpeg);;"
           "Tactile graphics (*.svg *.png *.jpg *.jpeg);;All files (*)"));
    if (!path.isEmpty()) open_file(path);
}

void MainWindow::open_file(const QString& path) {
    if (busy_) return;
    start_busy(tr("Opening %1").arg(QFileInfo(path).fileName()),
               load_file(path, editor_->layout().tables(), editor_->layout().options(), profile_->profile()), true);
}

bool MainWindow::open_file_now(const QString& path) {
    auto r = load_file_now(path, editor_->layout().tables(), editor_->layout().options(), profile_->profile());
    finish_load(r, true);
    return r->layout.has_value() || (!r->error && !r->cancelled);
}

void MainWindow::start_busy(const QString& what, QFuture<LoadResultPtr> future, bool replace_text) {
    auto* watcher = new QFutureWatcher<LoadResultPtr>(this);
    busy_ = watcher;
    busy_return_ = std::make_shared<FocusReturn>(this, editor_->print_pane());
    editor_->print_pane()->setReadOnly(true);  // edits during a re-layout would be lost
    progress_ = new QProgressDialog(what, tr("Cancel"), 0, 100, this);
    progress_->setObjectName(QStringLiteral("progress"));
    progress_->setAccessibleName(what);
    progress_->setWindowModality(Qt::WindowModal);
    progress_->setMinimumDuration(progress_delay_);
    connect(progress_, &QProgressDialog::canceled, watcher, [watcher] { watcher->cancel(); });
    connect(watcher, &QFutureWatcher<LoadResultPtr>::progressValueChanged, progress_, [this, watcher](int v) {
        // Said before the bar moves: setValue() on a shown modal dialog runs
        // the event loop, where the job's end may be handled ("Opened ...");
        // a step said after it replaced that message before the screen reader
        // read it, and the user heard "100 percent" and never that the
        // document was open. The start and the end have their own messages.
        if (v % 25 == 0 && v > 0 && v < 100) announcer_->announce(tr("%1 percent").arg(v));
        if (busy_ == watcher && progress_) progress_->setValue(v);
    });
    connect(watcher, &QFutureWatcher<LoadResultPtr>::finished, this, [this, watcher, replace_text] {
        LoadResultPtr r;
        if (watcher->future().resultCount() > 0) r = watcher->future().result();
        if (!r) {
            r = std::make_shared<LoadResult>();
            r->cancelled = true;
        }
        // Hidden before it goes: a modal dialog deleted while shown left the
        // main window inactive under a window manager, and Orca silent.
        progress_->reset();
        progress_->hide();
        progress_->deleteLater();
        progress_ = nullptr;
        busy_ = nullptr;
        watcher->deleteLater();
        editor_->print_pane()->setReadOnly(false);
        if (auto back = std::exchange(busy_return_, nullptr)) back->restore();
        word_after_burst_ = true;
        finish_load(r, replace_text);
        word_after_burst_ = false;
    });
    announcer_->announce(what);
    watcher->setFuture(future);
}

void MainWindow::finish_load(const LoadResultPtr& r, bool replace_text) {
    if (r->cancelled || (!r->layout && !r->error)) {
        report(tr("Cancelled; the document is unchanged"));
        return;
    }
    if (r->error) {
        const auto where = QString::fromStdString(r->error->where);
        report(tr("Cannot open %1: %2")
                   .arg(QDir::toNativeSeparators(r->path.isEmpty() ? tr("the document") : r->path),
                        QString::fromStdString(r->error->to_string())),
               true);
        Q_EMIT failed(QString::fromStdString(r->error->to_string()));
        return;
    }
    if (replace_text) {
        autosave_.remove();
        show_graphic(std::move(r->graphic), r->path);
        editor_->adopt(std::move(*r->layout));
        editor_->print_pane()->setReadOnly(graphic_.has_value());  // what the graphic is, not text to edit
        pages_kept_ = editor_->layout().pages_kept();
        const QFileInfo info(r->path);
        // Saved in place when Tactus writes the format (Markdown, text, DOCX, ODT), else "Save as".
        path_ = saved_in_place(info.filePath()) ? info.absoluteFilePath() : QString();
        source_name_ = info.fileName();
        book_progress_->forget_opened();
        // The title page's lines typed for the document before are not this one's.
        book_->keep_options(without_title_lines(book_->options()));
        book_->start();  // now, not after the edits' pause: and no other document's book meanwhile
        add_recent(info.absoluteFilePath());
        update_title();
        const auto& paged = this->paged();
        // One message: a second one would cut the first off in the screen reader.
        auto said = tr("Opened %1: %n sheet(s)", nullptr, static_cast<int>(paged.sheet_count())).arg(info.fileName());
        QString suffix;
        if (graphic_) {
            said = tr("%1. %2", "a message, then what the graphic is")
                       .arg(said, graphic_->summary().replace(QLatin1Char('\n'), QLatin1Char(' ')));
            if (!paged.warnings.empty())
                suffix = QLatin1Char(' ') + tr("Warning: %1").arg(QString::fromStdString(paged.warnings.front()));
        } else if (!paged.warnings.empty())
            suffix = QLatin1Char(' ') + table_warning(QString::fromStdString(paged.warnings.front()));
        // A book is said open when its book layout is ready, with its count.
        if (book_->running())
            book_progress_->opened(info.fileName(), said, suffix);
        else
            report(said + suffix);
        if (editor_->layout().error_count() > 0)
            report(tr("%n line(s) could not be translated; they are left out of the braille", nullptr,
                      static_cast<int>(editor_->layout().error_count())),
                   true);
        Q_EMIT opened(r->path);
    } else {
        editor_->swap_layout(std::move(*r->layout));
        report(tr("Braille table: %1").arg(tables_->currentText()));
    }
}

void MainWindow::tell_pages_kept() {
    if (!editor_->has_layout()) return;
    const auto& layout = editor_->layout();
    const bool kept = layout.pages_kept();
    if (kept == pages_kept_) return;
    pages_kept_ = kept;
    if (!layout.ready_braille()) return;  // a new document, a table's change: said elsewhere
    // Spoken and shown once, at the edit that changed it (what to do about it is in docs/gui.md).
    report(kept ? tr("The braille's own pages, sections and volumes are kept again")
                : tr("The braille is laid out again on the printer's page: its own pages, sections and volumes are "
                     "kept only while it holds nothing but braille rows that fit the page"));
}

QString MainWindow::status_text() const {
    if (!editor_->has_layout()) return {};
    const auto& layout = editor_->layout();
    if (graphic_)
        return tr("Graphic %1 | %n sheet(s)", nullptr, static_cast<int>(std::max<std::size_t>(1, graphic_->paged.sheet_count())))
            .arg(graphic_->title);
    const auto& paged = layout.paged();
    const auto pos = editor_->current_position();
    const bool interpoint = paged.geometry.interpoint;
    const auto sheet = paged.geometry.sheet_of_page(pos.page);
    auto print_page = QString::fromStdString(layout.print_page_at(static_cast<std::size_t>(editor_->current_line())));
    if (print_page.isEmpty()) print_page = QStringLiteral("-");
    auto text = tr("Sheet %1 of %2%3 | line %4 | cell %5 | print page %6")
                    .arg(sheet)
                    .arg(std::max<std::size_t>(1, paged.sheet_count()))
                    .arg(interpoint ? (paged.geometry.page_is_back(pos.page) ? tr(", back") : tr(", front")) : QString())
                    .arg(pos.line + 1)
                    .arg(pos.cell + 1)
                    .arg(print_page);
    // A passage marked in another language says so where the cursor is.
    if (const auto language = language_status(editor_->language_at_cursor()); !language.isEmpty())
        text += QStringLiteral(" | ") + language;
    return text;
}

void MainWindow::update_status() {
    if (const auto text = status_text(); status_->text() != text) status_->setText(text);
}

void MainWindow::update_title() {
    const auto name = !source_name_.isEmpty() ? source_name_ : tr("Untitled");
    setWindowTitle(QStringLiteral("%1[*] \u2014 Tactus").arg(name));
    setWindowModified(!editor_->undo_stack()->isClean());
    // The frame's name is what a screen reader says on coming back to the window:
    // the document's name, not only the program's.
    setAccessibleName(tr("%1 \u2014 Tactus").arg(name));
}

void MainWindow::report(const QString& message, bool error) {
    message_->show_message(message, 10000);
    if (word_after_burst_) {
        // The end of background work swaps the document: the dialog goes, the
        // focus comes back, the panes, preview and choosers change, dozens of
        // AT-SPI events at once. Orca 43, when more than 50 events wait in
        // its queue (it falls seconds behind on a loaded machine), drops
        // every name change and "showing" event in it: the announcer's
        // message went with them and "Opened ..." was never heard. Said once
        // the burst is out, and Orca has had time to work through it (at
        // 10-20 events a second when loaded), it arrives in a short queue.
        QTimer::singleShot(kWordAfterBurstMs, announcer_, [a = announcer_, message] { a->announce(message); });
    } else {
        announcer_->announce(message);
    }
    if (error && interactive_ && isVisible()) {
        FocusReturn back(this, editor_->print_pane());
        QMessageBox::warning(this, tr("Tactus"), message);
    }
}

bool MainWindow::save() { return path_.isEmpty() ? save_as() : save_to(path_); }

bool MainWindow::refuse_saving_graphic() {
    if (!graphic_) return false;
    // The print pane holds what the graphic is, not a document: written as
    // Markdown it would replace a drawing (or stand beside it) as text nobody wants.
    report(tr("Cannot save %1: a tactile graphic is kept in its own file; emboss or plan it, or open a document to save")
               .arg(QFileInfo(graphic_path_).fileName()),
           true);
    return true;
}

bool MainWindow::save_as() {
    if (refuse_saving_graphic()) return false;
    auto suggested = path_;
    if (suggested.isEmpty() && !source_name_.isEmpty())
        suggested = QFileInfo(source_name_).completeBaseName() + QStringLiteral(".md");
    FocusReturn back(this, editor_->print_pane());
    QString filter = save_as_filter_for(suggested);
    auto path = QFileDialog::getSaveFileName(this, tr("Save as"), suggested, save_as_filters().join(QStringLiteral(";;")),
                                             &filter);
    if (path.isEmpty()) return false;
    path = with_filter_suffix(path, filter);
    // Braille is exported from the pages; the document keeps its own file.
    return is_braille_export(path) ? export_to(path) : save_to(path);
}

QByteArray MainWindow::file_bytes(const QString& file_name) const {
    // Markdown or plain text by the file's extension: core's writers, which the importers read back.
    std::vector<std::string> lines;
    for (const auto& line : editor_->text().split(QLatin1Char('\n'))) lines.push_back(line.toStdString());
    const auto& layout = editor_->layout();
    return QByteArray::fromStdString(
        edit::file_text(lines, layout.dialect(), layout.document(), file_name.toStdString(), layout.line_ending()));
}

bool MainWindow::save_to(const QString& path) {
    if (refuse_saving_graphic()) return false;
    if (!may_lose_pictures(path)) return false;
    // In the file's format and, for a text file, its own encoding (core's writer).
    std::vector<std::string> lines;
    for (const auto& line : editor_->text().split(QLatin1Char('\n'))) lines.push_back(line.toStdString());
    std::vector<std::string> warnings;  // what the format does not keep
    const auto bytes_for = [&] {
        const auto& layout = editor_->layout();
        return edit::file_bytes(lines, layout.dialect(), layout.document(), path.toStdString(), layout.line_ending(),
                                &warnings);
    };
    auto bytes = bytes_for();
    if (!bytes && exporter::is_unrepresentable_error(bytes.error())) {
        if (!may_save_as_utf8(path, bytes.error())) return false;
        editor_->set_encoding("UTF-8", false);
        bytes = bytes_for();
    }
    if (!bytes) {
        report(tr("Cannot save %1: %2").arg(QFileInfo(path).fileName(), QString::fromStdString(bytes.error().to_string())),
               true);
        return false;
    }
    QString error;
    // A Markdown file's pictures are files beside it: the ones it lacks are
    // written first, so the file saved finds its pictures there.
    const auto beside = edit::picture_files(editor_->layout().document(), std::filesystem::path(path.toStdString()));
    for (const auto& f : beside) {
        const auto file = QString::fromStdString(f.path.string());
        QDir().mkpath(QFileInfo(file).absolutePath());
        if (!write_atomically(file, QByteArray::fromStdString(f.bytes), &error)) {
            report(error, true);
            return false;
        }
    }
    if (!write_atomically(path, QByteArray::fromStdString(*bytes), &error)) {
        report(error, true);
        return false;
    }
    path_ = QFileInfo(path).absoluteFilePath();
    source_name_ = QFileInfo(path).fileName();
    editor_->undo_stack()->setClean();
    autosave_.remove();
    add_recent(path_);
    update_title();
    // One message: what the format does not keep follows the file's name.
    auto said = tr("Saved %1").arg(QFileInfo(path).fileName());
    if (!beside.empty())
        said += QLatin1Char(' ') + tr("with %n picture file(s) beside it", nullptr, static_cast<int>(beside.size()));
    if (!warnings.empty()) said += QLatin1Char(' ') + QString::fromStdString(warnings.front());
    report(said);
    return true;
}

void MainWindow::export_dialog(const QString& format) {
    const auto base = document_base_name();
    const auto filter = format == QLatin1String("pef") ? tr("PEF (*.pef)") : tr("Braille ASCII (*.brf)");
    FocusReturn back(this, editor_->print_pane());
    auto path = QFileDialog::getSaveFileName(this, tr("Export"), base + QLatin1Char('.') + format, filter);
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QLatin1Char('.') + format;
    export_to(path);
}

bool MainWindow::export_to(const QString& path) {
    if (!may_reflow_braille()) return false;
    const auto& paged = this->paged();
    const auto suffix = QFileInfo(path).suffix().toLower();
    Result<std::string> bytes = fail(ErrorKind::usage, "unknown export format", suffix.toStdString());
    if (suffix == QLatin1String("brf")) {
        bytes = exporter::to_brf(paged);
    } else if (suffix == QLatin1String("pef")) {
        // A PEF's own metadata is kept, as the CLI keeps it (paged.metadata).
        const auto meta = exporter::pef_metadata(
            paged.metadata, QFileInfo(source_name_.isEmpty() ? path : source_name_).completeBaseName().toStdString(),
            QDate::currentDate().toString(Qt::ISODate).toStdString(),
            translate::table_language_tag(editor_->layout().tables()));
        bytes = exporter::to_pef(paged, meta);
    }
    if (!bytes) {
        report(tr("Cannot export %1: %2").arg(QFileInfo(path).fileName(), QString::fromStdString(bytes.error().to_string())),
               true);
        return false;
    }
    QString error;
    if (!write_atomically(path, QByteArray::fromStdString(*bytes), &error)) {
        report(error, true);
        return false;
    }
    report(tr("Exported %1 (%n sheet(s))", nullptr, static_cast<int>(paged.sheet_count())).arg(QFileInfo(path).fileName()));
    return true;
}

void MainWindow::print_pdf_dialog() {
    const auto base = document_base_name();
    FocusReturn back(this, editor_->print_pane());
    auto path = QFileDialog::getSaveFileName(this, tr("Print preview to PDF"), base + QStringLiteral("-proof.pdf"),
                                             tr("PDF (*.pdf)"));
    if (!path.isEmpty()) print_pdf_to(path);
}

bool MainWindow::print_pdf_to(const QString& path) {
    QString error;
    const auto* sp = preview_->preview();
    if (!print_to_pdf(paged(), sp->geometry(), sp->mode(), path, &error)) {
        report(error, true);
        return false;
    }
    report(tr("Wrote proof %1").arg(QFileInfo(path).fileName()));
    return true;
}

QStringList MainWindow::recent_files() const {
    return QSettings().value(QStringLiteral("recent/files")).toStringList();
}

void MainWindow::add_recent(const QString& path) {
    auto files = recent_files();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecent) files.removeLast();
    QSettings().setValue(QStringLiteral("recent/files"), files);
    update_recent_menu();
}

void MainWindow::update_recent_menu() {
    recent_menu_->clear();
    const auto files = recent_files();
    for (int i = 0; i < files.size(); ++i) {
        auto* a = recent_menu_->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(files[i]).fileName()));
        a->setToolTip(files[i]);
        a->setShortcut(QKeySequence(QStringLiteral("Alt+Shift+%1").arg(i + 1)));
        const auto path = files[i];
        connect(a, &QAction::triggered, this, [this, path] {
            if (maybe_save()) open_file(path);
        });
    }
    recent_menu_->setEnabled(!files.isEmpty());
}

bool MainWindow::maybe_save() {
    if (editor_->undo_stack()->isClean() || !interactive_) return true;
    FocusReturn back(this, editor_->print_pane());
    const auto answer = QMessageBox::question(this, tr("Tactus"), tr("Save the changes to %1?")
                                                                      .arg(source_name_.isEmpty() ? tr("Untitled") : source_name_),
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

bool MainWindow::may_reflow_braille() {
    const auto& live = editor_->layout();
    if (!live.ready_braille()) return true;
    const auto misfit = layout::find_braille_misfit(live.document(), live.options());
    if (!misfit) return true;
    const auto name = source_name_.isEmpty() ? tr("Untitled") : source_name_;
    const auto question = tr("The printer's page is too small for the pages of %1. Lay the braille out again on the "
                             "printer's page?")
                              .arg(name);
    // The file's own page is said, as it declares it (PEF cols x rows; a
    // BRF's longest line and page), volume by volume when its volumes differ,
    // against the printer's page: what the user can compare with a printer.
    const auto& volumes = misfit->volumes;
    const bool one_size = std::ranges::all_of(volumes, [&](const layout::VolumePage& v) {
        return v.cols == volumes.front().cols && v.rows == volumes.front().rows;
    });
    QString sizes;
    if (volumes.empty() || one_size) {
        const int cols = volumes.empty() ? misfit->file_cols : volumes.front().cols;
        const int rows = volumes.empty() ? misfit->file_rows : volumes.front().rows;
        sizes = tr("The pages of %1 are %2 cells by %3 lines; the printer's page holds %4 cells by %5 lines.")
                    .arg(name)
                    .arg(cols)
                    .arg(rows)
                    .arg(misfit->target_cols)
                    .arg(misfit->target_rows);
    } else {
        QStringList each;
        for (const auto& v : volumes)
            each << (v.fits ? tr("volume %1, %2 cells by %3 lines") : tr("volume %1, %2 cells by %3 lines, too large"))
                        .arg(v.volume)
                        .arg(v.cols)
                        .arg(v.rows);
        sizes = tr("The pages of %1 differ by volume: %2. The printer's page holds %3 cells by %4 lines.")
                    .arg(name, each.join(tr("; ")))
                    .arg(misfit->target_cols)
                    .arg(misfit->target_rows);
    }
    const auto detail = sizes + QLatin1Char(' ') +
                        tr("Nothing has been embossed or exported. Reflow lays the braille out again on the printer's "
                           "page, so its lines and pages change. Stop leaves it as it is; choose a printer whose page "
                           "is large enough.");
    if (!interactive_) {
        report(question + QLatin1Char(' ') + detail, true);
        return false;
    }
    FocusReturn back(this, editor_->print_pane());
    if (ask(this, {.title = tr("Tactus"),
                   .text = question,
                   .detail = detail,
                   .accessible_name = tr("The printer's page is too small"),
                   .object_name = QStringLiteral("pageTooSmallQuestion"),
                   .go = {tr("&Reflow"), QStringLiteral("reflowButton"),
                          tr("Lay the braille out again on the printer's page and go on")},
                   .stay = {tr("&Stop"), QStringLiteral("stopButton"), tr("Emboss or export nothing")}}))
        return true;
    report(tr("Stopped: nothing was embossed or exported (the printer's page is too small for %1)").arg(name));
    return false;
}

bool MainWindow::may_save_as_utf8(const QString& path, const Error& why) {
    const auto name = QFileInfo(path).fileName();
    const auto encoding = QString::fromStdString(editor_->layout().encoding());
    const auto question = tr("%1 cannot be saved in its encoding, %2. Save it as UTF-8?").arg(name, encoding);
    const auto detail = tr("At line:column %1, %2. Nothing has been saved. UTF-8 holds every character, but programs that "
                           "expect %3 may show it wrongly. Cancel leaves the file as it is; remove the character "
                           "to keep %3.")
                            .arg(QString::fromStdString(why.where), QString::fromStdString(why.message), encoding);
    return ask_before_saving({.title = tr("Tactus"),
                              .text = question,
                              .detail = detail,
                              .accessible_name = tr("A character does not fit the file's encoding"),
                              .object_name = QStringLiteral("encodingQuestion"),
                              .go = {tr("Save as &UTF-8"), QStringLiteral("saveUtf8Button"),
                                     tr("Save the whole file as UTF-8 from now on")},
                              .stay = {{}, {}, tr("Save nothing")}},  // the standard Cancel
                             tr("Not saved: %1 has a character that %2 cannot hold").arg(name, encoding));
}

bool MainWindow::ask_before_saving(const Question& question, const QString& not_saved) {
    // With nobody to ask (tests, scripts), the question and its detail are the refusal.
    if (!interactive_) {
        report(question.text + QLatin1Char(' ') + question.detail, true);
        return false;
    }
    FocusReturn back(this, editor_->print_pane());
    if (ask(this, question)) return true;
    report(not_saved);
    return false;
}

bool MainWindow::may_lose_pictures(const QString& path) {
    // The editor keeps the document's pictures (edit/editor_pictures.hpp): a
    // DOCX or ODT writes them all, a Markdown file has them beside it (written
    // with it, unless another file there has the name); a text file keeps
    // only their descriptions.
    const auto lost = edit::pictures_lost(editor_->layout().document(), std::filesystem::path(path.toStdString()));
    if (lost == 0) return true;
    const auto name = QFileInfo(path).fileName();
    const auto n = static_cast<int>(lost);
    return ask_before_saving(
        {.title = tr("Tactus"),
         .text = tr("%1 cannot keep %n of the document's pictures. Save anyway?", nullptr, n).arg(name),
         .detail = tr("Nothing has been saved. In %1 each of these pictures would be its description only. "
                      "Cancel saves nothing; a DOCX or ODT file keeps every picture.")
                       .arg(name),
         .accessible_name = tr("Saving would lose pictures"),
         .object_name = QStringLiteral("picturesQuestion"),
         .go = {tr("&Save Without Them"), QStringLiteral("replacePicturesButton"),
                tr("Save with the pictures' descriptions only")},
         .stay = {{}, {}, tr("Save nothing")}},  // the standard Cancel
        tr("Not saved: %1 cannot keep %n picture(s)", nullptr, n).arg(name));
}

bool MainWindow::may_stop_embossing() {
    const auto job = printer_->embossing();
    if (!job || !interactive_) return true;
    FocusReturn back(this, editor_->print_pane());
    return ask(this, {.title = tr("Tactus"),
                      .text = tr("%1 is being embossed. Quit anyway?").arg(QString::fromStdString(job->title)),
                      .detail = tr("The job stays in the print queue. The sheet in the embosser now is discarded; "
                                   "the rest is embossed when Tactus or tactus-cli serve runs printer %1 again.")
                                    .arg(QString::fromStdString(job->printer)),
                      .accessible_name = {},
                      .object_name = {},
                      .go = {tr("&Quit"), {}, {}},
                      .stay = {tr("&Keep embossing"), {}, {}}});
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (!may_stop_embossing() || !maybe_save()) {
        e->ignore();
        return;
    }
    // This window's runner lets go of the printer; its job waits in the spool.
    printer_->disconnect_device();
    if (busy_) busy_->cancel();
    if (planning_) planning_->cancel();
    QSettings s;
    s.setValue(QStringLiteral("window/geometry"), saveGeometry());
    s.setValue(QStringLiteral("window/state"), saveState());
    autosave_.remove();
    e->accept();
}

bool MainWindow::focusNextPrevChild(bool next) {
    // Only the controls on the raised tab of each dock (widgets/visible_focus.hpp).
    return focus_next_visible(this, next) || QMainWindow::focusNextPrevChild(next);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
    if (e->mimeData()->hasUrls()) e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
    const auto urls = e->mimeData()->urls();
    if (urls.isEmpty() || !urls.front().isLocalFile()) return;
    e->acceptProposedAction();
    if (maybe_save()) open_file(urls.front().toLocalFile());
}

void MainWindow::show_panel(const QString& name) {
    const auto dock_name = name + QStringLiteral("Dock");
    if (auto* dock = findChild<QDockWidget*>(dock_name)) {
        dock->show();
        dock->raise();
    }
}

// The document's name without its extension, for the files made from it.
QString MainWindow::document_base_name() const {
    return QFileInfo(source_name_.isEmpty() ? tr("untitled") : source_name_).completeBaseName();
}

bool MainWindow::emboss() {
    const auto name = source_name_.isEmpty() ? tr("Untitled") : source_name_;
    // To a CUPS queue: the source document, laid out by the server with its
    // embosser's profile, in the chosen table: ready-made braille with a
    // PEF's structure as PEF (its pages, sections, volumes, grids and
    // metadata: edit::structured_braille_pef, the rule the autosave follows
    // too), anything else as Markdown. Else into the spool: the job outlives
    // this window, and waits if the embosser is unreachable.
    const auto base = document_base_name();
    // A CUPS queue lays the document out with its own embosser's profile; the
    // spool embosses the pages laid out here, on this profile's page.
    const bool to_queue = printer_->selected_is_queue();
    if (!to_queue && !may_reflow_braille()) return false;
    bool sent = false;
    if (to_queue && graphic_) {
        // A CUPS queue imports a document's text; a drawing's dots depend on
        // the printer, so it goes through the spool to a device (docs/graphics.md).
        report(tr("Cannot send %1 to a CUPS queue: a tactile graphic is embossed on a device (choose it in the printer panel)")
                   .arg(name),
               true);
        return false;
    }
    if (to_queue) {
        const auto pef = edit::structured_braille_pef(editor_->layout(), base.toStdString());
        if (pef && !*pef) {
            report(tr("Cannot send %1: %2").arg(name, QString::fromStdString(pef->error().to_string())), true);
            return false;
        }
        sent = pef ? printer_->send_to_queue(name, base + QStringLiteral(".pef"), QByteArray::fromStdString(**pef),
                                             tables_->table())
                   : printer_->send_to_queue(name, base + QStringLiteral(".md"), file_bytes(base + QStringLiteral(".md")),
                                             tables_->table());
    } else {
        book_->flush();
        sent = printer_->submit(name, *book_->shown(&paged()), profile_->profile()) != 0;
    }
    if (!sent) {
        // The fault is on the printer panel, beside the device picker: go there.
        show_panel(QStringLiteral("printer"));
        if (auto* picker = printer_->findChild<QWidget*>(QStringLiteral("devicePicker")))
            picker->setFocus(Qt::ShortcutFocusReason);
        return false;
    }
    // The queue is where the job's progress, pause and cancel are: raise it with the focus.
    show_panel(QStringLiteral("printer"));
    if (auto* queue = printer_->findChild<QWidget*>(QStringLiteral("jobQueue"))) queue->setFocus(Qt::ShortcutFocusReason);
    return true;
}

QDockWidget* MainWindow::add_dock(const QString& title, const QString& name, QWidget* w, Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    dock->setAccessibleName(title);
    dock->setWidget(w);
    dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    addDockWidget(area, dock);
    track_dock_page(dock);
    return dock;
}

// ---- planning for the motion and vibration views ----

namespace {
constexpr std::size_t kPlannedSheetsKept = 20;  // sheets the views can show in full
}

void MainWindow::schedule_plan() { plan_timer_.start(); }

void MainWindow::start_plan() {
    if (!editor_->has_layout()) return;
    if (planning_) planning_->cancel();  // its result is stale; the watcher is dropped when done
    auto* watcher = new QFutureWatcher<DocumentPlanPtr>(this);
    planning_ = watcher;
    connect(watcher, &QFutureWatcher<DocumentPlanPtr>::finished, this, [this, watcher] {
        watcher->deleteLater();
        if (watcher != planning_ || watcher->future().resultCount() == 0) return;
        planning_ = nullptr;
        show_plan(watcher->future().result());
    });
    watcher->setFuture(plan_document_async(paged(), profile_->profile(), kPlannedSheetsKept));
}

DocumentPlanPtr MainWindow::plan_now() {
    auto plan = plan_document(paged(), profile_->profile(), kPlannedSheetsKept);
    show_plan(plan);
    return plan;
}

void MainWindow::show_plan(const DocumentPlanPtr& plan) {
    if (!plan || plan->cancelled) return;
    motion_->set_plan(plan);
    vibration_->set_plan(plan);
    if (plan->error)
        message_->show_message(tr("Cannot plan the job: %1").arg(QString::fromStdString(plan->error->to_string())), 10000);
    Q_EMIT planned(plan);
}

// ---- autosave and recovery ----

bool MainWindow::autosave_now() {
    // Ready-made braille with a PEF's structure is kept as PEF, so a recovery
    // has its sections, volumes, grids and metadata (edit::structured_braille_pef,
    // the rule a CUPS job follows too); anything else as the editor's lines.
    const auto base = document_base_name();
    const auto pef = edit::structured_braille_pef(editor_->layout(), base.toStdString());
    const bool as_pef = pef && pef->has_value();
    const auto& layout = editor_->layout();
    const AutosaveMeta meta{.document_path = path_,
                            .name = source_name_,
                            .table = QString::fromStdString(layout.tables()),
                            .line_ending = QString::fromStdString(layout.line_ending()),
                            .encoding = QString::fromStdString(layout.encoding()),
                            .byte_order_mark = layout.byte_order_mark()};
    QString error;
    if (!autosave_.write(as_pef ? QByteArray::fromStdString(**pef) : editor_->text().toUtf8(), as_pef, meta, &error)) {
        if (!error.isEmpty()) message_->show_message(error, 10000);
        return false;
    }
    return true;
}

QList<Recovery> MainWindow::pending_recoveries() { return Autosave::pending(); }

bool MainWindow::recover(const Recovery& r) {
    QFile f(r.autosave_path);
    if (!f.open(QIODevice::ReadOnly)) {
        report(tr("Cannot read the autosaved copy %1: %2").arg(r.autosave_path, f.errorString()), true);
        return false;
    }
    const auto table = r.table.isEmpty() ? editor_->layout().tables() : r.table.toStdString();
    if (r.autosave_path.endsWith(QLatin1String(".pef"))) {
        // Ready-made braille kept as PEF: opened as a PEF is, with its structure.
        f.close();
        auto loaded = load_file_now(r.autosave_path, table, editor_->layout().options());
        if (!loaded->layout) {
            report(tr("Cannot read the autosaved copy %1: %2")
                       .arg(r.autosave_path, loaded->error ? QString::fromStdString(loaded->error->to_string()) : QString()),
                   true);
            return false;
        }
        editor_->adopt(std::move(*loaded->layout));
    } else {
        std::vector<std::string> lines;
        for (const auto& l : QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'))) lines.push_back(l.toStdString());
        auto layout = edit::LiveLayout::create(table, editor_->layout().options());
        if (!layout) {
            report(QString::fromStdString(layout.error().to_string()), true);
            return false;
        }
        layout->set_dialect(edit::dialect_for(r.document_path.toStdString()));
        if (!r.line_ending.isEmpty()) layout->set_line_ending(r.line_ending.toStdString());
        if (!r.encoding.isEmpty()) layout->set_encoding(r.encoding.toStdString(), r.byte_order_mark);
        layout->reset(std::move(lines));
        editor_->adopt(std::move(*layout));
    }
    show_graphic(std::nullopt, {});
    editor_->print_pane()->setReadOnly(false);
    tables_->set_table(QString::fromStdString(table));
    path_ = r.document_path;
    source_name_ = r.document_path.isEmpty() ? tr("Recovered") : QFileInfo(r.document_path).fileName();
    editor_->undo_stack()->resetClean();  // recovered text is unsaved work
    Autosave::discard(r);
    autosave_now();
    update_title();
    report(tr("Recovered unsaved changes to %1").arg(source_name_));
    return true;
}

void MainWindow::offer_recovery() {
    if (const auto r = Autosave::ask(this)) recover(*r);
}

// ---- help ----

void MainWindow::show_shortcuts() {
    FocusReturn back(this, editor_->print_pane());
    QDialog d(this);
    d.setWindowTitle(tr("Keyboard Shortcuts"));
    d.setAccessibleName(d.windowTitle());
    auto* table = new QTableWidget(&d);
    table->setObjectName(QStringLiteral("shortcutTable"));
    table->setAccessibleName(tr("Shortcuts"));
    table->setColumnCount(2);
    table->setHorizontalHeaderLabels({tr("Action"), tr("Shortcut")});
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setTabKeyNavigation(false);  // Tab leaves the table; arrows move between cells
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    auto rows = shortcut_rows();
    table->setRowCount(static_cast<int>(rows.size()));
    for (int i = 0; i < rows.size(); ++i) {
        table->setItem(i, 0, new QTableWidgetItem(rows[i].first));
        table->setItem(i, 1, new QTableWidgetItem(rows[i].second));
    }
    table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    table->resizeColumnToContents(1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, &d);
    connect(buttons, &QDialogButtonBox::rejected, &d, &QDialog::reject);
    auto* layout = new QVBoxLayout(&d);
    layout->addWidget(table);
    layout->addWidget(buttons);
    d.resize(560, 520);
    table->setFocus();
    d.exec();
}

QList<QPair<QString, QString>> MainWindow::shortcut_rows() const {
    QList<QPair<QString, QString>> rows;
    for (auto* a : all_actions()) {
        if (a->shortcut().isEmpty()) continue;
        rows.append({a->text().remove(QLatin1Char('&')).remove(QStringLiteral("...")),
                     a->shortcut().toString(QKeySequence::NativeText)});
    }
    rows.append({tr("Braille pane: dots 1 2 3 4 5 6 (chord, released together)"), tr("F D S J K L")});
    rows.append({tr("Braille pane: blank cell / erase cell"), tr("Space / Backspace, Delete")});
    rows.append({tr("Preview: move between cells / lines"), tr("Arrow keys")});
    rows.append({tr("Preview: turn to the other side"), tr("Space")});
    rows.append({tr("Preview: previous / next sheet"), tr("PgUp / PgDown")});
    rows.append({tr("Move between panes"), tr("Tab / Shift+Tab")});
    return rows;
}

void MainWindow::book_settings() {
    BookSettingsDialog dialog(book_->options(), this);
    if (dialog.exec() != QDialog::Accepted) return;
    apply_book_settings(dialog.options());
}

void MainWindow::apply_book_settings(const pipeline::BookOptions& options) {
    QSettings s;
    save_book_rules(s, options);
    book_->set_options(options);
    report(tr("Book settings: about %n sheet(s) per volume", nullptr, options.sheets_per_volume));
}

void MainWindow::show_about() {
    FocusReturn back(this, editor_->print_pane());
    QMessageBox::about(this, tr("About Tactus"),
                       tr("<p><b>Tactus %1</b></p><p>Braille editor and embosser print manager.</p>"
                          "<p>Licensed under the GNU GPL, version 3 or later.</p>")
                           .arg(QStringLiteral(TACTUS_VERSION)));
}

}  // namespace tactus::gui
