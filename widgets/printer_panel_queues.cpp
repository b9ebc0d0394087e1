// SPDX-License-Identifier: GPL-3.0-or-later
// The printer panel's remote CUPS queues: finding them (listed in the device
// picker after the cables), sending a document to one over IPP, and following
// the job on the server for the job view.
#include <QComboBox>
#include <QFile>
#include <QFutureWatcher>
#include <QLabel>
#include <QSettings>
#include <QTableWidget>
#include <QtConcurrent/QtConcurrentRun>

#include "ipp/queue_options.hpp"
#include "ipp/queue_uri.hpp"
#include "ipp/remote_queues.hpp"
#include "printer_panel.hpp"
#include "printer_panel_rows.hpp"

namespace tactus::gui {
using panel::col_job;
using panel::col_state;
using panel::joined;
using panel::kNetworkRole;
using panel::qs;
using panel::remote_state_text;

namespace {

// What discovery of the CUPS queues brings back to the GUI thread: the queues,
// or the server that did not answer and CUPS's reason (worded in the panel).
struct Discovered {
    std::vector<ipp::RemoteQueue> queues;
    bool failed = false;
    std::string server;
    std::string reason;
};

}  // namespace

QString panel::remote_state_text(ipp::RemoteJobState s) {
    switch (s) {
        case ipp::RemoteJobState::pending: return QObject::tr("waiting");
        case ipp::RemoteJobState::held: return QObject::tr("held");
        case ipp::RemoteJobState::processing: return QObject::tr("embossing");
        case ipp::RemoteJobState::stopped: return QObject::tr("stopped");
        case ipp::RemoteJobState::cancelled: return QObject::tr("cancelled");
        case ipp::RemoteJobState::aborted: return QObject::tr("aborted");
        case ipp::RemoteJobState::completed: return QObject::tr("done");
    }
    return {};
}

// The CUPS queues come from the server (and DNS-SD), which may take seconds
// or not answer: asked off the GUI thread, and listed after the cables.
void PrinterPanel::discover_queues() {
    if (discovering_) return;
    discovering_ = true;
    auto* watcher = new QFutureWatcher<Discovered>(this);
    connect(watcher, &QFutureWatcher<Discovered>::finished, this, [this, watcher] {
        watcher->deleteLater();
        discovering_ = false;
        const auto found = watcher->result();
        if (found.failed)
            log(tr("Cannot list the CUPS queues on %1: %2").arg(qs(found.server), qs(found.reason)));
        const auto current = selected_device();
        for (int i = devices_->count() - 1; i >= 0; --i)
            if (devices_->itemData(i, kNetworkRole).toBool()) devices_->removeItem(i);
        for (const auto& q : found.queues) {
            const auto name = qs(q.name), server = qs(q.server);
            auto text = tr("Network queue %1 on %2").arg(name, server);
            if (!q.info.empty() && q.info != q.name) text += QStringLiteral(" - ") + qs(q.info);
            devices_->addItem(QStringLiteral("%1 [%2]").arg(text, qs(q.uri)), qs(q.uri));
            const int i = devices_->count() - 1;
            devices_->setItemData(i, true, kNetworkRole);
            devices_->setItemData(i, tr("Network queue %1 on the CUPS server %2").arg(name, server),
                                  Qt::AccessibleTextRole);
            devices_->setItemData(i,
                                  tr("A Tactus queue on another computer: the document is sent there over "
                                     "the network and laid out with that embosser's profile"),
                                  Qt::AccessibleDescriptionRole);
            devices_->setItemData(i, qs(q.uri), Qt::ToolTipRole);
        }
        if (!current.isEmpty()) select_device(current);
        if (!found.failed)
            log(tr("%n Tactus queue(s) found on CUPS servers", nullptr, static_cast<int>(found.queues.size())));
    });
    watcher->setFuture(QtConcurrent::run([] {
        Discovered d;
        if (auto q = ipp::visible_tactus_queues()) d.queues = std::move(*q);
        else {
            d.failed = true;
            d.server = q.error().where;
            d.reason = q.error().message;
        }
        return d;
    }));
}

bool PrinterPanel::selected_is_queue() const { return ipp::is_queue_uri(selected_device().toStdString()); }

bool PrinterPanel::send_to_queue(const QString& title, const QString& file_name, const QByteArray& document,
                                 const QString& table) {
    const auto device = selected_device();
    auto queue = ipp::parse_queue_uri(device.toStdString());
    if (!queue) {
        show_fault(tr("“%1” is not a CUPS queue: %2").arg(device, qs(queue.error().to_string())));
        return false;
    }
    auto job = std::make_unique<QueueJob>();
    job->title = title;
    job->name = qs(queue->resource.substr(queue->resource.rfind('/') + 1));
    job->queue = tr("%1 at %2").arg(job->name, qs(queue->host));
    job->dir = std::make_unique<QTemporaryDir>();
    const auto path = job->dir->filePath(file_name);
    QFile file(path);
    if (!job->dir->isValid() || !file.open(QIODevice::WriteOnly) || file.write(document) != document.size() ||
        !file.flush()) {
        show_fault(tr("Cannot send %1: cannot write a copy to send (%2)").arg(title, file.errorString()));
        return false;
    }
    file.close();
    ipp::RemoteJobRequest request;
    request.file = path.toStdString();
    request.title = title.toStdString();
    if (!table.isEmpty()) request.options.emplace_back(std::string(ipp::option::braille_table), table.toStdString());
    auto* raw = job.get();
    raw->thread = std::thread([raw, queue = *queue, request] {
        ipp::FollowOptions options;
        options.stop = &raw->stop;
        auto end = ipp::send_and_follow(
            queue, request,
            [raw](int id) {
                std::lock_guard lock(raw->mutex);
                raw->sent_id = id;
            },
            [raw](const ipp::RemoteJobStatus& s) {
                std::lock_guard lock(raw->mutex);
                raw->changes.push_back(s);
            },
            raw->cancel, options);
        std::lock_guard lock(raw->mutex);
        raw->end = std::move(end);
    });
    QSettings().setValue(QStringLiteral("printer/last"), device);
    log(tr("Sending %1 to %2 (%3)").arg(title, raw->queue, device));
    Q_EMIT message(tr("Sending %1 to %2").arg(title, raw->queue), false);
    queue_jobs_.push_back(std::move(job));
    show_jobs();
    queue_->selectRow(queue_->rowCount() - 1);
    update_buttons();
    return true;
}

// The jobs on CUPS queues: what their threads saw since the last poll, told
// as the local jobs are (its start, sheets now and then, a wait, its end once).
void PrinterPanel::follow_queue_jobs() {
    bool changed = false;
    for (auto& owned : queue_jobs_) {
        auto& j = *owned;
        if (j.ended) continue;
        int sent = 0;
        std::vector<ipp::RemoteJobStatus> changes;
        std::optional<Result<ipp::RemoteJobStatus>> end;
        {
            std::lock_guard lock(j.mutex);
            sent = j.sent_id;
            changes.swap(j.changes);
            end = j.end;
        }
        if (sent && !j.id) {
            j.id = sent;
            j.dir.reset();  // the server has the document
            log(tr("Sent %1 to %2 as job %3").arg(j.title, j.queue).arg(sent));
            changed = true;
        }
        for (const auto& s : changes) {
            const bool new_state = !j.status || j.status->state != s.state;
            const auto message_text = qs(s.message.empty() ? s.reasons : s.message);
            if (new_state && s.state == ipp::RemoteJobState::processing) {
                Q_EMIT message(tr("Embossing %1 on %2").arg(j.title, j.queue), false);
                j.spoken_at = ProgressSteps::Clock::now();
            } else if (new_state && (s.state == ipp::RemoteJobState::held || s.state == ipp::RemoteJobState::stopped)) {
                show_fault(tr("%1 waits on %2: %3").arg(j.title, j.queue, message_text));
            } else if (!new_state && s.state == ipp::RemoteJobState::processing && s.sheets_completed > 0 &&
                       s.sheets_completed != j.status->sheets_completed) {
                // A step at most every few seconds, as for local jobs, so a screen reader is not flooded.
                const auto now = ProgressSteps::Clock::now();
                if (!j.spoken_at || now - *j.spoken_at >= std::chrono::seconds(3)) {
                    Q_EMIT message(tr("%1: %n sheet(s) embossed", nullptr, s.sheets_completed).arg(j.title), false);
                    j.spoken_at = now;
                }
            }
            if (s.state != ipp::RemoteJobState::processing || s.message != (j.status ? j.status->message : ""))
                log(tr("Job %1 on %2: %3").arg(j.id).arg(j.queue, joined(remote_state_text(s.state), message_text)) +
                    (s.reasons.empty() ? QString() : QStringLiteral(" (%1)").arg(qs(s.reasons))));
            j.status = s;
            changed = true;
        }
        if (!end) continue;
        j.ended = true;
        j.dir.reset();
        changed = true;
        if (!*end) {
            j.error = qs(end->error().to_string());
            const auto text = j.id ? tr("%1: the job on %2 can no longer be followed: %3").arg(j.title, j.queue, j.error)
                                   : tr("%1 was not sent to %2: %3").arg(j.title, j.queue, j.error);
            fault_->setText(text);  // announced once, below
            log(text);
            Q_EMIT message(text, true);
            Q_EMIT job_finished(j.id, false, text);
            continue;
        }
        const auto& last = **end;
        j.status = last;
        if (!last.ended()) continue;  // following stopped: the window closes
        const auto why = qs(last.why_ended());
        QString text;
        if (last.state == ipp::RemoteJobState::completed) {
            text = tr("Embossed %1 on %2").arg(j.title, j.queue);
        } else if (last.state == ipp::RemoteJobState::cancelled) {
            text = why.isEmpty() ? tr("%1 cancelled on %2").arg(j.title, j.queue)
                                 : tr("%1 cancelled on %2: %3").arg(j.title, j.queue, why);
        } else {
            text = tr("%1 stopped on %2: %3").arg(j.title, j.queue, why);
            fault_->setText(text);  // announced once, below
        }
        log(text);
        Q_EMIT message(text, last.state == ipp::RemoteJobState::aborted);
        Q_EMIT job_finished(j.id, last.state == ipp::RemoteJobState::completed, text);
    }
    if (changed) {
        show_jobs();
        update_buttons();
    }
}

std::vector<PrinterPanel::QueueJobRow> PrinterPanel::queue_jobs() const {
    std::vector<QueueJobRow> out;
    const int first = static_cast<int>(jobs_.size());
    for (std::size_t i = 0; i < queue_jobs_.size(); ++i) {
        const auto& j = *queue_jobs_[i];
        const int row = first + static_cast<int>(i);
        const auto cell = [&](int col) {
            const auto* item = queue_->item(row, col);
            return item ? item->text() : QString();
        };
        out.push_back({j.title, cell(col_job), j.queue, cell(col_state), j.ended});
    }
    return out;
}

PrinterPanel::QueueJob* PrinterPanel::selected_queue_job() const {
    const int row = selected_row() - shown_local_rows_;
    return row >= 0 && row < static_cast<int>(queue_jobs_.size()) ? queue_jobs_[static_cast<std::size_t>(row)].get()
                                                                   : nullptr;
}

}  // namespace tactus::gui
