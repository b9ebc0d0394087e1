// SPDX-License-Identifier: GPL-3.0-or-later
#include "book_view.hpp"

#include "edit/live_layout.hpp"
#include "import/import.hpp"
#include "pipeline/book_choice.hpp"
#include "pipeline/page_range.hpp"

namespace tactus::gui {

namespace {
// Long enough to let a burst of typing end before the book is laid out again.
constexpr int kSettleMs = 400;
}  // namespace

BookView::BookView(QObject* parent) : QObject(parent) {
    timer_.setSingleShot(true);
    timer_.setInterval(kSettleMs);
    connect(&timer_, &QTimer::timeout, this, &BookView::refresh_now);
}

void BookView::set_source(std::function<const edit::LiveLayout*()> layout, std::function<QString()> file_name) {
    layout_ = std::move(layout);
    file_name_ = std::move(file_name);
}

void BookView::set_options(const pipeline::BookOptions& options) {
    options_ = options;
    refresh_now();
}

void BookView::schedule() { timer_.start(); }

void BookView::refresh_now() {
    timer_.stop();
    const auto* live = layout_ ? layout_() : nullptr;
    book_.reset();
    labels_.clear();
    error_.clear();
    if (live) {
        const auto& plain = live->paged();
        const auto name = file_name_ ? file_name_().toStdString() : std::string{};
        const auto format = import::detect_source_format({}, name);
        if (pipeline::lays_out_as_book(format, live->ready_braille(), plain.pages.size(), options_,
                                       live->options().geometry)) {
            auto doc = live->document();
            auto laid = pipeline::lay_out_book(doc, live->options(), options_, live->translator(), 1);
            if (laid) {
                laid->pages.metadata = doc.metadata;
                book_ = std::move(*laid);
                labels_ = pipeline::page_labels(*book_);
            } else {
                error_ = QString::fromStdString(laid.error().to_string());
            }
        }
        if (!book_) labels_ = pipeline::page_labels(plain);
    }
    Q_EMIT changed();
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
