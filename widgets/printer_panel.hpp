// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The printer panel is a client of the spool (docs/spool.md), like `tactus-cli
// queue` and the CUPS backend: Ctrl+P stores a job in the SQLite spool on the
// chosen device's spool printer, so it survives quitting the app and `tactus-cli
// serve` can finish it. The queue view is the spool's (jobs from the CLI, the
// app and the network alike), read again whenever another process commits.
// One runner per printer: the panel starts core's spool::Runner on a thread
// when no live runner holds the printer, otherwise it only watches. Pause,
// resume, cancel and resume-from-page are spool actions, carried out by
// whichever runner holds the job.
//
// Remote CUPS queues that run the Tactus backend (docs/cups.md) are listed
// beside the cables, found off the GUI thread. Ctrl+P to such a queue sends
// the document over IPP (core/ipp, as `tactus-cli emboss --device ipp://...`)
// and the job view follows the job on the server; it is not in the local
// spool, and quitting the app leaves it to the server. That part of the panel
// is printer_panel_queues.cpp.
//
// For technicians: a device picker that takes any device string, Connect
// (HELLO, CONFIGURE with the profile being edited, STATUS), faults injected
// into the built-in simulator, its speed (the plan's own by default), and the
// spool's event log.
#include <QPointer>
#include <QTimer>
#include <QWidget>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "layout/page.hpp"
#include "profile/profile.hpp"
#include "progress_steps.hpp"
#include "spool/records.hpp"

class QComboBox;
class QGroupBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace tactus::controller {
class BuiltInSimulator;
}
namespace tactus::spool {
class Spool;
}

namespace tactus::gui {

struct RemoteQueueJob;  // printer_panel_rows.hpp
class EmbossChoice;

class PrinterPanel : public QWidget {
    Q_OBJECT
public:
    // The spool at spool::spool_path() ($TACTUS_SPOOL_DB, else the XDG data folder).
    explicit PrinterPanel(QWidget* parent = nullptr);
    // Stops this window's runner: a job it was embossing goes back to the queue
    // (the sheet in the machine is discarded), for the next runner to finish.
    ~PrinterPanel() override;

    // Where Connect and Ctrl+P take the profile from (the profile editor's);
    // default_profile() until set.
    void set_profile_source(std::function<profile::PrinterProfile()> source);

    // Connect: checks the device string, sets up its spool printer with `p`
    // (a new printer, or the existing one's profile replaced by `p`), and unless
    // another live runner holds the printer, talks to the controller (HELLO,
    // CONFIGURE from `p`, STATUS) and starts this window's runner on it.
    bool connect_device(const QString& device, const profile::PrinterProfile& p);
    // Stops this window's runner and lets go of the printer.
    void disconnect_device();
    // This window runs or watches a printer.
    [[nodiscard]] bool connected() const { return !printer_.empty(); }
    // This window's runner holds the printer.
    [[nodiscard]] bool runs_printer() const { return runner_ != nullptr; }
    [[nodiscard]] QString selected_device() const;
    // Chooses a listed device, or types the device string into the picker.
    void select_device(const QString& device);
    // The chosen device is a CUPS queue (ipp://host/printers/NAME).
    [[nodiscard]] bool selected_is_queue() const;

    // Ctrl+P to a CUPS queue: sends `document` (the source document, named
    // `file_name` so the server types it) to the chosen queue over IPP with
    // braille table `table`, off the GUI thread, and follows the job on the
    // server in the job view. False, with the fault shown, when the address
    // names no queue; a server that refuses the job is reported when it does.
    bool send_to_queue(const QString& title, const QString& file_name, const QByteArray& document,
                       const QString& table);
    // Rows of the job view for jobs sent to CUPS queues from this window: the
    // state words the view shows, the job's CUPS name once sent ("Embosser-12").
    struct QueueJobRow {
        QString title, job, queue, state;
        bool ended = false;
    };
    [[nodiscard]] std::vector<QueueJobRow> queue_jobs() const;

    // Ctrl+P: stores `pages` as a job on the chosen device's spool printer (set
    // up with `p` if needed, as `emboss --queue --device` does) and makes sure a
    // runner serves the printer. An unreachable embosser does not stop it: the
    // job waits in the queue. Returns the spool job id, or 0 with the fault shown.
    // Only the pages chosen on the panel go into the job (emboss_choice(): the
    // whole document, a volume or a page range); a range that names no page
    // queues nothing and says why.
    spool::JobId submit(const QString& title, const layout::PagedDocument& pages, const profile::PrinterProfile& p);
    // What Ctrl+P embosses: the whole document, a volume, a page range.
    [[nodiscard]] EmbossChoice* emboss_choice() const { return choice_; }

