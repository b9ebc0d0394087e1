// SPDX-License-Identifier: GPL-3.0-or-later
#include "preview_panel.hpp"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QLabel>
#include <QScrollArea>
#include <QToolBar>
#include <QVBoxLayout>

#include "book_view.hpp"
#include "status_label.hpp"

namespace tactus::gui {

PreviewPanel::PreviewPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("previewPanel"));
    preview_ = new SheetPreview(this);
    scroll_ = new QScrollArea(this);
    scroll_->setObjectName(QStringLiteral("previewScroll"));
    scroll_->setAccessibleName(tr("Preview scroll area"));
    scroll_->setWidget(preview_);
    scroll_->setWidgetResizable(false);
    scroll_->setFocusPolicy(Qt::NoFocus);
    preview_->resize(preview_->sizeHint());

    const auto make = [this](const QString& text, const QKeySequence& key, const QString& name) {
        auto* a = new QAction(text, this);
        a->setShortcut(key);
        a->setShortcutContext(Qt::WindowShortcut);
        a->setObjectName(name);
        a->setToolTip(QStringLiteral("%1 (%2)").arg(QString(text).remove(QLatin1Char('&')),
                                                    key.toString(QKeySequence::NativeText)));
        return a;
    };
    auto* sides = new QActionGroup(this);
    front_ = make(tr("Fr&ont"), QKeySequence(tr("Ctrl+Alt+F")), QStringLiteral("viewFront"));
    back_ = make(tr("Bac&k"), QKeySequence(tr("Ctrl+Alt+B")), QStringLiteral("viewBack"));
    both_ = make(tr("Front &and back"), QKeySequence(tr("Ctrl+Alt+A")), QStringLiteral("viewBoth"));
    for (auto* a : {front_, back_, both_}) {
        a->setCheckable(true);
        sides->addAction(a);
    }
    both_->setChecked(true);
    previous_ = make(tr("Pr&evious sheet"), QKeySequence(tr("Ctrl+PgUp")), QStringLiteral("previousSheet"));
    next_ = make(tr("Ne&xt sheet"), QKeySequence(tr("Ctrl+PgDown")), QStringLiteral("nextSheet"));
    previous_volume_ = make(tr("Previou&s volume"), QKeySequence(tr("Ctrl+Alt+PgUp")), QStringLiteral("previousVolume"));
    next_volume_ = make(tr("Next vo&lume"), QKeySequence(tr("Ctrl+Alt+PgDown")), QStringLiteral("nextVolume"));
    zoom_in_ = make(tr("Zoom &in"), QKeySequence::ZoomIn, QStringLiteral("zoomIn"));
    zoom_out_ = make(tr("Zoom o&ut"), QKeySequence::ZoomOut, QStringLiteral("zoomOut"));
    contrast_ = make(tr("&High contrast"), QKeySequence(tr("Ctrl+Alt+H")), QStringLiteral("highContrast"));
    contrast_->setCheckable(true);
    pdf_ = make(tr("Print preview to P&DF..."), QKeySequence(tr("Ctrl+Alt+P")), QStringLiteral("printPdf"));

    connect(front_, &QAction::triggered, preview_, [this] { preview_->set_mode(SideMode::front); });
    connect(back_, &QAction::triggered, preview_, [this] { preview_->set_mode(SideMode::back); });
    connect(both_, &QAction::triggered, preview_, [this] { preview_->set_mode(SideMode::both); });
    connect(next_, &QAction::triggered, preview_, &SheetPreview::next_sheet);
    connect(previous_, &QAction::triggered, preview_, &SheetPreview::previous_sheet);
    connect(next_volume_, &QAction::triggered, this, [this] { go_to_volume(volume() + 1); });
    connect(previous_volume_, &QAction::triggered, this, [this] {
        if (volume() > 0) go_to_volume(volume() - 1);
    });
    connect(zoom_in_, &QAction::triggered, preview_, &SheetPreview::zoom_in);
    connect(zoom_out_, &QAction::triggered, preview_, &SheetPreview::zoom_out);
    connect(contrast_, &QAction::toggled, preview_, &SheetPreview::set_high_contrast);
    connect(pdf_, &QAction::triggered, this, &PreviewPanel::print_pdf_requested);

    // Two rows: in one, a dock of 1280 px hid "Print preview to PDF" behind
    // the toolbar's extension button, where a keyboard user never finds it.
    auto* bar = new QToolBar(tr("Preview"), this);
    bar->setObjectName(QStringLiteral("previewBar"));
    bar->setAccessibleName(tr("Preview controls"));
    bar->addActions({front_, back_, both_});
    bar->addSeparator();
    bar->addActions({previous_, next_});
    bar->addSeparator();
    bar->addActions({previous_volume_, next_volume_});
    // The volume chooser: a book's volumes by number, hidden for a document in one.
    volume_box_ = new QComboBox(this);
    volume_box_->setObjectName(QStringLiteral("volumeChooser"));
    volume_box_->setAccessibleName(tr("Volume"));
    volume_box_->setToolTip(tr("Go to volume (%1, %2)")
                                .arg(previous_volume_->shortcut().toString(QKeySequence::NativeText),
                                     next_volume_->shortcut().toString(QKeySequence::NativeText)));
    volume_box_action_ = nullptr;
    connect(volume_box_, &QComboBox::activated, this, [this](int index) {
        if (index >= 0) go_to_volume(static_cast<std::size_t>(index));
    });
    auto* view_bar = new QToolBar(tr("View"), this);
    view_bar->setObjectName(QStringLiteral("previewViewBar"));
    view_bar->setAccessibleName(tr("Preview view controls"));
    view_bar->addActions({zoom_out_, zoom_in_, contrast_, pdf_});
    // On the second row, where a dock of ordinary width still shows it.
    view_bar->addSeparator();
    volume_box_action_ = view_bar->addWidget(volume_box_);
    label_ = new QLabel(this);
    label_->setObjectName(QStringLiteral("previewLabel"));
    expose_status(label_, tr("Preview status"));

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(bar);
    layout->addWidget(view_bar);
    layout->addWidget(label_);
    layout->addWidget(scroll_, 1);

    connect(preview_, &SheetPreview::sheet_changed, this, &PreviewPanel::update_label);
    connect(preview_, &SheetPreview::cursor_moved, this, &PreviewPanel::update_label);
    // The side toggles follow the preview when the cursor turns the sheet.
    connect(preview_, &SheetPreview::cursor_moved, this, [this] {
        (preview_->mode() == SideMode::front ? front_
         : preview_->mode() == SideMode::back ? back_
                                              : both_)->setChecked(true);
    });
    update_volumes();
}

