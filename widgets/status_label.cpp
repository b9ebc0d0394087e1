// SPDX-License-Identifier: GPL-3.0-or-later
#include "status_label.hpp"

#include <QAccessibleWidget>
#include <QLabel>
#include <QTextDocument>
#include <QTextDocumentFragment>

namespace tactus::gui {
namespace {

constexpr const char* kCaption = "tactusStatusCaption";

class AccessibleStatus : public QAccessibleWidget {
public:
    explicit AccessibleStatus(QLabel* l) : QAccessibleWidget(l, QAccessible::StaticText) {}
    QString text(QAccessible::Text t) const override {
        const auto* l = static_cast<const QLabel*>(object());
        if (t == QAccessible::Name) return status_accessible_name(l);
        if (t == QAccessible::Description) return status_caption(l);
        return QAccessibleWidget::text(t);
    }
};

}  // namespace

void expose_status(QLabel* label, const QString& caption) {
    label->setProperty(kCaption, caption);
    label->setAccessibleName(QString());  // else QLabel::setText announces nothing
    label->setAccessibleDescription(caption);
}

QString status_caption(const QLabel* label) { return label->property(kCaption).toString(); }

QString status_accessible_name(const QLabel* label) {
    const auto caption = status_caption(label);
    const bool rich = label->textFormat() == Qt::RichText ||
                      (label->textFormat() == Qt::AutoText && Qt::mightBeRichText(label->text()));
    auto text = rich ? QTextDocumentFragment::fromHtml(label->text()).toPlainText() : label->text();
    text = text.simplified();
    if (text.isEmpty()) return caption;
    return caption.isEmpty() ? text : QStringLiteral("%1: %2").arg(caption, text);
}

QAccessibleInterface* make_accessible_status(QLabel* label) { return new AccessibleStatus(label); }

}  // namespace tactus::gui
