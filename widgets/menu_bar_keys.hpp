// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lone Alt does not move the focus into the menu bar, except on Windows,
// where that is what every program does. Elsewhere the menus open by F10 or
// Alt+letter, and a lone Alt there did harm: after Alt+P (Pause) the menu bar
// could take the Alt's release as a lone Alt, Orca said "File." and the next
// key went to the menus instead of the job.
class QMenuBar;

namespace tactus::gui {

void keep_lone_alt_out_of_menus(QMenuBar* bar);

}  // namespace tactus::gui
