// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Gives the keyboard focus back after a dialog. Under a window manager the main
// window did not always become active again after File > Open (the file dialog,
// then a progress dialog that was deleted while shown): Orca then heard no
// window and the app fell silent for good. A FocusReturn made before
// a dialog activates the window again when it goes out of scope and puts the
// focus back where it was (or on `fallback`).
#include <QPointer>
#include <QWidget>

namespace tactus::gui {

class FocusReturn {
public:
    FocusReturn(QWidget* window, QWidget* fallback);
    ~FocusReturn();
    FocusReturn(const FocusReturn&) = delete;
    FocusReturn& operator=(const FocusReturn&) = delete;
    // Does it now (for work that ends later, e.g. a file loaded in the background).
    void restore();

private:
    QPointer<QWidget> window_;
    QPointer<QWidget> previous_;
    QPointer<QWidget> fallback_;
    bool done_ = false;
};

// Activates `window` and focuses `target` (or the window's last focus).
void return_focus(QWidget* window, QWidget* target);

}  // namespace tactus::gui
