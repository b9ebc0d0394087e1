// SPDX-License-Identifier: GPL-3.0-or-later
// Accessible interfaces for widgets Qt leaves without one: the announcer
// (Notification role), the sheet preview (a graphic with a text caret), and
// splitter handles, which otherwise show up with no role at all; and text
// interfaces that answer every read (Qt's fallback loops on some).
#include <QAccessible>
#include <QApplication>
#include <QAccessibleWidget>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <QSplitterHandle>

#include "announcer.hpp"
#include "braille_pane.hpp"
#include "sheet_preview.hpp"
#include "status_label.hpp"
#include "accessible_text_pane.hpp"
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

// A line edit, or a spin box through its line edit. Qt's interfaces for both
// take textAtOffset from QAccessibleTextInterface's fallback, which never returns
// at the end of the text by word ("1" in the Sheet box hung the app).
class AccessibleLineText : public QAccessibleWidget, public QAccessibleTextInterface, public QAccessibleValueInterface {
public:
    AccessibleLineText(QWidget* w, QAccessible::Role role) : QAccessibleWidget(w, role) {}

    void* interface_cast(QAccessible::InterfaceType t) override {
        if (t == QAccessible::TextInterface) return static_cast<QAccessibleTextInterface*>(this);
        if (t == QAccessible::ValueInterface && spin()) return static_cast<QAccessibleValueInterface*>(this);
        return QAccessibleWidget::interface_cast(t);
    }
    QAccessible::State state() const override {
        auto s = QAccessibleWidget::state();
        s.editable = !edit()->isReadOnly();
        s.readOnly = edit()->isReadOnly();
        s.selectableText = true;
        return s;
    }
    QString text(QAccessible::Text t) const override {
        if (t == QAccessible::Value) return edit()->text();
        return QAccessibleWidget::text(t);
    }
    QStringList actionNames() const override {
        auto names = QAccessibleWidget::actionNames();
        if (spin()) names << increaseAction() << decreaseAction();
        return names;
    }
    void doAction(const QString& name) override {
        if (spin() && name == increaseAction()) spin()->stepUp();
        else if (spin() && name == decreaseAction()) spin()->stepDown();
        else QAccessibleWidget::doAction(name);
    }

    // QAccessibleValueInterface (spin boxes): Qt's value, minimum, maximum and step properties.
    QVariant currentValue() const override { return widget()->property("value"); }
    void setCurrentValue(const QVariant& v) override { widget()->setProperty("value", v); }
    QVariant maximumValue() const override { return widget()->property("maximum"); }
    QVariant minimumValue() const override { return widget()->property("minimum"); }
    QVariant minimumStepSize() const override { return widget()->property("singleStep"); }

    // QAccessibleTextInterface
    void selection(int index, int* start, int* end) const override {
        if (index != 0 || !edit()->hasSelectedText()) {
            *start = *end = 0;
            return;
        }
        *start = edit()->selectionStart();
        *end = *start + static_cast<int>(edit()->selectedText().size());
    }
    int selectionCount() const override { return edit()->hasSelectedText() ? 1 : 0; }
    void addSelection(int start, int end) override { setSelection(0, start, end); }
    void removeSelection(int) override { edit()->deselect(); }
    void setSelection(int, int start, int end) override { edit()->setSelection(start, end - start); }
    int cursorPosition() const override { return edit()->cursorPosition(); }
    void setCursorPosition(int position) override { edit()->setCursorPosition(position); }
    QString text(int start, int end) const override { return edit()->text().mid(start, end - start); }
    int characterCount() const override { return static_cast<int>(edit()->text().size()); }
    QRect characterRect(int) const override { return rect(); }
    int offsetAtPoint(const QPoint& point) const override { return edit()->cursorPositionAt(edit()->mapFromGlobal(point)); }
    void scrollToSubstring(int, int) override {}
    QString attributes(int, int* start, int* end) const override {
        *start = 0;
        *end = characterCount();
        return {};
    }
    QString textAtOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_at_offset(edit()->text(), offset, b, start, end);
    }
    QString textBeforeOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_before_offset(edit()->text(), offset, b, start, end);
    }
    QString textAfterOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_after_offset(edit()->text(), offset, b, start, end);
    }

