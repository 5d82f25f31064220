// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/Theme.h"

#include <QApplication>
#include <QPalette>
#include <QStyle>

namespace rs::ui {

namespace {

QPalette darkPalette() {
    QPalette p;
    const QColor window(0x2b2d31);
    const QColor base(0x1e1f22);
    const QColor text(0xdfe1e5);
    const QColor disabled(0x7d8590);
    p.setColor(QPalette::Window, window);
    p.setColor(QPalette::WindowText, text);
    p.setColor(QPalette::Base, base);
    p.setColor(QPalette::AlternateBase, QColor(0x26282c));
    p.setColor(QPalette::ToolTipBase, QColor(0x3b3e44));
    p.setColor(QPalette::ToolTipText, text);
    p.setColor(QPalette::PlaceholderText, disabled);
    p.setColor(QPalette::Text, text);
    p.setColor(QPalette::Button, QColor(0x3b3e44));
    p.setColor(QPalette::ButtonText, text);
    p.setColor(QPalette::BrightText, QColor(0xff7b72));
    p.setColor(QPalette::Light, QColor(0x4a4d55));
    p.setColor(QPalette::Midlight, QColor(0x3b3e44));
    p.setColor(QPalette::Mid, QColor(0x31343a));
    p.setColor(QPalette::Dark, QColor(0x18191c));
    p.setColor(QPalette::Shadow, QColor(0x0d0e10));
    p.setColor(QPalette::Highlight, QColor(0x2f6fde));
    p.setColor(QPalette::HighlightedText, QColor(0xffffff));
    p.setColor(QPalette::Link, QColor(0x58a6ff));
    p.setColor(QPalette::LinkVisited, QColor(0xbc8cff));
    for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
        p.setColor(QPalette::Disabled, role, disabled);
    p.setColor(QPalette::Disabled, QPalette::Light, window);
    return p;
}

} // namespace

void applyTheme(Preferences::Theme theme) {
    switch (theme) {
    case Preferences::Theme::Dark:
        QApplication::setPalette(darkPalette());
        return;
    case Preferences::Theme::Light:
        QApplication::setPalette(QApplication::style()->standardPalette());
        return;
    case Preferences::Theme::System:
        QApplication::setPalette(QPalette()); // back to the platform's
        return;
    }
}

} // namespace rs::ui
