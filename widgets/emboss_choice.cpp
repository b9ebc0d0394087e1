// SPDX-License-Identifier: GPL-3.0-or-later
#include "emboss_choice.hpp"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

#include "entry_focus.hpp"
#include "pipeline/page_range.hpp"
#include "status_label.hpp"

namespace tactus::gui {

EmbossChoice::EmbossChoice(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("embossChoice"));
    scope_ = new QComboBox(this);
    scope_->setObjectName(QStringLiteral("embossScope"));
    scope_->setAccessibleName(tr("Emboss"));
    scope_->setAccessibleDescription(tr("The whole document, one volume of a book, or a range of braille pages"));
    range_ = new QLineEdit(this);
    range_->setObjectName(QStringLiteral("embossPages"));
    range_->setAccessibleName(tr("Braille pages to emboss"));
    range_->setAccessibleDescription(
        tr("As the pages are numbered: 3-10, 5- (to the end), 7; in a book t1 for the title page, p1-p2 for the contents"));
    range_->setPlaceholderText(tr("e.g. 3-10, 5-, p1-p2"));
    speak_entry_on_focus(range_);
    auto* range_label = new QLabel(tr("Pages:"), this);
    range_label->setBuddy(range_);
    auto* scope_label = new QLabel(tr("Em&boss:"), this);
    scope_label->setBuddy(scope_);
    summary_ = new QLabel(this);
    summary_->setObjectName(QStringLiteral("embossChoiceSummary"));
    summary_->setWordWrap(true);
    expose_status(summary_, tr("To emboss"));

    auto* row = new QHBoxLayout;
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(scope_label);
    row->addWidget(scope_, 1);
    row->addWidget(range_label);
    row->addWidget(range_, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(row);
    layout->addWidget(summary_);

    connect(scope_, &QComboBox::currentIndexChanged, this, &EmbossChoice::update_summary);
    // Said when the choice is made, not at every key typed.
    connect(scope_, &QComboBox::activated, this, [this] { Q_EMIT said(summary()); });
    connect(range_, &QLineEdit::returnPressed, this, [this] {
        said_range_ = range_->text();
        Q_EMIT said(summary());
    });
    connect(range_, &QLineEdit::editingFinished, this, [this] {
        // Leaving a range that was changed says it too, once.
        if (range_->text() == said_range_) return;
        said_range_ = range_->text();
        Q_EMIT said(summary());
    });
    connect(range_, &QLineEdit::textEdited, this, &EmbossChoice::update_summary);
    update_choices();
}

void EmbossChoice::set_pages(std::vector<std::string> labels, std::vector<pipeline::VolumeRange> volumes,
                             const layout::PageGeometry& geometry) {
    const bool same_volumes = volumes.size() == volumes_.size();
    labels_ = std::move(labels);
    volumes_ = std::move(volumes);
    geometry_ = geometry;
    if (same_volumes) update_summary();
    else update_choices();
}

void EmbossChoice::update_choices() {
    const QSignalBlocker quiet(scope_);
    const auto was_range = scope_->count() > 0 && scope_->currentIndex() == scope_->count() - 1;
    scope_->clear();
    scope_->addItem(tr("Whole document"));
    if (volumes_.size() > 1)
        for (std::size_t v = 0; v < volumes_.size(); ++v)
            scope_->addItem(tr("Volume %1 of %2").arg(v + 1).arg(volumes_.size()));
    scope_->addItem(tr("Page range"));
    scope_->setCurrentIndex(was_range ? scope_->count() - 1 : 0);
    update_summary();
}

void EmbossChoice::choose_whole() { scope_->setCurrentIndex(0); }

void EmbossChoice::choose_volume(std::size_t volume) {
    if (volumes_.size() > 1 && volume < volumes_.size()) scope_->setCurrentIndex(static_cast<int>(volume) + 1);
}

void EmbossChoice::choose_range(const QString& range) {
    range_->setText(range);
    scope_->setCurrentIndex(scope_->count() - 1);
    update_summary();
}

Result<std::pair<std::size_t, std::size_t>> EmbossChoice::chosen() const {
    const int index = scope_->currentIndex();
    if (index <= 0) return std::pair<std::size_t, std::size_t>{0, 0};
    if (index < scope_->count() - 1) {
        const auto& v = volumes_[static_cast<std::size_t>(index - 1)];
        return std::pair{v.first_page + 1, v.end_page};
    }
    auto range = pipeline::parse_page_range(range_->text().toStdString());
    if (!range) return std::unexpected(range.error());
    return pipeline::find_page_range(labels_, *range);
}

QString EmbossChoice::summary() const { return summary_->text(); }

void EmbossChoice::update_summary() {
    const auto pages = chosen();
    QString text;
    const int index = scope_->currentIndex();
    if (!pages) {
        text = tr("No pages chosen: %1").arg(QString::fromStdString(pages.error().message));
    } else {
        const auto [first, last] = *pages;
        const auto count = first == 0 ? labels_.size() : last - first + 1;
        const auto sheets = static_cast<int>(geometry_.sheets_for_pages(count));
        if (index <= 0)
            text = tr("Whole document: %n sheet(s)", nullptr, sheets);
        else if (index < scope_->count() - 1)
            text = tr("Volume %1 of %2: %n sheet(s)", nullptr, sheets).arg(index).arg(volumes_.size());
        else {
            const auto name = [this](std::size_t page) {
                return page - 1 < labels_.size() ? QString::fromStdString(labels_[page - 1]) : QString();
            };
            text = tr("Pages %1 to %2: %n sheet(s)", nullptr, sheets).arg(name(first), name(last));
        }
    }
    if (summary_->text() != text) summary_->setText(text);
    // The range is typed only once "Page range" is chosen: with it in the Tab
    // order always, Tab from the choice landed in an entry Orca did not speak
    // (Qt sends the entry's caret event before its focus event, and Orca 43
    // then takes the focus as already there), so the printer panel's next
    // controls went unheard to a user who only passed through.
    range_->setEnabled(index == scope_->count() - 1);
    Q_EMIT changed();
}

}  // namespace tactus::gui