private:
    QAbstractSpinBox* spin() const { return qobject_cast<QAbstractSpinBox*>(widget()); }
    // A spin box may be asked for while it is built, before its line edit exists.
    QLineEdit* edit() const {
        if (auto* e = qobject_cast<QLineEdit*>(widget())) return e;
        if (auto* e = widget()->findChild<QLineEdit*>()) return e;
        static auto* none = new QLineEdit;  // never shown, never freed: an empty text until the line edit exists
        return none;
    }
};

// A combo box that is not editable. Qt 6.4 names it by its current item only
// when it has no accessible name, and gives it no text: Orca 43 takes a combo
// box's value from its text (or a selection interface, which Qt 6.4 does not
// bridge), so it said "Table: combo box." with no value, on focus and after
// Up/Down. Here the current item is the box's read-only text; the list stays
// its one child, as in Qt's own interface.
class AccessibleComboBox : public QAccessibleWidget, public QAccessibleTextInterface {
public:
    explicit AccessibleComboBox(QComboBox* box) : QAccessibleWidget(box, QAccessible::ComboBox) {
        addControllingSignal(QStringLiteral("activated(int)"));
    }
    void* interface_cast(QAccessible::InterfaceType t) override {
        if (t == QAccessible::TextInterface) return static_cast<QAccessibleTextInterface*>(this);
        return QAccessibleWidget::interface_cast(t);
    }
    int childCount() const override { return 1; }
    QAccessibleInterface* child(int index) const override {
        return index == 0 ? QAccessible::queryAccessibleInterface(box()->view()) : nullptr;
    }
    int indexOfChild(const QAccessibleInterface* child) const override {
        return child && child->object() == box()->view() ? 0 : -1;
    }
    QAccessible::State state() const override {
        auto s = QAccessibleWidget::state();
        s.expandable = true;
        s.expanded = box()->view()->isVisible();
        s.collapsed = !s.expanded;
        return s;
    }
    QString text(QAccessible::Text t) const override {
        if (t == QAccessible::Value) return value();
        if (t == QAccessible::Name && box()->accessibleName().isEmpty()) return value();
        return QAccessibleWidget::text(t);
    }
    QStringList actionNames() const override { return {showMenuAction(), pressAction()}; }
    void doAction(const QString& name) override {
        if (name == showMenuAction() || name == pressAction()) box()->showPopup();
    }

    // QAccessibleTextInterface: the current item, read only, caret at its start.
    void selection(int, int* start, int* end) const override { *start = *end = 0; }
    int selectionCount() const override { return 0; }
    void addSelection(int, int) override {}
    void removeSelection(int) override {}
    void setSelection(int, int, int) override {}
    int cursorPosition() const override { return 0; }
    void setCursorPosition(int) override {}
    QString text(int start, int end) const override { return value().mid(start, end - start); }
    int characterCount() const override { return static_cast<int>(value().size()); }
    QRect characterRect(int) const override { return rect(); }
    int offsetAtPoint(const QPoint&) const override { return 0; }
    void scrollToSubstring(int, int) override {}
    QString attributes(int, int* start, int* end) const override {
        *start = 0;
        *end = characterCount();
        return {};
    }
    QString textAtOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_at_offset(value(), offset, b, start, end);
    }
    QString textBeforeOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_before_offset(value(), offset, b, start, end);
    }
    QString textAfterOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_after_offset(value(), offset, b, start, end);
    }

private:
    QComboBox* box() const { return static_cast<QComboBox*>(widget()); }
    QString value() const { return box()->currentText(); }
};

