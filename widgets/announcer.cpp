// SPDX-License-Identifier: GPL-3.0-or-later
#include "announcer.hpp"

#include <QAccessible>
#include <QAccessibleWidget>

#include "sheet_preview.hpp"

namespace tactus::gui {
namespace {

class AccessibleAnnouncer : public QAccessibleWidget {
public:
    explicit AccessibleAnnouncer(Announcer* a) : QAccessibleWidget(a, QAccessible::Notification) {}
    QString text(QAccessible::Text t) const override {
        const auto* a = static_cast<const Announcer*>(object());
        switch (t) {
            case QAccessible::Name:
            case QAccessible::Description:
                return a->message();
            default:
                return QAccessibleWidget::text(t);
        }
    }
};

QAccessibleInterface* factory(const QString& classname, QObject* object) {
    if (classname == QLatin1String("tactus::gui::Announcer") && object->isWidgetType())
        return new AccessibleAnnouncer(static_cast<Announcer*>(object));
    if (classname == QLatin1String("tactus::gui::SheetPreview") && object->isWidgetType())
        return make_accessible_sheet_preview(static_cast<SheetPreview*>(object));
    return nullptr;
}

}  // namespace

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

void install_accessibility() { QAccessible::installFactory(factory); }

}  // namespace tactus::gui
