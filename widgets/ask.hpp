// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's questions before something that cannot be taken back
// (reflow ready-made braille, save as UTF-8, quit while embossing): a question,
// its detail, one answer that goes on and one that stays. Staying is the
// default and Escape's answer, so a key pressed by mistake changes nothing.
#include <QString>

class QWidget;

namespace tactus::gui {

struct Answer {
    QString text;         // the button, with its mnemonic ("&Reflow")
    QString object_name;  // for tests and the accessibility walk; may be empty
    QString description;  // what a screen reader adds to the name; may be empty
};

struct Question {
    QString title;
    QString text;    // the question, the box's first label
    QString detail;  // what each answer does, the box's second label
    // The box's name is what Orca says first ("alert ..."); the question and
    // the detail are its labels, read next (a description on the box as well
    // made Orca read all of it twice). Empty: the box's default.
    QString accessible_name;
    QString object_name;  // may be empty
    Answer go;            // accepts
    Answer stay;          // rejects; an empty text is the standard Cancel button
};

// Asks modally; true when the go-on answer was chosen.
bool ask(QWidget* parent, const Question& q);

}  // namespace tactus::gui