QAccessibleInterface* factory(const QString& classname, QObject* object) {
    if (!object || !object->isWidgetType()) return nullptr;
    auto* w = static_cast<QWidget*>(object);
    if (classname == QLatin1String("tactus::gui::Announcer")) return new AccessibleAnnouncer(static_cast<Announcer*>(w));
    if (classname == QLatin1String("tactus::gui::SheetPreview"))
        return make_accessible_sheet_preview(static_cast<SheetPreview*>(w));
    if (classname == QLatin1String("tactus::gui::BraillePane"))
        return make_accessible_plain_text(static_cast<BraillePane*>(w));
    if (classname == QLatin1String("tactus::gui::PrintPane")) return make_accessible_rich_text(static_cast<PrintPane*>(w));
    // A read-only log: Qt's interface answers a word read at a word's edge with
    // the unit before the offset.
    if (auto* log = qobject_cast<QPlainTextEdit*>(w); log && log->isReadOnly() && classname == QLatin1String("QPlainTextEdit"))
        return make_accessible_plain_text(log);
    if (classname == QLatin1String("QSplitterHandle")) return new AccessibleSplitterHandle(w);
    // Asked first for the most derived class (QSpinBox, QDoubleSpinBox), which
    // Qt's own factory would answer.
    if (auto* edit = qobject_cast<QLineEdit*>(w); edit && edit->echoMode() == QLineEdit::Normal)
        return new AccessibleLineText(w, QAccessible::EditableText);
    if (qobject_cast<QAbstractSpinBox*>(w)) return new AccessibleLineText(w, QAccessible::SpinBox);
    if (auto* box = qobject_cast<QComboBox*>(w); box && !box->isEditable()) return new AccessibleComboBox(box);
    if (classname == QLatin1String("QLabel"))
        if (auto* l = static_cast<QLabel*>(w); !status_caption(l).isEmpty()) return make_accessible_status(l);
    return nullptr;
}

// The main window loses its activation to each popup menu it opens and gets it
// back when the menu closes; walking the menu bar by
// Right even re-activates it, and moves the focus back to the text, between two
// menus. Orca takes each return for coming back to the window and reads it
// again ("Tactus frame", then the print text), so Right read the document
// instead of the next menu. The popups belong to the window: while one is open,
// the window's activation changes and the focus of widgets outside the popup
// are not passed to the screen reader. Leaving for another program still is.
// Only menus: a combo box's list opened by a key is announced with the box it
// belongs to, which a held-back focus event silenced.
bool popup_open() { return qobject_cast<QMenu*>(QApplication::activePopupWidget()) != nullptr; }

// A combo box's list is a popup window of its own (Qt's private container).
QComboBox* combo_of_popup(QObject* popup) {
    if (!popup || !popup->inherits("QComboBoxPrivateContainer")) return nullptr;
    return qobject_cast<QComboBox*>(popup->parent());
}

// Opening a combo box's list moves the focus into the list before the list's
// current item is set as the focused child, so Orca said "List with 201
// items." and never which item was current. Told once the list is shown.
void announce_current_item(QComboBox* box) {
    auto* view = box->view();
    if (!view || !view->isVisible() || !view->currentIndex().isValid()) return;
    QAccessibleEvent focus(view, QAccessible::Focus);
    focus.setChild(view->currentIndex().row());
    QAccessible::updateAccessibility(&focus);
}

// Up and Down on a closed combo box change its value, which Qt 6.4 tells only
// by a name change and a selection change of the box; Orca 43 ignores a combo
// box's name changes and reads its selection through an interface Qt 6.4 does
// not bridge, so the new value was silent. The window's announcer says it.
// A box whose change the window words itself (the braille table says
// "Braille table: ...") sets the property "announcesChange".
void announce_closed_change(QComboBox* box) {
    if (!box->hasFocus() || box->view()->isVisible() || box->property("announcesChange").toBool()) return;
    if (auto* a = box->window()->findChild<Announcer*>()) a->announce(box->currentText());
}

