// SPDX-License-Identifier: GPL-3.0-or-later
#include "printer_panel.hpp"

#include <QComboBox>
#include <QDateTime>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QCoreApplication>
#include <QtConcurrent/QtConcurrentRun>
#include <numeric>

#include "controller/sim_controller.hpp"
#include "plan/planner.hpp"
#include "status_label.hpp"

namespace tactus::gui {
namespace {

QString state_text(QueuedJob::State s) {
    switch (s) {
        case QueuedJob::State::queued: return QObject::tr("waiting");
        case QueuedJob::State::running: return QObject::tr("embossing");
        case QueuedJob::State::paused: return QObject::tr("paused");
        case QueuedJob::State::done: return QObject::tr("done");
        case QueuedJob::State::failed: return QObject::tr("stopped");
        case QueuedJob::State::cancelled: return QObject::tr("cancelled");
    }
    return {};
}

// What the worker reports back; built on the worker thread, read on the GUI thread.
struct Outcome {
    bool completed = false;
    bool cancelled = false;
    std::size_t passes_done = 0;
    std::size_t resume_sheet = 1;
    QString message;
    QString check;  // the simulator's strikes against the plan
};

}  // namespace

struct PrinterPanel::Running {
    int id = 0;
    link::CancelToken cancel;
    QFutureWatcher<Outcome> watcher;
};

PrinterPanel::PrinterPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("printerPanel"));
    devices_ = new QComboBox(this);
    devices_->setObjectName(QStringLiteral("devicePicker"));
    devices_->setAccessibleName(tr("Embosser"));
    devices_->setAccessibleDescription(tr("Serial ports with their USB descriptions, HID bridges, parallel ports, and the built-in simulator"));
    auto* refresh = new QPushButton(tr("&Refresh"), this);
    connect_ = new QPushButton(tr("&Connect"), this);
    connect_->setObjectName(QStringLiteral("connectButton"));
    status_ = new QLabel(tr("Not connected"), this);
    status_->setObjectName(QStringLiteral("controllerStatus"));
    expose_status(status_, tr("Controller status"));
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByKeyboard | Qt::TextSelectableByMouse);
    fault_ = new QLabel(this);
    fault_->setObjectName(QStringLiteral("faultMessage"));
    expose_status(fault_, tr("Fault"));
    fault_->setWordWrap(true);
    fault_->setStyleSheet(QStringLiteral("QLabel { color: #a00000; font-weight: bold; }"));
    queue_ = new QTableWidget(0, 4, this);
    queue_->setObjectName(QStringLiteral("jobQueue"));
    queue_->setAccessibleName(tr("Job queue"));
    queue_->setHorizontalHeaderLabels({tr("Document"), tr("State"), tr("Progress"), tr("Sheet")});
    queue_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    queue_->setTabKeyNavigation(false);  // Tab leaves the table; arrows move between cells
    queue_->setSelectionBehavior(QAbstractItemView::SelectRows);
    queue_->setSelectionMode(QAbstractItemView::SingleSelection);
    queue_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    pause_ = new QPushButton(tr("&Pause"), this);
    resume_ = new QPushButton(tr("Res&ume"), this);
    cancel_ = new QPushButton(tr("Ca&ncel job"), this);
    page_ = new QSpinBox(this);
    page_->setRange(1, 100000);
    page_->setAccessibleName(tr("Braille page to resume from"));
    from_page_ = new QPushButton(tr("Resume from pa&ge"), this);
    log_ = new QPlainTextEdit(this);
    log_->setObjectName(QStringLiteral("linkLog"));
    log_->setReadOnly(true);
    log_->setAccessibleName(tr("Link log"));
    log_->setMaximumBlockCount(5000);
    log_->setTabChangesFocus(true);

    auto* device_row = new QHBoxLayout;
    auto* label = new QLabel(tr("E&mbosser:"), this);
    label->setBuddy(devices_);
    device_row->addWidget(label);
    device_row->addWidget(devices_, 1);
    device_row->addWidget(refresh);
    device_row->addWidget(connect_);
    auto* job_row = new QHBoxLayout;
    job_row->addWidget(pause_);
    job_row->addWidget(resume_);
    job_row->addWidget(cancel_);
    job_row->addStretch();
    job_row->addWidget(page_);
    job_row->addWidget(from_page_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(device_row);
    layout->addWidget(status_);
    layout->addWidget(fault_);
    layout->addWidget(queue_, 2);
    layout->addLayout(job_row);
    auto* log_label = new QLabel(tr("Lin&k log (for technicians):"), this);
    log_label->setBuddy(log_);
    layout->addWidget(log_label);
    layout->addWidget(log_, 1);

    connect(refresh, &QPushButton::clicked, this, &PrinterPanel::refresh_devices);
    connect(connect_, &QPushButton::clicked, this, [this] {
        if (connected()) disconnect_device();
        else connect_device(selected_device(), profile::default_profile());
    });
    connect(pause_, &QPushButton::clicked, this, &PrinterPanel::pause_job);
    connect(resume_, &QPushButton::clicked, this, &PrinterPanel::resume_job);
    connect(cancel_, &QPushButton::clicked, this, &PrinterPanel::cancel_job);
    connect(from_page_, &QPushButton::clicked, this, [this] { resume_from_page(page_->value()); });
    status_timer_.setInterval(1000);
    connect(&status_timer_, &QTimer::timeout, this, &PrinterPanel::poll_status);
    update_buttons();
    refresh_devices();
    select_device(QSettings().value(QStringLiteral("printer/last"), QStringLiteral("sim")).toString());
}

