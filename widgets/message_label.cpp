// SPDX-License-Identifier: GPL-3.0-or-later
#include "message_label.hpp"

#include <QTimer>

namespace tactus::gui {

MessageLabel::MessageLabel(QWidget* parent) : QLabel(parent) {
    setObjectName(QStringLiteral("statusMessage"));
    setWordWrap(true);
    setTextFormat(Qt::PlainText);
    setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Wide as the bar allows; the height follows the wrapped text.
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    clear_ = new QTimer(this);
    clear_->setSingleShot(true);
    connect(clear_, &QTimer::timeout, this, [this] { show_message({}, 0); });
}

void MessageLabel::show_message(const QString& text, int timeout_ms) {
    setText(text);
    fit_height();
    if (timeout_ms > 0) clear_->start(timeout_ms);
    else clear_->stop();
}

void MessageLabel::resizeEvent(QResizeEvent* event) {
    QLabel::resizeEvent(event);
    fit_height();
}

void MessageLabel::fit_height() {
    const int lines = text().isEmpty() ? fontMetrics().height() : heightForWidth(std::max(1, width()));
    const int height = std::max(lines, fontMetrics().height()) + contentsMargins().top() + contentsMargins().bottom();
    if (height != this->height() || minimumHeight() != height) setFixedHeight(height);
}

}  // namespace tactus::gui
