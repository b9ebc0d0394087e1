// SPDX-License-Identifier: GPL-3.0-or-later
#include "menu_bar_keys.hpp"

#include <QMenuBar>
#include <QProxyStyle>

namespace tactus::gui {
namespace {

class NoLoneAltStyle : public QProxyStyle {
public:
    using QProxyStyle::QProxyStyle;
    int styleHint(StyleHint hint, const QStyleOption* option, const QWidget* widget,
                  QStyleHintReturn* data) const override {
        if (hint == SH_MenuBar_AltKeyNavigation) return 0;
        return QProxyStyle::styleHint(hint, option, widget, data);
    }
};

}  // namespace

void keep_lone_alt_out_of_menus([[maybe_unused]] QMenuBar* bar) {
#ifndef Q_OS_WIN
    // The proxy draws as the application's style; the bar owns it.
    auto* style = new NoLoneAltStyle;
    style->setParent(bar);
    bar->setStyle(style);
#endif
}

}  // namespace tactus::gui
