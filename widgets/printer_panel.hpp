// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The printer panel: device picker (the simulator always there), connect and
// live controller status, the job queue with progress bars, pause / resume /
// cancel / resume from a page, faults in plain words with what to do, and the
// link log for technicians. Jobs run one at a time off the GUI thread.
#include <QFutureWatcher>
#include <QPointer>
#include <QTimer>
#include <QWidget>
#include <memory>
#include <optional>

#include "embosser.hpp"
#include "layout/page.hpp"
#include "progress_steps.hpp"

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace tactus::gui {

struct QueuedJob {
    enum class State { queued, running, paused, done, failed, cancelled };
    int id = 0;
    QString name;
    std::shared_ptr<const layout::PagedDocument> pages;
    profile::PrinterProfile profile;
    std::size_t start_sheet = 1;
    State state = State::queued;
    std::size_t passes_done = 0;
    std::size_t passes_total = 0;
    std::size_t resume_sheet = 1;
    QString message;
    std::shared_ptr<ProgressSteps> steps;  // when the bar moves and what is spoken
};

class PrinterPanel : public QWidget {
    Q_OBJECT
public:
    explicit PrinterPanel(QWidget* parent = nullptr);
    ~PrinterPanel() override;

    bool connect_device(const QString& device, const profile::PrinterProfile& p);
    void disconnect_device();
    [[nodiscard]] bool connected() const { return embosser_.has_value(); }
    [[nodiscard]] QString selected_device() const;
    void select_device(const QString& device);
    // Adds a job; it starts when the printer is connected and free.
    int enqueue(const QString& name, const layout::PagedDocument& pages, const profile::PrinterProfile& p,
                std::size_t start_sheet = 1);
    [[nodiscard]] const std::vector<QueuedJob>& jobs() const { return jobs_; }
    [[nodiscard]] QString fault_text() const;
    [[nodiscard]] QString log_text() const;
    [[nodiscard]] Embosser* embosser() { return embosser_ ? &*embosser_ : nullptr; }

public Q_SLOTS:
    void refresh_devices();
    void pause_job();
    void resume_job();
    void cancel_job();
    // Queues the selected job again from the sheet holding braille page `page`.
    void resume_from_page(int page);

Q_SIGNALS:
    void message(const QString& text, bool error);
    void job_finished(int id, bool completed, const QString& text);

private:
    struct Running;
    void start_next();
    void finished_job(int id);
    void update_row(const QueuedJob& job);
    void log(const QString& line);
    void poll_status();
    void show_fault(const QString& text);
    void set_status(const QString& text);
    void on_progress(int id, std::size_t done, std::size_t total, std::size_t sheet);
    void update_buttons();
    QueuedJob* job(int id);
    QueuedJob* selected_job();

    QComboBox* devices_;
    QPushButton* connect_;
    QLabel* status_;
    QLabel* fault_;
    QTableWidget* queue_;
    QPushButton *pause_, *resume_, *cancel_, *from_page_;
    QSpinBox* page_;
    QPlainTextEdit* log_;
    std::optional<Embosser> embosser_;
    std::vector<QueuedJob> jobs_;
    int next_id_ = 1;
    std::unique_ptr<Running> running_;
    QTimer status_timer_;
};

}  // namespace tactus::gui
