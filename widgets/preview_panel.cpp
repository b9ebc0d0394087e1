// SPDX-License-Identifier: GPL-3.0-or-later
#include "preview_panel.hpp"

#include <QAction>
#include <QActionGroup>
#include <QLabel>
#include <QScrollArea>
#include <QToolBar>
#include <QVBoxLayout>

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
    auto* view_bar = new QToolBar(tr("View"), this);
    view_bar->setObjectName(QStringLiteral("previewViewBar"));
    view_bar->setAccessibleName(tr("Preview view controls"));
    view_bar->addActions({zoom_out_, zoom_in_, contrast_, pdf_});
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
    update_label();
}

QList<QAction*> PreviewPanel::view_actions() const {
    return {front_, back_, both_, previous_, next_, zoom_in_, zoom_out_, contrast_, pdf_};
}

void PreviewPanel::update_label() { label_->setText(preview_->summary()); }

}  // namespace tactus::gui
