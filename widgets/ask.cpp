// SPDX-License-Identifier: GPL-3.0-or-later
#include "ask.hpp"

#include <QMessageBox>
#include <QPushButton>

namespace tactus::gui {

namespace {

void describe(QPushButton* button, const Answer& a) {
    if (!a.object_name.isEmpty()) button->setObjectName(a.object_name);
    if (!a.description.isEmpty()) button->setAccessibleDescription(a.description);
}

}  // namespace

bool ask(QWidget* parent, const Question& q) {
    QMessageBox box(QMessageBox::Question, q.title, q.text, QMessageBox::NoButton, parent);
    if (!q.object_name.isEmpty()) box.setObjectName(q.object_name);
    box.setInformativeText(q.detail);
    if (!q.accessible_name.isEmpty()) box.setAccessibleName(q.accessible_name);
    auto* go = box.addButton(q.go.text, QMessageBox::AcceptRole);
    auto* stay = q.stay.text.isEmpty() ? box.addButton(QMessageBox::Cancel) : box.addButton(q.stay.text, QMessageBox::RejectRole);
    describe(go, q.go);
    describe(stay, q.stay);
    box.setDefaultButton(stay);
    box.setEscapeButton(stay);
    box.exec();
    return box.clickedButton() == go;
}

}  // namespace tactus::gui
