// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the printer panel's two source files share: its local spool jobs
// (printer_panel.cpp) and its jobs on remote CUPS queues
// (printer_panel_queues.cpp) are rows of one job view, worded alike.
#include <QString>
#include <QTemporaryDir>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "common/result.hpp"
#include "ipp/remote_job.hpp"
#include "progress_steps.hpp"

namespace tactus::gui::panel {

enum Column { col_job, col_document, col_printer, col_state, col_progress, col_sheet, col_count };

inline QString qs(const std::string& s) { return QString::fromStdString(s); }

// Item data of the device picker: a CUPS queue rather than a cable.
constexpr int kNetworkRole = Qt::UserRole + 1;

// A message and its detail ("Embossed a.md: all 120 strikes checked"), joined
// the interface language's way: Chinese takes a full-width colon and no space.
QString joined(const QString& head, const QString& detail);

// A job on a CUPS queue in the words of the job view (the local ones where
// they mean the same).
QString remote_state_text(ipp::RemoteJobState s);

}  // namespace tactus::gui::panel

namespace tactus::gui {

// A job sent to a CUPS queue: ipp::send_and_follow on a thread of its own,
// which only records what it sees here; the GUI thread reads it on its poll.
struct RemoteQueueJob {
    QString title;
    QString queue;  // "Embosser at 127.0.0.1", for messages and the view
    QString name;   // the queue's name: the job is "Embosser-12" on the server
    std::unique_ptr<QTemporaryDir> dir;  // the document, until the server has it
    std::atomic<bool> cancel{false};
    std::atomic<bool> stop{false};  // stop following: the window closes, the job goes on
    std::thread thread;
    std::mutex mutex;
    int sent_id = 0;                                  // written by the thread
    std::vector<ipp::RemoteJobStatus> changes;        // written by the thread, taken by the GUI
    std::optional<Result<ipp::RemoteJobStatus>> end;  // written by the thread
    // The GUI thread's own.
    int id = 0;
    std::optional<ipp::RemoteJobStatus> status;
    QString error;
    bool ended = false;
    bool cancelling = false;
    std::optional<ProgressSteps::Clock::time_point> spoken_at;

    ~RemoteQueueJob() {
        stop = true;
        if (thread.joinable()) thread.join();
    }
};

}  // namespace tactus::gui
