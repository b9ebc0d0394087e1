// SPDX-License-Identifier: GPL-3.0-or-later
#include "system_look.hpp"

#include <QAction>
#include <QApplication>
#include <QPalette>
#include <algorithm>
#include <cmath>

#include "preview_panel.hpp"
#include "preview_panel.hpp"

namespace tactus::gui {
namespace {

double luminance(const QColor& c) {
    const auto channel = [](double v) { return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    return 0.2126 * channel(c.redF()) + 0.7152 * channel(c.greenF()) + 0.0722 * channel(c.blueF());
}

}  // namespace

bool system_high_contrast() {
    const auto theme = qEnvironmentVariable("GTK_THEME") + qEnvironmentVariable("QT_STYLE_OVERRIDE");
    if (theme.contains(QLatin1String("HighContrast"), Qt::CaseInsensitive)) return true;
    // WCAG contrast ratio of text on window: ordinary themes sit well below 15:1,
    // high-contrast themes (pure black on white or the reverse) at 21:1.
    const auto pal = QApplication::palette();
    const double a = luminance(pal.color(QPalette::WindowText)) + 0.05;
    const double b = luminance(pal.color(QPalette::Window)) + 0.05;
    return std::max(a, b) / std::min(a, b) >= 19.0;
}

double system_text_scale() {
    const double pt = QApplication::font().pointSizeF();
    return pt > 0 ? std::clamp(pt / 10.0, 1.0, 4.0) : 1.0;
}

void apply_system_look(PreviewPanel& panel) {
    if (system_high_contrast()) panel.high_contrast_action()->setChecked(true);
    panel.preview()->set_zoom(system_text_scale());
}

}  // namespace tactus::gui
