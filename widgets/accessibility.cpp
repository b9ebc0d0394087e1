// SPDX-License-Identifier: GPL-3.0-or-later
// Accessible interfaces for widgets Qt leaves without one: the announcer
// (Notification role), the sheet preview (a graphic with a text caret), and
// splitter handles, which otherwise show up with no role at all; and for combo
// boxes, whose value Qt's own interface does not let a screen reader find.
#include <QAbstractItemView>
#include <QAccessible>
#include <QAccessibleWidget>
#include <QComboBox>
#include <QLabel>
#include <QSplitterHandle>

#include "announcer.hpp"
#include "braille_pane.hpp"
#include "sheet_preview.hpp"
#include "status_label.hpp"
#include "text_units.hpp"

namespace tactus::gui {
namespace {

class AccessibleAnnouncer : public QAccessibleWidget {
public:
    explicit AccessibleAnnouncer(Announcer* a) : QAccessibleWidget(a, QAccessible::Notification) {}
    QString text(QAccessible::Text t) const override {
        const auto* a = static_cast<const Announcer*>(object());
        if (t == QAccessible::Name) return a->message();
        // No description: screen readers cache it, so Orca spoke each new message
        // followed by the previous one (issue 14).
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

// A closed combo box. Orca reads a combo box's value from its selected child or
// its text; Qt's interface (Qt 6.4) has neither, so Orca said "Speed: combo box"
// with no value. Here the value is the box's text, and a change made with the
// arrows while it is closed, which Orca does not speak from Qt's events, is said
// through the window's announcer (unless the box's owner announces its own
// changes: property "announcesChanges").
class AccessibleComboBox : public QAccessibleWidget, public QAccessibleTextInterface {
public:
    explicit AccessibleComboBox(QComboBox* box) : QAccessibleWidget(box, QAccessible::ComboBox) {
        QObject::connect(box, &QComboBox::currentIndexChanged, box, [box] {
            if (!box->hasFocus() || box->view()->isVisible() || box->property("announcesChanges").toBool()) return;
            if (auto* a = box->window()->findChild<Announcer*>()) a->announce(box->currentText());
        });
    }
    QComboBox* box() const { return static_cast<QComboBox*>(widget()); }

    void* interface_cast(QAccessible::InterfaceType t) override {
        if (t == QAccessible::TextInterface) return static_cast<QAccessibleTextInterface*>(this);
        return QAccessibleWidget::interface_cast(t);
    }
    QString text(QAccessible::Text t) const override {
        if (t == QAccessible::Value) return box()->currentText();
        if (t == QAccessible::Name && box()->accessibleName().isEmpty()) return box()->currentText();
        return QAccessibleWidget::text(t);
    }
    QAccessible::State state() const override {
        auto s = QAccessibleWidget::state();
        s.expandable = true;
        s.hasPopup = true;
        s.expanded = box()->view()->isVisible();
        s.collapsed = !s.expanded;
        return s;
    }
    QStringList actionNames() const override { return {showMenuAction(), pressAction()}; }
    void doAction(const QString& name) override {
        if (name == showMenuAction() || name == pressAction()) box()->showPopup();
    }
    QStringList keyBindingsForAction(const QString&) const override { return {}; }

    // QAccessibleTextInterface: the value, read-only.
    void selection(int, int* start, int* end) const override { *start = *end = 0; }
    int selectionCount() const override { return 0; }
    void addSelection(int, int) override {}
    void removeSelection(int) override {}
    void setSelection(int, int, int) override {}
    int cursorPosition() const override { return 0; }
    void setCursorPosition(int) override {}
    QString text(int start, int end) const override { return box()->currentText().mid(start, end - start); }
    int characterCount() const override { return static_cast<int>(box()->currentText().size()); }
    QRect characterRect(int) const override { return rect(); }
    int offsetAtPoint(const QPoint&) const override { return 0; }
    void scrollToSubstring(int, int) override {}
    QString attributes(int, int* start, int* end) const override {
        *start = 0;
        *end = characterCount();
        return {};
    }
    QString textAtOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_at_offset(box()->currentText(), offset, b, start, end);
    }
    QString textBeforeOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_before_offset(box()->currentText(), offset, b, start, end);
    }
    QString textAfterOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_after_offset(box()->currentText(), offset, b, start, end);
    }
};

QAccessibleInterface* factory(const QString& classname, QObject* object) {
    if (!object || !object->isWidgetType()) return nullptr;
    auto* w = static_cast<QWidget*>(object);
    if (classname == QLatin1String("tactus::gui::Announcer")) return new AccessibleAnnouncer(static_cast<Announcer*>(w));
    if (classname == QLatin1String("tactus::gui::SheetPreview"))
        return make_accessible_sheet_preview(static_cast<SheetPreview*>(w));
    if (classname == QLatin1String("tactus::gui::BraillePane"))
        return make_accessible_braille_pane(static_cast<BraillePane*>(w));
    if (classname == QLatin1String("QSplitterHandle")) return new AccessibleSplitterHandle(w);
    // An editable combo box keeps Qt's interface: its line edit is its text.
    if (classname == QLatin1String("QComboBox"))
        if (auto* box = static_cast<QComboBox*>(w); !box->isEditable()) return new AccessibleComboBox(box);
    if (classname == QLatin1String("QLabel"))
        if (auto* l = static_cast<QLabel*>(w); !status_caption(l).isEmpty()) return make_accessible_status(l);
    return nullptr;
}

}  // namespace

void install_accessibility() { QAccessible::installFactory(factory); }

}  // namespace tactus::gui