    // The spool's jobs as the queue view shows them (all printers; unfinished
    // first in queue order, then the 100 most recent finished ones).
    [[nodiscard]] const std::vector<spool::JobRecord>& jobs() const { return jobs_; }
    // A job this window's runner is embossing (running or paused on the machine).
    [[nodiscard]] std::optional<spool::JobRecord> embossing() const;
    [[nodiscard]] QString fault_text() const;
    [[nodiscard]] QString log_text() const;
    [[nodiscard]] QString status_text() const;
    [[nodiscard]] std::filesystem::path spool_path() const { return db_; }
    // The built-in simulator ("sim"), made on first use; it lives as long as the panel.
    controller::BuiltInSimulator& simulator();
    // Reads the spool now (a timer also does it whenever another process commits).
    void refresh();
    // The job selected in the queue view, else the job being embossed.
    [[nodiscard]] std::optional<spool::JobId> selected_job() const;
    void select_job(spool::JobId id);

public Q_SLOTS:
    void refresh_devices();
    void pause_job();
    void resume_job();
    void cancel_job();
    // Embosses the selected job again from the sheet holding braille page `page`.
    void resume_from_page(int page);
    // Faults for the built-in simulator (the technician's test bench).
    void inject_paper_out();
    void inject_pulled_cable();
    void inject_noise();
    void inject_reset();
    // The built-in simulator's speed: the `speed` option of the chosen `sim`
    // device string ("": the plan's own speed, "10", "max").
    void set_simulator_speed(const QString& speed);

Q_SIGNALS:
    void message(const QString& text, bool error);
    // A job ended: `id` is the spool's job id, or the server's for a job sent
    // to a CUPS queue.
    void job_finished(qint64 id, bool completed, const QString& text);

private:
    struct AppRunner;
    using QueueJob = RemoteQueueJob;
    struct Watch {
        spool::JobState state = spool::JobState::queued;
        std::string reason;
        std::unique_ptr<ProgressSteps> steps;
    };
    struct Shown {
        int percent = 0;
        std::size_t sheet = 0;  // first unfinished sheet (0: none)
    };
    spool::Spool* open_spool(bool create);
    // The spool printer for the chosen device with profile `p`; empty on error (shown).
    std::string setup_printer(const QString& device, const profile::PrinterProfile& p);
    void start_runner(const std::string& printer);
    void stop_runner();
    void poll();
    void reload();
    void show_jobs();
    void follow(const spool::JobRecord& job, const Shown& shown, std::size_t passes_done, std::size_t passes_total);
    void finished(const spool::JobRecord& job, const Shown& shown);
    void check_strikes(const spool::JobRecord& job);
    void append_events();
    void update_status();
    void update_buttons();
    void show_speed();  // the speed choice follows the device string
    void log(const QString& line);
    void show_fault(const QString& text);
    void act(int action, std::optional<std::size_t> sheet = {});
    void discover_queues();
    void follow_queue_jobs();
    [[nodiscard]] QueueJob* selected_queue_job() const;
    [[nodiscard]] int selected_row() const;

    std::filesystem::path db_;
    std::unique_ptr<spool::Spool> spool_;
    std::function<profile::PrinterProfile()> profile_source_;
    std::shared_ptr<controller::BuiltInSimulator> sim_;
    std::unique_ptr<AppRunner> runner_;
    std::string printer_;  // the spool printer this window runs or watches
    std::vector<spool::JobRecord> jobs_;
    std::map<spool::JobId, Shown> shown_;
    std::map<spool::JobId, Watch> watch_;
    std::int64_t data_version_ = -1;
    std::int64_t last_event_ = 0;
    // The fault last announced per job: a fault the runner rides through in a
    // blink (the built-in simulator reloads paper at once) is seen only in the
    // event log, a longer one also as a paused job; it is said once either way.
    std::map<std::int64_t, QString> announced_fault_;
    void announce_fault(std::int64_t job, const QString& text);
    void announce_going_on(std::int64_t job);
    QString status_;

    QComboBox* devices_;
    EmbossChoice* choice_;
    QPushButton* connect_;
    QLabel* status_label_;
    QLabel* fault_;
    QTableWidget* queue_;
    QPushButton *pause_, *resume_, *cancel_, *from_page_;
    QSpinBox* page_;
    QGroupBox* faults_box_;
    QComboBox* speed_;
    QPlainTextEdit* log_;
    QTimer poll_timer_;
    std::vector<std::unique_ptr<QueueJob>> queue_jobs_;
    bool discovering_ = false;
    int shown_local_rows_ = 0;  // rows of the job view above the jobs on CUPS queues
};

}  // namespace tactus::gui