class PopupActivationFilter : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* target, QEvent* e) override {
        const auto type = e->type();
        if (type == QEvent::Show && target->isWidgetType() &&
            static_cast<QWidget*>(target)->windowType() == Qt::Popup) {
            if (auto* box = combo_of_popup(target))
                QMetaObject::invokeMethod(box, [box] { announce_current_item(box); }, Qt::QueuedConnection);
            // Stay the first application filter, before the AT-SPI bridge's,
            // which is installed once the screen reader's bus answers.
            QMetaObject::invokeMethod(this, [this] {
                qApp->removeEventFilter(this);
                qApp->installEventFilter(this);
            }, Qt::QueuedConnection);
            return false;
        }
        if ((type != QEvent::WindowActivate && type != QEvent::WindowDeactivate) || !e->spontaneous() ||
            !target->isWidgetType())
            return false;
        auto* w = static_cast<QWidget*>(target);
        if (!w->isWindow() || w->windowType() == Qt::Popup) return false;
        // Menus only: a combo box's list deactivates the window but its closing
        // sends no activation back, so hiding the one would hide the next
        // window's activation (a dialog's, which then flooded Orca). The list's
        // activation changes are held back as accessible state changes instead
        // (hide_combo_activation).
        if (type == QEvent::WindowDeactivate) {
            if (!popup_open()) return false;
            hid_deactivation_ = true;
            return true;
        }
        if (popup_open()) return true;
        if (!hid_deactivation_) return false;
        hid_deactivation_ = false;
        return true;
    }

private:
    bool hid_deactivation_ = false;
};

QAccessible::UpdateHandler qt_handler = nullptr;

void pass_on(QAccessibleEvent* e) {
    if (qt_handler) {
        qt_handler(e);
        return;
    }
    // No handler before this one: Qt's own delivery, which runs without one.
    auto* mine = QAccessible::installUpdateHandler(nullptr);
    QAccessible::updateAccessibility(e);
    QAccessible::installUpdateHandler(mine);
}

// Opening a combo box's list makes Qt tell the screen reader that the main
// window stopped being active and the list's window became so, and the reverse
// on closing, as accessible state changes (not window events, which the filter
// above sees). Orca took each return for coming back to the window and said
// "Tactus frame." again at every list. The list belongs to the window: these
// changes are not passed on, the window's one change after the list closes
// included.
bool hid_window_activation = false;

bool hide_combo_activation(QAccessibleEvent* e) {
    if (e->type() != QAccessible::StateChanged || !static_cast<QAccessibleStateChangeEvent*>(e)->changedStates().active)
        return false;
    auto* o = e->object();
    if (!o || !o->isWidgetType() || !static_cast<QWidget*>(o)->isWindow()) return false;
    if (combo_of_popup(o)) return true;
    if (combo_of_popup(QApplication::activePopupWidget())) {
        hid_window_activation = true;
        return true;
    }
    if (!hid_window_activation) return false;
    hid_window_activation = false;
    return true;
}

// A spin box's line edit drops its selection when the focus leaves it,
// after the focus has moved: Orca, still on the old field, said "Text
// unselected." before the next control. Nothing the user did is unselected
// there, so the change is not passed on; the same change in the focused field
// (Shift+arrow, a click) still is.
bool selection_dropped_on_leaving(QAccessibleEvent* e) {
    if (e->type() != QAccessible::TextSelectionChanged) return false;
    // Spin boxes only, where the stray phrase was heard: held back for every
    // line edit, opening the export dialog flooded Orca (orca_open).
    auto* edit = qobject_cast<QLineEdit*>(e->object());
    if (!edit || edit->hasFocus() || !qobject_cast<QAbstractSpinBox*>(edit->parentWidget())) return false;
    const auto* change = static_cast<QAccessibleTextSelectionEvent*>(e);
    return change->selectionStart() == change->selectionEnd();
}

