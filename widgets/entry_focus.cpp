// SPDX-License-Identifier: GPL-3.0-or-later
#include "entry_focus.hpp"

#include <QCoreApplication>
#include <QFocusEvent>
#include <QLineEdit>
#include <QObject>
#include <QPointer>
#include <QTimer>

namespace tactus::gui {

namespace {

class SpokenEntry final : public QObject {
public:
    explicit SpokenEntry(QLineEdit* entry) : QObject(entry), entry_(entry) {}

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched != entry_ || event->type() != QEvent::FocusIn || resending_) return false;
        const auto reason = static_cast<QFocusEvent*>(event)->reason();
        // The reasons for which QLineEdit selects all as it takes the focus.
        if (reason != Qt::TabFocusReason && reason != Qt::BacktabFocusReason && reason != Qt::ShortcutFocusReason)
            return false;
        resending_ = true;
        QFocusEvent plain(QEvent::FocusIn, Qt::OtherFocusReason);
        QCoreApplication::sendEvent(entry_, &plain);
        resending_ = false;
        if (!entry_->text().isEmpty()) {
            QPointer<QLineEdit> entry = entry_;
            QTimer::singleShot(0, entry_, [entry] {
                if (entry && entry->hasFocus()) entry->selectAll();
            });
        }
        return true;
    }

private:
    QLineEdit* entry_;
    bool resending_ = false;
};

}  // namespace

void speak_entry_on_focus(QLineEdit* entry) { entry->installEventFilter(new SpokenEntry(entry)); }

}  // namespace tactus::gui
