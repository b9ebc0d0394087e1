// SPDX-License-Identifier: GPL-3.0-or-later
// Accessible interfaces for widgets Qt leaves without one: the announcer
// (Notification role), the sheet preview (a graphic with a text caret), and
// splitter handles, which otherwise show up with no role at all.
#include <QAccessible>
#include <QAccessibleWidget>
#include <QLabel>
#include <QSplitterHandle>

#include "announcer.hpp"
#include "sheet_preview.hpp"
#include "status_label.hpp"

namespace tactus::gui {
namespace {

class AccessibleAnnouncer : public QAccessibleWidget {
public:
    explicit AccessibleAnnouncer(Announcer* a) : QAccessibleWidget(a, QAccessible::Notification) {}
    QString text(QAccessible::Text t) const override {
        const auto* a = static_cast<const Announcer*>(object());
        if (t == QAccessible::Name) return a->message();
        // No description: screen readers cache it, so Orca spoke each new message
        // followed by the previous one.
        if (t == QAccessible::Description) return {};
        return QAccessibleWidget::text(t);
    }
};

class AccessibleSplitterHandle : public QAccessibleWidget {
public:
    explicit AccessibleSplitterHandle(QWidget* w) : QAccessibleWidget(w, QAccessible::Separator) {}
    QString text(QAccessible::Text t) const override {
        if (t == QAccessible::Name) return QObject::tr("Divider between print and braille");
        return QAccessibleWidget::text(t);
    }
};

QAccessibleInterface* factory(const QString& classname, QObject* object) {
    if (!object || !object->isWidgetType()) return nullptr;
    auto* w = static_cast<QWidget*>(object);
    if (classname == QLatin1String("tactus::gui::Announcer")) return new AccessibleAnnouncer(static_cast<Announcer*>(w));
    if (classname == QLatin1String("tactus::gui::SheetPreview"))
        return make_accessible_sheet_preview(static_cast<SheetPreview*>(w));
    if (classname == QLatin1String("QSplitterHandle")) return new AccessibleSplitterHandle(w);
    if (classname == QLatin1String("QLabel"))
        if (auto* l = static_cast<QLabel*>(w); !status_caption(l).isEmpty()) return make_accessible_status(l);
    return nullptr;
}

}  // namespace

void install_accessibility() { QAccessible::installFactory(factory); }

}  // namespace tactus::gui