QList<QAction*> PreviewPanel::view_actions() const {
    return {front_, back_, both_, previous_, next_, previous_volume_, next_volume_, zoom_in_, zoom_out_, contrast_, pdf_};
}

void PreviewPanel::set_book(const BookView* book) {
    if (book_) disconnect(book_, nullptr, this, nullptr);
    book_ = book;
    if (book_) connect(book_, &BookView::changed, this, &PreviewPanel::update_volumes);
    update_volumes();
}

void PreviewPanel::update_volumes() {
    const auto count = book_ ? book_->volumes().size() : 0;
    if (static_cast<std::size_t>(volume_box_->count()) != count) {
        volume_box_->clear();
        for (std::size_t v = 0; v < count; ++v)
            volume_box_->addItem(tr("Volume %1 of %2").arg(v + 1).arg(count));
    }
    volume_box_action_->setVisible(count > 1);
    next_volume_->setEnabled(count > 1);
    previous_volume_->setEnabled(count > 1);
    update_label();
}

std::size_t PreviewPanel::volume() const {
    if (!book_ || !book_->active()) return 0;
    const auto page = preview_->cursor_page();
    return page == static_cast<std::size_t>(-1) ? 0 : book_->volume_of(page);
}

void PreviewPanel::go_to_volume(std::size_t volume) {
    if (!book_ || !book_->active()) return;
    const auto& volumes = book_->volumes();
    if (volume >= volumes.size()) {
        Q_EMIT announce(tr("Volume %1 of %2 is the last").arg(volumes.size()).arg(volumes.size()));
        return;
    }
    const auto* doc = preview_->document();
    if (!doc) return;
    preview_->set_sheet(doc->geometry.sheet_of_page(volumes[volume].first_page));
    update_label();
    // The volume's first page, whichever side the cell cursor is on.
    Q_EMIT announce(tr("%1; %2", "where in the book; the sheet")
                        .arg(book_->place(volumes[volume].first_page), preview_->summary()));
}

QString PreviewPanel::label_text() const {
    auto text = preview_->summary();
    if (book_ && book_->active()) {
        const auto page = preview_->cursor_page();
        if (page != static_cast<std::size_t>(-1)) text = tr("%1; %2", "where in the book; the sheet").arg(book_->place(page), text);
    }
    return text;
}

void PreviewPanel::update_label() {
    label_->setText(label_text());
    if (book_ && book_->active() && volume_box_->count() > 0) {
        const QSignalBlocker quiet(volume_box_);
        volume_box_->setCurrentIndex(static_cast<int>(volume()));
    }
}

}  // namespace tactus::gui
