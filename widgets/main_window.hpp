// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Tactus window: the editor in the middle, the interpoint preview (and, as
// their cores land, the motion and printer panels) in docks; every action has a
// shortcut and an accessible name; long work runs off the GUI thread.
#include <QDateTime>
#include <QFutureWatcher>
#include <QMainWindow>
#include <QPointer>
#include <QTimer>
#include <memory>

#include "ask.hpp"
#include "autosave.hpp"
#include "document_loader.hpp"
#include "motion_model.hpp"
#include "picture_pages.hpp"
#include "pipeline/book_layout.hpp"

class QDockWidget;
class QLabel;
class QMenu;
class QProgressDialog;

namespace tactus::gui {

class Announcer;
class EditorWidget;
class FocusReturn;
class MessageLabel;
class MotionView;
class PrinterPanel;
class ProfileEditor;
class VibrationView;
class FindReplaceDialog;
class PreviewPanel;
class BookView;
class BookProgress;
class TablePicker;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Starts opening a file in the background; `opened` or `failed` follows.
    void open_file(const QString& path);
    // Opens synchronously (tests, the benchmark); returns false with a message on failure.
    bool open_file_now(const QString& path);
    // A standalone drawing is open: says why it is not saved, and returns true.
    bool refuse_saving_graphic();
    bool save_to(const QString& path);
    // The document as the editor holds it, as the file `file_name` would hold
    // it (plain text for .txt, else Markdown): what Save writes, and what is
    // sent to a network queue.
    [[nodiscard]] QByteArray file_bytes(const QString& file_name) const;
    bool export_to(const QString& path);  // .brf, .pef (by extension)
    bool print_pdf_to(const QString& path);
    void set_table(const QString& table);
    // Styles > Graphic: the picture file (.svg, .png, .jpg) as a paragraph
    // after the cursor's, with its description (required); announced. False,
    // with a message, when it cannot be.
    bool insert_graphic(const QString& path, const QString& description);
    // File > Emboss Pictures as Graphics: the document's pictures as graphic
    // pages (as `tactus-cli layout --images graphics`), or their descriptions
    // only; kept as a setting.
    void set_picture_choice(PictureChoice choice);
    [[nodiscard]] PictureChoice picture_choice() const { return picture_choice_; }

    [[nodiscard]] EditorWidget* editor() const { return editor_; }
    // The pages shown, exported, planned and embossed: the open graphic's,
    // else the editor's document laid out (with its pictures' graphic pages
    // when they are embossed as graphics).
    [[nodiscard]] const layout::PagedDocument& paged() const;
    // The open drawing (File > Open of an .svg, .png, .jpg), or null.
    [[nodiscard]] const GraphicView* graphic() const { return graphic_ ? &*graphic_ : nullptr; }
    [[nodiscard]] PreviewPanel* preview_panel() const { return preview_; }
    [[nodiscard]] Announcer* announcer() const { return announcer_; }
    // The book layout the preview shows and the printer embosses, when the document reads as a book.
    [[nodiscard]] BookView* book_view() const { return book_; }
    // What Book Settings does on OK: the rules kept for every book, the book
    // laid out again with them.
    void apply_book_settings(const pipeline::BookOptions& options);
    [[nodiscard]] TablePicker* table_picker() const { return tables_; }
    [[nodiscard]] MotionView* motion_view() const { return motion_; }
    [[nodiscard]] VibrationView* vibration_view() const { return vibration_; }
    [[nodiscard]] ProfileEditor* profile_editor() const { return profile_; }
    // Null when this build has no link stage.
    [[nodiscard]] PrinterPanel* printer_panel() const { return printer_; }
    // Queues the document in the spool on the chosen embosser's printer, or
    // sends it to the chosen CUPS queue (printer panel).
    bool emboss();
    // Plans the document now (tests); normally planning follows edits after a pause.
    DocumentPlanPtr plan_now();
    // Brings a dock to the front: "preview", "motion", "vibration", "profile", "printer".
    void show_panel(const QString& name);
    [[nodiscard]] QString status_text() const;
    [[nodiscard]] QString document_path() const { return path_; }
    [[nodiscard]] QStringList recent_files() const;
    [[nodiscard]] QList<QAction*> all_actions() const;
    [[nodiscard]] bool is_busy() const { return busy_ != nullptr; }
    [[nodiscard]] QList<QPair<QString, QString>> shortcut_rows() const;
    // Interactive windows ask before discarding work and show error boxes; tests don't.
    void set_interactive(bool on) { interactive_ = on; }
    // Background work that ends in a document (opening, a new table): a
    // progress dialog with Cancel, the steps said, then the result adopted.
    void start_busy(const QString& what, QFuture<LoadResultPtr> future, bool replace_text);
    // How long background work runs before its progress dialog shows (300 ms;
    // a test shows it at once, as a slow machine does).
    void set_progress_delay(int ms) { progress_delay_ = ms; }

