// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The book the preview shows and the printer embosses: when the open document
// reads as a book (pipeline::lays_out_as_book, core's one rule: an EPUB, or a
// text longer than a volume), its book layout (pipeline::lay_out_book: title
// page, contents, p-numbered preliminary pages, volumes), laid out again a
// moment after the editor's layout changes; otherwise the editor's own pages.
// The editor keeps its plain layout: its lines map to those pages as they did.
//
// The layout runs on a worker thread (a whole Bible takes seconds, and the
// GUI thread must keep answering the screen reader meanwhile). It works on a
// copy of the document and its translator, so the editor may change under it:
// each new layout stops the one running, and only the newest result is shown.
#include <QFutureWatcher>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QTimer>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "layout/page.hpp"
#include "pipeline/book_layout.hpp"

namespace tactus::edit {
class LiveLayout;
}

namespace tactus::gui {

class BookView : public QObject {
    Q_OBJECT
public:
    explicit BookView(QObject* parent = nullptr);
    ~BookView() override;

    // Where the document comes from: the editor's layout and the file's name
    // (its extension says EPUB). Both are read when the book is laid out.
    void set_source(std::function<const edit::LiveLayout*()> layout, std::function<QString()> file_name);
    // The book's options (sheets per volume, ...); lays the book out again.
    void set_options(const pipeline::BookOptions& options);
    // The same, for the next layout: none is started (the caller starts one).
    void keep_options(const pipeline::BookOptions& options) { options_ = options; }
    [[nodiscard]] const pipeline::BookOptions& options() const { return options_; }

    // The editor's layout changed: the book follows shortly (edits come in bursts).
    void schedule();
    // Decides now, and lays the book out in the background; changed() follows
    // when it is ready (at once when the document is no book).
    void start();
    // Decides and lays out now, on this thread; emits changed().
    void refresh_now();
    // Lays out now if a change is waiting or running (before embossing what is shown).
    void flush() {
        if (timer_.isActive() || running()) refresh_now();
    }
    // Stops the layout running; the pages shown stay as they were.
    void cancel();
    [[nodiscard]] bool running() const { return job_ != nullptr; }

    // The document reads as a book and its book layout is ready.
    [[nodiscard]] bool active() const { return book_.has_value(); }
    // The pages to show and emboss: the book's, else `plain`.
    [[nodiscard]] const layout::PagedDocument* shown(const layout::PagedDocument* plain) const;
    [[nodiscard]] const std::vector<pipeline::VolumeRange>& volumes() const;
    // The number each shown page carries ("t1", "p2", "14"), for the page
    // range the printer panel takes; the plain pages' when no book.
    [[nodiscard]] const std::vector<std::string>& labels() const { return labels_; }
    // The volume (0-based) that holds page `page`; 0 without volumes.
    [[nodiscard]] std::size_t volume_of(std::size_t page) const;
    // "Volume 2 of 3, page p1" for a page of the book; empty when no book.
    [[nodiscard]] QString place(std::size_t page) const;
    // Why the book could not be laid out (the preview then shows the plain pages).
    [[nodiscard]] const QString& error() const { return error_; }

Q_SIGNALS:
    void changed();
    // A background layout began, moved on (whole percent of the body
    // translated), ended with a new book shown (`done`) or was stopped.
    void started();
    void progressed(int percent);
    void ended(bool done);

private:
    struct Job;
    struct Inputs;
    // What refresh_now() and start() both decide first: nullopt when there is
    // no book to lay out (the plain pages are then shown, changed() emitted).
    std::optional<Inputs> decide();
    void adopt(std::optional<pipeline::BookLayout> book, const QString& error, const std::string& source);
    void show_plain();
    void stop_job();

    std::function<const edit::LiveLayout*()> layout_;
    std::function<QString()> file_name_;
    pipeline::BookOptions options_;
    std::optional<pipeline::BookLayout> book_;
    std::string book_source_;  // the file the book shown was laid out from
    std::vector<std::string> labels_;
    QString error_;
    QTimer timer_;
    std::shared_ptr<Job> job_;
};

}  // namespace tactus::gui
