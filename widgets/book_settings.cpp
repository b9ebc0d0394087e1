// SPDX-License-Identifier: GPL-3.0-or-later
#include "book_settings.hpp"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

#include "entry_focus.hpp"

namespace tactus::gui {

namespace {

// A volume of a single sheet cannot hold its own title page and contents
// (pipeline::lay_out_book refuses fewer than 2); a thousand is far past any
// binding (the rules suggest well under 100).
constexpr int kMinSheets = 2;
constexpr int kMaxSheets = 1000;

QSpinBox* spin(QWidget* parent, int low, int high, const QString& name, const QString& description) {
    auto* box = new QSpinBox(parent);
    box->setRange(low, high);
    box->setAccessibleName(name);
    box->setAccessibleDescription(description);
    return box;
}

QLineEdit* entry(QWidget* parent, const QString& name) {
    auto* line = new QLineEdit(parent);
    line->setAccessibleName(name);
    line->setPlaceholderText(BookSettingsDialog::tr("From the document"));
    speak_entry_on_focus(line);
    return line;
}

std::string text_of(const QLineEdit* line) { return line->text().trimmed().toStdString(); }

}  // namespace

BookSettingsDialog::BookSettingsDialog(const pipeline::BookOptions& current, QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("bookSettings"));
    setWindowTitle(tr("Book Settings"));
    setAccessibleName(windowTitle());
    setAccessibleDescription(
        tr("How a book is divided into volumes and what each volume starts with. A document is laid out as a book when it "
           "is an EPUB, HTML or DAISY book, or longer than one volume."));

    sheets_ = spin(this, kMinSheets, kMaxSheets, tr("Sheets per volume"),
                   tr("About this many sheets in each volume, its title page and contents included"));
    sheets_->setObjectName(QStringLiteral("bookSheetsPerVolume"));
    split_level_ = spin(this, 1, 6, tr("Volumes start at heading level"),
                        tr("1: only at chapters; 2: at chapters and sections"));
    split_level_->setObjectName(QStringLiteral("bookSplitLevel"));
    title_page_ = new QCheckBox(tr("&Title page in each volume"), this);
    title_page_->setObjectName(QStringLiteral("bookTitlePage"));
    contents_ = new QCheckBox(tr("&Contents pages in each volume"), this);
    contents_->setObjectName(QStringLiteral("bookContents"));
    contents_depth_ = spin(this, 1, 6, tr("Heading levels in the contents"), tr("1: chapters only"));
    contents_depth_->setObjectName(QStringLiteral("bookContentsDepth"));
    running_heads_ = new QCheckBox(tr("Runnin&g heads"), this);
    running_heads_->setObjectName(QStringLiteral("bookRunningHeads"));
    connect(contents_, &QCheckBox::toggled, contents_depth_, &QWidget::setEnabled);

    title_ = entry(this, tr("Title"));
    title_->setObjectName(QStringLiteral("bookTitle"));
    author_ = entry(this, tr("Author"));
    publisher_ = entry(this, tr("Publisher"));
    year_ = entry(this, tr("Year"));
    transcriber_ = new QLineEdit(this);
    transcriber_->setAccessibleName(tr("Transcribed by"));
    transcriber_->setPlaceholderText(tr("No such line"));
    speak_entry_on_focus(transcriber_);

    auto* rules = new QFormLayout;
    rules->addRow(tr("&Sheets per volume:"), sheets_);
    rules->addRow(tr("&Volumes start at heading level:"), split_level_);
    rules->addRow(title_page_);
    rules->addRow(contents_);
    rules->addRow(tr("&Heading levels in the contents:"), contents_depth_);
    rules->addRow(running_heads_);

    auto* page = new QGroupBox(tr("Title page (this document only)"), this);
    auto* lines = new QFormLayout(page);
    lines->addRow(tr("T&itle:"), title_);
    lines->addRow(tr("&Author:"), author_);
    lines->addRow(tr("&Publisher:"), publisher_);
    lines->addRow(tr("&Year:"), year_);
    lines->addRow(tr("Transcri&bed by:"), transcriber_);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel |
                                             QDialogButtonBox::RestoreDefaults,
                                         this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    // The rules' defaults; the title page's lines stay as typed.
    connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
            [this] { show_rules(pipeline::BookOptions{}); });

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(rules);
    layout->addWidget(page);
    layout->addWidget(buttons);
    show_options(current);
}

void BookSettingsDialog::show_options(const pipeline::BookOptions& o) {
    show_rules(o);
    title_->setText(QString::fromStdString(o.title));
    author_->setText(QString::fromStdString(o.author));
    publisher_->setText(QString::fromStdString(o.publisher));
    year_->setText(QString::fromStdString(o.year));
    transcriber_->setText(QString::fromStdString(o.transcriber));
}

void BookSettingsDialog::show_rules(const pipeline::BookOptions& o) {
    sheets_->setValue(o.sheets_per_volume);
    split_level_->setValue(o.split_level);
    title_page_->setChecked(o.title_page);
    contents_->setChecked(o.contents);
    contents_depth_->setValue(o.contents_depth);
    contents_depth_->setEnabled(o.contents);
    running_heads_->setChecked(o.running_heads);
}

pipeline::BookOptions BookSettingsDialog::options() const {
    pipeline::BookOptions o;
    o.sheets_per_volume = sheets_->value();
    o.split_level = split_level_->value();
    o.title_page = title_page_->isChecked();
    o.contents = contents_->isChecked();
    o.contents_depth = contents_depth_->value();
    o.running_heads = running_heads_->isChecked();
    o.title = text_of(title_);
    o.author = text_of(author_);
    o.publisher = text_of(publisher_);
    o.year = text_of(year_);
    o.transcriber = text_of(transcriber_);
    return o;
}

pipeline::BookOptions load_book_rules(const QSettings& s) {
    const pipeline::BookOptions d;
    pipeline::BookOptions o;
    const auto number = [&s](const char* key, int fallback, int low, int high) {
        bool ok = false;
        const int v = s.value(QLatin1String(key)).toInt(&ok);
        // A value out of range (a hand-edited file) is the default, not a clamp:
        // the user never chose the clamped value.
        return ok && v >= low && v <= high ? v : fallback;
    };
    o.sheets_per_volume = number("book/sheets_per_volume", d.sheets_per_volume, kMinSheets, kMaxSheets);
    o.split_level = number("book/split_level", d.split_level, 1, 6);
    o.contents_depth = number("book/contents_depth", d.contents_depth, 1, 6);
    o.title_page = s.value(QStringLiteral("book/title_page"), d.title_page).toBool();
    o.contents = s.value(QStringLiteral("book/contents"), d.contents).toBool();
    o.running_heads = s.value(QStringLiteral("book/running_heads"), d.running_heads).toBool();
    return o;
}

void save_book_rules(QSettings& s, const pipeline::BookOptions& o) {
    s.setValue(QStringLiteral("book/sheets_per_volume"), o.sheets_per_volume);
    s.setValue(QStringLiteral("book/split_level"), o.split_level);
    s.setValue(QStringLiteral("book/contents_depth"), o.contents_depth);
    s.setValue(QStringLiteral("book/title_page"), o.title_page);
    s.setValue(QStringLiteral("book/contents"), o.contents);
    s.setValue(QStringLiteral("book/running_heads"), o.running_heads);
}

pipeline::BookOptions without_title_lines(pipeline::BookOptions o) {
    o.title.clear();
    o.author.clear();
    o.publisher.clear();
    o.year.clear();
    o.transcriber.clear();
    return o;
}

}  // namespace tactus::gui
