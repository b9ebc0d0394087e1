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
    // Measured here, not with heightForWidth(): QLabel answers that from a
    // size it cached at an earlier width, and the bar stayed five lines tall
    // after a message first laid out while the window was still narrow.
    const auto margins = contentsMargins();
    const int width = std::max(1, this->width() - margins.left() - margins.right() - 2 * margin());
    const int lines = text().isEmpty() ? fontMetrics().height()
                                       : fontMetrics().boundingRect(QRect(0, 0, width, 1 << 20),
                                                                    Qt::TextWordWrap | Qt::AlignLeft, text()).height();
    const int height = std::max(lines, fontMetrics().height()) + margins.top() + margins.bottom() + 2 * margin();
    if (height != this->height() || minimumHeight() != height) setFixedHeight(height);
}

}  // namespace tactus::gui
