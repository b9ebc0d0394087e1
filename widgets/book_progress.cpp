// SPDX-License-Identifier: GPL-3.0-or-later
#include "book_progress.hpp"

#include <utility>

#include <QHBoxLayout>
#include <QProgressBar>
#include <QToolButton>

#include "announcer.hpp"
#include "book_view.hpp"
#include "progress_steps.hpp"

namespace tactus::gui {

namespace {
// The steps are whole percents of the body translated; ProgressSteps counts
// them in tenths when told of ten or more "sheets".
constexpr std::size_t kTenths = 10;
}  // namespace

BookProgress::BookProgress(BookView* book, Announcer* announcer, std::function<void(const QString&)> say_end,
                           QWidget* parent)
    : QWidget(parent), book_(book), announcer_(announcer), say_end_(std::move(say_end)) {
    setObjectName(QStringLiteral("bookProgress"));
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    bar_ = new QProgressBar(this);
    bar_->setObjectName(QStringLiteral("bookProgressBar"));
    bar_->setRange(0, 100);
    bar_->setAccessibleName(tr("Laying out the book"));
    bar_->setMaximumWidth(160);
    cancel_ = new QToolButton(this);
    cancel_->setObjectName(QStringLiteral("bookCancel"));
    cancel_->setText(tr("Cancel book layout"));
    cancel_->setAccessibleName(tr("Cancel book layout"));
    row->addWidget(bar_);
    row->addWidget(cancel_);
    hide();
    connect(cancel_, &QToolButton::clicked, this, [this] {
        const bool running = book_->running();
        spoke_ = false;
        book_->cancel();
        if (running) announcer_->announce(tr("Book layout cancelled; the preview shows the pages laid out before"));
    });
    connect(book_, &BookView::started, this, &BookProgress::on_started);
    connect(book_, &BookView::progressed, this, &BookProgress::on_progress);
    connect(book_, &BookView::ended, this, &BookProgress::on_ended);
}

BookProgress::~BookProgress() = default;

void BookProgress::on_started() {
    // A layout that replaces a running one (an edit meanwhile) goes on in
    // the same bar and the same quiet time; its steps start again.
    steps_ = std::make_unique<ProgressSteps>(kTenths);
    if (!running_.isValid()) {
        running_.start();
        spoke_ = false;
    }
    bar_->setValue(0);
}

void BookProgress::on_progress(int percent) {
    if (!steps_) return;
    if (!steps_->update(static_cast<std::size_t>(percent), 100, 1)) return;
    // A layout that ends within the quiet time shows and says nothing: each
    // change of the bar is an event for the screen reader, and a short book
    // is laid out again after every pause in typing.
    if (running_.elapsed() < quiet_ms_) return;
    bar_->setValue(percent);
    show();
    if (steps_->speak(ProgressSteps::Clock::now())) {
        spoke_ = true;
        announcer_->announce(tr("Laying out the book: %1 percent").arg(percent));
    }
}

void BookProgress::opened(const QString& file_name, const QString& plain, const QString& suffix) {
    opened_ = Opened{file_name, plain, suffix};
}

void BookProgress::on_ended(bool done) {
    running_.invalidate();
    if (!isHidden()) hide();
    steps_.reset();
    const bool spoke = std::exchange(spoke_, false);
    const auto opened = std::exchange(opened_, std::nullopt);
    QString count;
    if (done && book_->active()) {
        const auto* pages = book_->shown(nullptr);
        count = tr("%n volume(s)", nullptr, static_cast<int>(book_->volumes().size())) + QStringLiteral(", ") +
                tr("%n sheet(s)", nullptr, static_cast<int>(pages ? pages->sheet_count() : 0));
    }
    if (opened) {
        say_end_(count.isEmpty() ? opened->plain + opened->suffix
                                 : tr("Opened %1: %2").arg(opened->file_name, count) + opened->suffix);
    } else if (spoke) {
        say_end_(!count.isEmpty()             ? tr("Book: %1").arg(count)
                 : !book_->error().isEmpty() ? tr("The book could not be laid out: %1").arg(book_->error())
                                             : tr("Book layout cancelled"));
    }
}

}  // namespace tactus::gui