// A spin box is two accessible objects here: the spin button, which Qt reports
// text changes for, and its line edit, which holds the text interface and
// reports the selection. Orca keeps each object's selection to tell what a
// selection event changed. Typing over a selection (Ctrl+A, then a digit) only
// told it that the line edit's selection was gone, and it said "Text
// unselected." though the typed text had replaced the selection. The typed
// text is told for the line edit too, as for a text field of its own: Orca
// reads the line edit's selection again on an insertion, finds none, and the
// selection's end that follows changes nothing it would say. (The removal is
// not: Orca would take the removed selection for a deletion and say
// "Selection deleted.".) A selection taken back with Shift+arrow has no text
// change and is still heard.
void insertion_in_spin_box_edit(QAccessibleEvent* e) {
    if (e->type() != QAccessible::TextInserted && e->type() != QAccessible::TextUpdated) return;
    auto* spin = qobject_cast<QAbstractSpinBox*>(e->object());
    if (!spin) return;
    auto* edit = spin->findChild<QLineEdit*>(QString(), Qt::FindDirectChildrenOnly);
    if (!edit) return;
    const auto inserted = e->type() == QAccessible::TextInserted
                              ? static_cast<QAccessibleTextInsertEvent*>(e)->textInserted()
                              : static_cast<QAccessibleTextUpdateEvent*>(e)->textInserted();
    const int at = e->type() == QAccessible::TextInserted ? static_cast<QAccessibleTextInsertEvent*>(e)->changePosition()
                                                          : static_cast<QAccessibleTextUpdateEvent*>(e)->changePosition();
    if (inserted.isEmpty()) return;
    QAccessibleTextInsertEvent copy(edit, at, inserted);
    pass_on(&copy);
}

// The editor's panes mirror one another's selection: Ctrl+A in the print text
// selects every cell of the braille pane too. Orca took the unfocused pane's
// selection as news (it read the braille after Ctrl+A in the print text), kept
// it, and when typing replaced the selection and the braille was rebuilt, said
// "Text unselected." for the pane the user was not in. A text pane's selection
// is passed on only while it has the focus; Orca reads a pane's selection
// afresh when the focus comes to it.
bool selection_of_unfocused_pane(QAccessibleEvent* e) {
    if (e->type() != QAccessible::TextSelectionChanged) return false;
    auto* o = e->object();
    auto* pane = qobject_cast<QAbstractScrollArea*>(o);
    if (!pane || !(qobject_cast<QTextEdit*>(o) || qobject_cast<QPlainTextEdit*>(o))) return false;
    return !pane->hasFocus();
}

void update_handler(QAccessibleEvent* e) {
    if (hide_combo_activation(e) || selection_dropped_on_leaving(e) || selection_of_unfocused_pane(e)) return;
    insertion_in_spin_box_edit(e);
    if (e->type() == QAccessible::ValueChanged)
        // Only a change made in the closed box: one chosen in the open list is
        // heard as the list item, then as the box when the focus returns.
        if (auto* box = qobject_cast<QComboBox*>(e->object()); box && !box->isEditable() && !box->view()->isVisible())
            QMetaObject::invokeMethod(box, [box] { announce_closed_change(box); }, Qt::QueuedConnection);
    if (e->type() == QAccessible::Focus && popup_open()) {
        auto* o = e->object();
        if (o && o->isWidgetType() && static_cast<QWidget*>(o)->window()->windowType() != Qt::Popup) return;
    }
    pass_on(e);
}

}  // namespace

void install_accessibility() {
    QAccessible::installFactory(factory);
    qt_handler = QAccessible::installUpdateHandler(update_handler);
    qApp->installEventFilter(new PopupActivationFilter(qApp));
}

}  // namespace tactus::gui
