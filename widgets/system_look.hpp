// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// High contrast and large text follow the desktop: the palette's contrast and the
// GTK theme name tell us about high contrast, the default font size about large
// text. The user's own choices in the View menu win afterwards.
class QWidget;

namespace tactus::gui {

class PreviewPanel;

[[nodiscard]] bool system_high_contrast();
// Preview zoom matching the system font size (1.0 at 10 pt).
[[nodiscard]] double system_text_scale();
// Applies both to the preview, the one view that follows them.
void apply_system_look(PreviewPanel& panel);

}  // namespace tactus::gui
