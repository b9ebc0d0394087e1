// SPDX-License-Identifier: GPL-3.0-or-later
#include "book_view.hpp"

#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>

#include "edit/live_layout.hpp"
#include "import/import.hpp"
#include "pipeline/book_choice.hpp"
#include "pipeline/page_range.hpp"

namespace tactus::gui {

namespace {
// Long enough to let a burst of typing end before the book is laid out again.
constexpr int kSettleMs = 400;

// What a background layout hands back to the GUI thread.
struct Outcome {
    std::optional<pipeline::BookLayout> book;
    QString error;
    bool stopped = false;
};

Outcome lay_out(const document::Document& doc, const layout::LayoutOptions& layout, const pipeline::BookOptions& book,
                const translate::Translator& translator, const pipeline::BookProgress& progress) {
    Outcome out;
    auto laid = pipeline::lay_out_book(doc, layout, book, translator, progress);
    if (!laid)
        out.error = QString::fromStdString(laid.error().to_string());
    else if (!*laid)
        out.stopped = true;
    else {
        out.book = std::move(**laid);
        out.book->pages.metadata = doc.metadata;
    }
    return out;
}
}  // namespace

// A copy of what the layout reads, so the editor may change meanwhile.
struct BookView::Inputs {
    document::Document doc;
    layout::LayoutOptions layout;
    translate::Translator translator;
    std::string source;
};

struct BookView::Job {
    std::shared_ptr<std::atomic_bool> stop = std::make_shared<std::atomic_bool>(false);
    QPointer<QFutureWatcher<Outcome>> watcher;
};

BookView::BookView(QObject* parent) : QObject(parent) {
    timer_.setSingleShot(true);
    timer_.setInterval(kSettleMs);
    connect(&timer_, &QTimer::timeout, this, &BookView::start);
}

BookView::~BookView() { stop_job(); }

void BookView::set_source(std::function<const edit::LiveLayout*()> layout, std::function<QString()> file_name) {
    layout_ = std::move(layout);
    file_name_ = std::move(file_name);
}

void BookView::set_options(const pipeline::BookOptions& options) {
    options_ = options;
    start();
}

void BookView::schedule() { timer_.start(); }

void BookView::show_plain() {
    book_.reset();
    book_source_.clear();
    labels_.clear();
    if (const auto* live = layout_ ? layout_() : nullptr) labels_ = pipeline::page_labels(live->paged());
    Q_EMIT changed();
}

std::optional<BookView::Inputs> BookView::decide() {
    const auto* live = layout_ ? layout_() : nullptr;
    error_.clear();
    if (!live) {
        show_plain();
        return std::nullopt;
    }
    const auto name = file_name_ ? file_name_().toStdString() : std::string{};
    const auto format = import::detect_source_format({}, name);
    if (!pipeline::lays_out_as_book(format, live->ready_braille(), live->paged().pages.size(), options_,
                                    live->options().geometry)) {
        show_plain();
        return std::nullopt;
    }
    // Another document's book is not shown while this one's is laid out; the
    // same document's stays until its new layout replaces it.
    if (book_ && book_source_ != name) show_plain();
    return Inputs{live->document(), live->options(), live->translator(), name};
}

void BookView::adopt(std::optional<pipeline::BookLayout> book, const QString& error, const std::string& source) {
    book_ = std::move(book);
    book_source_ = book_ ? source : std::string{};
    error_ = error;
    labels_.clear();
    if (book_)
        labels_ = pipeline::page_labels(*book_);
    else if (const auto* live = layout_ ? layout_() : nullptr)
        labels_ = pipeline::page_labels(live->paged());
    Q_EMIT changed();
}

void BookView::stop_job() {
    if (!job_) return;
    job_->stop->store(true);
    if (job_->watcher) job_->watcher->disconnect(this);
    job_.reset();
}

void BookView::cancel() {
    timer_.stop();
    if (!job_) return;
    stop_job();
    Q_EMIT ended(false);
}

void BookView::refresh_now() {
    timer_.stop();
    const bool was_running = running();
    stop_job();
    auto in = decide();
    if (in) {
        auto out = lay_out(in->doc, in->layout, options_, in->translator, {});
        adopt(std::move(out.book), out.error, in->source);
    }
    if (was_running) Q_EMIT ended(in.has_value());
}

void BookView::start() {
    timer_.stop();
    const bool was_running = running();
    stop_job();
    auto in = decide();
    if (!in) {
        if (was_running) Q_EMIT ended(false);
        return;
    }
    auto job = std::make_shared<Job>();
    auto* watcher = new QFutureWatcher<Outcome>(this);
    job->watcher = watcher;
    connect(watcher, &QFutureWatcher<Outcome>::progressValueChanged, this, [this, job](int v) {
        if (job_ == job) Q_EMIT progressed(v);
    });
    connect(watcher, &QFutureWatcher<Outcome>::finished, this, [this, job, watcher, source = in->source] {
        watcher->deleteLater();
        if (job_ != job) return;  // a newer layout replaced this one
        job_.reset();
        if (watcher->future().resultCount() == 0) {
            Q_EMIT ended(false);
            return;
        }
        auto out = watcher->future().takeResult();
        if (out.stopped) {
            Q_EMIT ended(false);
            return;
        }
        adopt(std::move(out.book), out.error, source);
        Q_EMIT ended(true);
    });
    job_ = job;
    auto future = QtConcurrent::run([in = std::move(*in), book = options_, stop = job->stop](QPromise<Outcome>& promise) {
        promise.setProgressRange(0, 100);
        int said = -1;
        promise.addResult(lay_out(in.doc, in.layout, book, in.translator, [&](std::size_t done, std::size_t total) {
            const int percent = total ? static_cast<int>(100 * done / total) : 100;
            if (percent != said) promise.setProgressValue(said = percent);
            return stop->load() || promise.isCanceled();
        }));
    });
    watcher->setFuture(future);
    Q_EMIT started();
}

const layout::PagedDocument* BookView::shown(const layout::PagedDocument* plain) const {
    return book_ ? &book_->pages : plain;
}

const std::vector<pipeline::VolumeRange>& BookView::volumes() const {
    static const std::vector<pipeline::VolumeRange> none;
    return book_ ? book_->volumes : none;
}

std::size_t BookView::volume_of(std::size_t page) const {
    const auto& v = volumes();
    for (std::size_t i = v.size(); i-- > 0;)
        if (page >= v[i].first_page) return i;
    return 0;
}

QString BookView::place(std::size_t page) const {
    if (!book_ || page >= labels_.size()) return {};
    const auto volume = volume_of(page);
    const auto& label = labels_[page];
    return label.empty() ? tr("Volume %1 of %2, blank page").arg(volume + 1).arg(volumes().size())
                         : tr("Volume %1 of %2, page %3")
                               .arg(volume + 1)
                               .arg(volumes().size())
                               .arg(QString::fromStdString(label));
}

}  // namespace tactus::gui