    // Crash recovery: autosaves that no running Tactus owns.
    [[nodiscard]] static QList<Recovery> pending_recoveries();
    bool recover(const Recovery& r);
    void offer_recovery();  // asks the user (interactive start only)
    bool autosave_now();
    [[nodiscard]] QString autosave_path() const { return autosave_.path(); }

Q_SIGNALS:
    void planned(const tactus::gui::DocumentPlanPtr& plan);
    void job_finished(bool completed, const QString& text);
    void opened(const QString& path);
    void failed(const QString& message);

protected:
    void closeEvent(QCloseEvent* e) override;
    // With a job embossing on this window's runner, asks before quitting (the
    // job stays in the spool); true to go on.
    bool may_stop_embossing();
    bool focusNextPrevChild(bool next) override;
    void dragEnterEvent(QDragEnterEvent* e) override;
    void dropEvent(QDropEvent* e) override;

private:
    void build_actions();
    void build_menus();
    void restore_settings();
    void new_document();
    void open_dialog();
    bool save();
    bool save_as();
    void export_dialog(const QString& format);
    void print_pdf_dialog();
    void show_shortcuts();
    void show_about();
    void book_settings();
    void update_status();
    void update_title();
    void update_recent_menu();
    void add_recent(const QString& path);
    void report(const QString& message, bool error = false);
    [[nodiscard]] QString table_warning(const QString& detail) const;
    [[nodiscard]] QString document_base_name() const;
    bool maybe_save();
    // Ready-made braille (BRF, PEF) whose page is larger than the printer's:
    // asks before anything is embossed or exported whether to reflow it on the
    // printer's page or to stop (layout::find_braille_misfit, the rule the
    // CLI's exit 5 asks). True to go on. A window that is not interactive stops.
    bool may_reflow_braille();
    // A character the text file's encoding cannot hold: asks whether to save
    // as UTF-8 (true) or not at all.
    bool may_save_as_utf8(const QString& path, const Error& why);
    // Before saving the document's pictures to a file that cannot keep them
    // (a text file; a Markdown file where another file has a picture's name): asks
    // (refuses when not interactive), as nothing is lost unasked.
    bool may_lose_pictures(const QString& path);
    // Asks a question before saving (true: go on); with nobody to ask, or on
    // the answer that stays, nothing is saved and the window says why.
    bool ask_before_saving(const Question& question, const QString& not_saved);
    // The open drawing laid out again, for a new profile or table (its dots
    // depend on both), as the CLI lays it out for them.
    void lay_out_graphic_again();
    // The drawing (or none) becomes the document shown: preview, print pane.
    void show_graphic(std::optional<GraphicView> graphic, const QString& path);
    void finish_load(const LoadResultPtr& r, bool replace_text);
    QDockWidget* add_dock(const QString& title, const QString& name, QWidget* w, Qt::DockWidgetArea area);
    void schedule_plan();
    void start_plan();
    void show_plan(const DocumentPlanPtr& plan);

    EditorWidget* editor_ = nullptr;
    PreviewPanel* preview_ = nullptr;
    BookView* book_ = nullptr;
    BookProgress* book_progress_ = nullptr;
    TablePicker* tables_ = nullptr;
    Announcer* announcer_ = nullptr;
    FindReplaceDialog* find_ = nullptr;
    QLabel* status_ = nullptr;
    MessageLabel* message_ = nullptr;
    QMenu* recent_menu_ = nullptr;
    QString path_;         // where Save writes (a print format Tactus writes); empty: ask
    QString source_name_;  // the file the document came from, for the title
    std::optional<GraphicView> graphic_;
    QString graphic_path_;
    bool interactive_ = false;
    bool pages_kept_ = false;  // the layout kept ready-made braille's own pages when it last changed
    // Says so when an edit makes ready-made braille be laid out again (its own
    // pages, sections and volumes no longer kept), and when they are kept again.
    void tell_pages_kept();
    Autosave autosave_;
    QPointer<QFutureWatcher<LoadResultPtr>> busy_;
    QProgressDialog* progress_ = nullptr;
    std::shared_ptr<FocusReturn> busy_return_;
    int progress_delay_ = 300;
    // Messages at the end of background work are said this long after it (report()).
    static constexpr int kWordAfterBurstMs = 1500;
    bool word_after_burst_ = false;  // where the focus goes when the background work ends

    QAction *new_, *open_, *save_, *save_as_, *export_brf_, *export_pef_, *book_settings_, *quit_;
    MotionView* motion_ = nullptr;
    VibrationView* vibration_ = nullptr;
    ProfileEditor* profile_ = nullptr;
    PrinterPanel* printer_ = nullptr;
    QTimer plan_timer_;
    QPointer<QFutureWatcher<DocumentPlanPtr>> planning_;
    QAction *focus_motion_, *focus_vibration_, *focus_profile_, *focus_printer_ = nullptr, *emboss_ = nullptr;
    // The Styles menu's styles and emphasis, and View's "Show codes".
    QList<QAction*> format_actions_;
    QAction* show_codes_ = nullptr;
    QAction* insert_graphic_ = nullptr;
    QAction* pictures_as_graphics_ = nullptr;
    PictureChoice picture_choice_ = PictureChoice::descriptions;
    // The document laid out with its pictures as graphic pages (picture_choice_
    // graphics and the document holds pictures), else nothing.
    std::optional<layout::PagedDocument> pictured_;
    void lay_out_pictures();
    void insert_graphic_dialog();
    void build_format_actions();
    QAction *undo_, *redo_, *find_action_, *find_next_, *focus_print_, *focus_braille_, *focus_preview_,
        *focus_table_, *shortcuts_, *about_, *menus_ = nullptr;
};

}  // namespace tactus::gui