PrinterPanel::~PrinterPanel() {
    if (running_) {
        running_->cancel.cancel();
        running_->watcher.waitForFinished();
    }
}

void PrinterPanel::refresh_devices() {
    const auto current = selected_device();
    std::vector<std::string> problems;
    const auto found = list_devices(&problems);
    devices_->clear();
    for (const auto& d : found)
        devices_->addItem(QStringLiteral("%1 [%2]").arg(QString::fromStdString(d.description), QString::fromStdString(d.device)),
                          QString::fromStdString(d.device));
    for (const auto& p : problems) log(tr("Listing devices: %1").arg(QString::fromStdString(p)));
    select_device(current);
}

QString PrinterPanel::selected_device() const { return devices_->currentData().toString(); }

void PrinterPanel::select_device(const QString& device) {
    const int i = devices_->findData(device);
    if (i >= 0) devices_->setCurrentIndex(i);
}

void PrinterPanel::log(const QString& line) {
    log_->appendPlainText(QStringLiteral("%1  %2").arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss.zzz")), line));
}

QString PrinterPanel::log_text() const { return log_->toPlainText(); }
QString PrinterPanel::fault_text() const { return fault_->text(); }

void PrinterPanel::set_status(const QString& text) {
    if (status_->text() != text) status_->setText(text);  // an unchanged text sends no event
}

void PrinterPanel::show_fault(const QString& text) {
    fault_->setText(text);
    if (!text.isEmpty()) Q_EMIT message(text, true);
}

bool PrinterPanel::connect_device(const QString& device, const profile::PrinterProfile& p) {
    if (running_) return false;
    disconnect_device();
    log(tr("Connecting to %1").arg(device));
    auto e = Embosser::connect(device.toStdString(), p);
    if (!e) {
        const auto why = QString::fromStdString(e.error().to_string());
        log(why);
        show_fault(tr("Cannot connect to %1: %2. Check that it is switched on and plugged in, then try again.").arg(device, why));
        return false;
    }
    embosser_.emplace(std::move(*e));
    QSettings().setValue(QStringLiteral("printer/last"), device);
    select_device(device);
    connect_->setText(tr("Dis&connect"));
    fault_->clear();
    poll_status();
    status_timer_.start();
    Q_EMIT message(tr("Connected to %1").arg(devices_->currentText()), false);
    start_next();
    return true;
}

void PrinterPanel::disconnect_device() {
    if (running_) cancel_job();
    status_timer_.stop();
    if (embosser_) log(tr("Disconnected from %1").arg(QString::fromStdString(embosser_->device())));
    embosser_.reset();
    connect_->setText(tr("&Connect"));
    set_status(tr("Not connected"));
    update_buttons();
}

void PrinterPanel::poll_status() {
    if (!embosser_ || running_) return;  // during a job the link reports status itself
    auto s = embosser_->status();
    if (!s) {
        const auto why = QString::fromStdString(s.error().to_string());
        log(why);
        set_status(tr("No answer from the embosser"));
        show_fault(tr("The embosser does not answer (%1). Check the cable and the power switch.").arg(why));
        return;
    }
    set_status(tr("Connected to %1: %2").arg(QString::fromStdString(embosser_->device()),
                                              QString::fromStdString(explain_status(*s))));
}

int PrinterPanel::enqueue(const QString& name, const layout::PagedDocument& pages, const profile::PrinterProfile& p,
                          std::size_t start_sheet) {
    QueuedJob j;
    j.id = next_id_++;
    j.name = name;
    j.pages = std::make_shared<const layout::PagedDocument>(pages);
    j.profile = p;
    j.start_sheet = start_sheet;
    j.resume_sheet = start_sheet;
    jobs_.push_back(j);
    const int row = queue_->rowCount();
    queue_->insertRow(row);
    queue_->setItem(row, 0, new QTableWidgetItem(name));
    queue_->setItem(row, 1, new QTableWidgetItem);
    auto* bar = new QProgressBar(queue_);
    bar->setAccessibleName(tr("Progress of %1").arg(name));
    bar->setRange(0, 100);
    bar->setValue(0);
    queue_->setCellWidget(row, 2, bar);
    queue_->setItem(row, 3, new QTableWidgetItem);
    update_row(jobs_.back());
    queue_->selectRow(row);
    log(tr("Queued %1 (job %2) from sheet %3").arg(name).arg(j.id).arg(start_sheet));
    Q_EMIT message(tr("%1 added to the queue").arg(name), false);
    start_next();
    return j.id;
}

QueuedJob* PrinterPanel::job(int id) {
    for (auto& j : jobs_)
        if (j.id == id) return &j;
    return nullptr;
}

QueuedJob* PrinterPanel::selected_job() {
    const int row = queue_->currentRow();
    if (row >= 0 && row < static_cast<int>(jobs_.size())) return &jobs_[static_cast<std::size_t>(row)];
    return running_ ? job(running_->id) : nullptr;
}

void PrinterPanel::update_row(const QueuedJob& j) {
    const auto row = static_cast<int>(&j - jobs_.data());
    auto* bar = static_cast<QProgressBar*>(queue_->cellWidget(row, 2));
    const int pct = j.passes_total ? static_cast<int>(100 * j.passes_done / j.passes_total) : (j.state == QueuedJob::State::done ? 100 : 0);
    // The bar's value is what a screen reader reads; a description per update
    // only doubled the events (issue 14).
    if (bar->value() != pct) bar->setValue(pct);
    const auto state = state_text(j.state) + (j.message.isEmpty() ? QString() : QStringLiteral(": ") + j.message);
    if (queue_->item(row, 1)->text() != state) queue_->item(row, 1)->setText(state);
    const auto sheet = QString::number(j.resume_sheet);
    if (queue_->item(row, 3)->text() != sheet) queue_->item(row, 3)->setText(sheet);
    update_buttons();
}

void PrinterPanel::on_progress(int id, std::size_t done, std::size_t total, std::size_t sheet) {
    auto* j = job(id);
    if (!j) return;
    j->passes_done = done;
    j->passes_total = total;
    j->resume_sheet = sheet;
    if (!j->steps) j->steps = std::make_shared<ProgressSteps>(j->pages->sheet_count() + 1 - j->start_sheet);
    // The link reports every pass; the bar, the status and the screen reader
    // hear only the steps (issue 14: one event per strike flooded Orca).
    const auto step = j->steps->update(done, total, sheet + 1 - std::min(sheet, j->start_sheet));
    if (!step) return;
    update_row(*j);
    set_status(tr("Embossing %1: sheet %2 of %3, %4 percent")
                   .arg(j->name).arg(step->sheet).arg(step->sheets).arg(step->percent));
    if (j->steps->speak(ProgressSteps::Clock::now()))
        Q_EMIT message(step->by_sheet ? tr("%1: sheet %2 of %3").arg(j->name).arg(step->sheet).arg(step->sheets)
                                      : tr("%1: %2 percent, sheet %3 of %4")
                                            .arg(j->name).arg(step->percent / 10 * 10).arg(step->sheet).arg(step->sheets),
                       false);
}

void PrinterPanel::update_buttons() {
    const QueuedJob* r = running_ ? job(running_->id) : nullptr;
    const bool any_queued = std::any_of(jobs_.begin(), jobs_.end(),
                                        [](const QueuedJob& j) { return j.state == QueuedJob::State::queued; });
    const bool any_stopped = std::any_of(jobs_.begin(), jobs_.end(), [](const QueuedJob& j) {
        return j.state == QueuedJob::State::failed || j.state == QueuedJob::State::cancelled;
    });
    pause_->setEnabled(r && r->state == QueuedJob::State::running);
    resume_->setEnabled((r && r->state == QueuedJob::State::paused) || (!r && any_stopped));
    cancel_->setEnabled(r != nullptr || any_queued);
    from_page_->setEnabled(!jobs_.empty());
}

void PrinterPanel::start_next() {
    if (running_ || !embosser_) return;
    auto it = std::find_if(jobs_.begin(), jobs_.end(), [](const QueuedJob& j) { return j.state == QueuedJob::State::queued; });
    if (it == jobs_.end()) return;
    it->state = QueuedJob::State::running;
    it->message.clear();
    update_row(*it);
    fault_->clear();
    running_ = std::make_unique<Running>();
    running_->id = it->id;
    const int id = it->id;
    auto pages = it->pages;
    auto prof = it->profile;
    const auto start = it->start_sheet;
    auto* e = &*embosser_;
    auto* cancel = &running_->cancel;
    QPointer<PrinterPanel> self(this);
    log(tr("Embossing %1 from sheet %2").arg(it->name).arg(start));
    set_status(tr("Embossing %1").arg(it->name));
    Q_EMIT message(tr("Embossing %1").arg(it->name), false);
    // Progress crosses to the GUI thread as queued calls; the worker touches no widget.
    const auto post = [self](std::function<void(PrinterPanel&)> f) {
        QMetaObject::invokeMethod(qApp, [self, f = std::move(f)] {
            if (self) f(*self);
        }, Qt::QueuedConnection);
    };
    connect(&running_->watcher, &QFutureWatcher<Outcome>::finished, this, [this, id] { finished_job(id); });
    update_buttons();  // Pause and Cancel now reach the running job
    running_->watcher.setFuture(QtConcurrent::run([=]() -> Outcome {
        Outcome out;
        auto plan = plan::plan_job(*pages, prof);
        if (!plan) {
            out.message = tr("Cannot plan the job: %1").arg(QString::fromStdString(plan.error().to_string()));
            out.resume_sheet = start;
            return out;
        }
        const auto log_before = e->simulator() ? e->simulator()->strike_log().size() : 0;
        post([id, total = std::accumulate(plan->sheets.begin(), plan->sheets.end(), std::size_t{0},
                                          [&](std::size_t n, const plan::SheetPlan& s) {
                                              return s.index >= start ? n + s.passes.size() : n;
                                          }),
              sheets = static_cast<std::size_t>(std::count_if(plan->sheets.begin(), plan->sheets.end(),
                                                              [&](const plan::SheetPlan& s) { return s.index >= start; }))](
                 PrinterPanel& p) {
            if (auto* j = p.job(id)) {
                j->passes_total = total;
                j->steps = std::make_shared<ProgressSteps>(sheets);
                p.update_row(*j);
            }
        });
        auto result = e->link().send_job(*plan, start, [&](const link::Progress& pr) {
            if (pr.executed) {
                const auto done = pr.executed->passes_done, total = pr.executed->passes_total;
                const auto sheet = pr.executed->sheet;
                post([id, done, total, sheet](PrinterPanel& p) { p.on_progress(id, done, total, sheet); });
                return;
            }
            const auto note = QString::fromStdString(pr.note);
            const auto faults = pr.status.ack.faults;
            post([note, faults](PrinterPanel& p) {
                p.log(note);
                if (faults) p.show_fault(QString::fromStdString(explain_faults(faults)));
            });
        }, *cancel);
        if (!result) {
            out.message = QString::fromStdString(result.error().to_string());
            out.resume_sheet = start;
            return out;
        }
        out.passes_done = result->passes_done;
        out.resume_sheet = result->resume_sheet ? result->resume_sheet : start;
        out.completed = result->end == link::JobEnd::completed;
        out.cancelled = result->end == link::JobEnd::cancelled;
        const auto& st = result->stats;
        post([st](PrinterPanel& p) {
            p.log(tr("Link: %1 frames sent, %2 resent, %3 bytes, %4 NAKs, %5 timeouts, %6 reconnects, %7 restarts")
                      .arg(st.frames_sent).arg(st.frames_resent).arg(st.bytes_written).arg(st.naks)
                      .arg(st.timeouts).arg(st.reconnects).arg(st.restarts));
        });
        if (result->end == link::JobEnd::failed) {
            const auto& err = result->error;
            out.message = QString::fromStdString(err.to_string());
        }
        if (out.completed && e->simulator()) {
            // The simulator logs every dot it struck: compare with what was planned.
            auto expected = controller::planned_strikes(*plan);
            expected.erase(std::remove_if(expected.begin(), expected.end(),
                                          [&](const controller::LoggedStrike& s) { return s.sheet < start; }),
                           expected.end());
            const auto& log = e->simulator()->strike_log();
            const std::vector<controller::LoggedStrike> got(log.begin() + static_cast<std::ptrdiff_t>(log_before), log.end());
            out.check = got == expected ? tr("all %1 strikes checked against the plan").arg(got.size())
                                        : tr("%1 strikes embossed but %2 planned: the simulator disagrees with the plan")
                                              .arg(got.size()).arg(expected.size());
        }
        return out;
    }));
}

void PrinterPanel::finished_job(int id) {
    const auto out = running_->watcher.result();
    running_.reset();
    auto* j = job(id);
    if (!j) return;
    j->passes_done = out.completed ? j->passes_total : j->passes_done;
    j->resume_sheet = out.resume_sheet;
    QString text;
    if (out.completed) {
        j->state = QueuedJob::State::done;
        j->message = out.check;
        text = tr("Embossed %1").arg(j->name) + (out.check.isEmpty() ? QString() : QStringLiteral(": ") + out.check);
    } else if (out.cancelled) {
        j->state = QueuedJob::State::cancelled;
        text = tr("%1 cancelled; resume from sheet %2").arg(j->name).arg(j->resume_sheet);
    } else {
        j->state = QueuedJob::State::failed;
        j->message = out.message;
        text = tr("%1 stopped at sheet %2: %3. The queue is kept; fix the problem, then resume from sheet %2.")
                   .arg(j->name).arg(j->resume_sheet).arg(out.message);
        show_fault(text);
    }
    update_row(*j);
    // "idle" again, now that the job is over; after a failure the fault stays what was said.
    if (j->state != QueuedJob::State::failed) poll_status();
    log(text);
    Q_EMIT message(text, j->state == QueuedJob::State::failed);
    Q_EMIT job_finished(id, out.completed, text);
    // After a failure the queue waits: the next job would meet the same problem.
    if (j->state != QueuedJob::State::failed) start_next();
}

void PrinterPanel::pause_job() {
    if (!running_ || !embosser_) return;
    embosser_->link().request_pause();
    if (auto* j = job(running_->id)) {
        j->state = QueuedJob::State::paused;
        update_row(*j);
    }
    log(tr("Pause requested: the embosser stops at the end of the current move"));
    Q_EMIT message(tr("Pausing"), false);
}

void PrinterPanel::resume_job() {
    if (running_ && embosser_) {
        embosser_->link().request_resume();
        if (auto* j = job(running_->id)) {
            j->state = QueuedJob::State::running;
            update_row(*j);
        }
        log(tr("Resume requested"));
        Q_EMIT message(tr("Resuming"), false);
        return;
    }
    // A stopped or cancelled job starts again where it stopped.
    if (auto* j = selected_job(); j && (j->state == QueuedJob::State::failed || j->state == QueuedJob::State::cancelled))
        resume_from_page(static_cast<int>(j->pages->geometry.first_page_of_sheet(j->resume_sheet) + 1));
}

void PrinterPanel::cancel_job() {
    if (running_) {
        running_->cancel.cancel();
        embosser_->link().request_resume();  // a paused job must run to notice the cancel
        log(tr("Cancel requested"));
        return;
    }
    if (auto* j = selected_job(); j && j->state == QueuedJob::State::queued) {
        j->state = QueuedJob::State::cancelled;
        update_row(*j);
    }
}

void PrinterPanel::resume_from_page(int page) {
    auto* j = selected_job();
    if (!j || j->state == QueuedJob::State::running || j->state == QueuedJob::State::paused) return;
    // Braille page numbers count from 1; a page before the first is no sheet.
    const auto sheet = page < 1 ? 0 : j->pages->geometry.sheet_of_page(static_cast<std::size_t>(page) - 1);
    if (sheet < 1 || sheet > j->pages->sheet_count()) {
        Q_EMIT message(tr("Page %1 is not in %2 (it has %3 pages)").arg(page).arg(j->name).arg(j->pages->pages.size()), true);
        return;
    }
    // Copies: enqueue grows jobs_, which moves the job `j` points at.
    const auto name = j->name;
    const auto pages = j->pages;
    const auto prof = j->profile;
    enqueue(name, *pages, prof, sheet);
}

}  // namespace tactus::gui
