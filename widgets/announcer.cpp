// SPDX-License-Identifier: GPL-3.0-or-later
#include "announcer.hpp"

#include <QAccessible>

namespace tactus::gui {

Announcer::Announcer(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("announcer"));
    setFocusPolicy(Qt::NoFocus);
    setFixedSize(0, 0);
}

void Announcer::announce(const QString& message) {
    message_ = message;
    ++count_;
    setAccessibleName(message);
    QAccessibleEvent changed(this, QAccessible::NameChanged);
    QAccessible::updateAccessibility(&changed);
    QAccessibleEvent show(this, QAccessible::ObjectShow);
    QAccessible::updateAccessibility(&show);
    Q_EMIT announced(message);
}

}  // namespace tactus::gui
