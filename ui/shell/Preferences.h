// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QString>

namespace rs::ui {

// The user's preferences (manual Part 1, 14), kept in the settings so that
// they outlive the program: the ladder diagram's colours, the screen update
// interval in online mode, whether ladder diagrams start expanded, whether
// the compiler warns about unconfigured I/O, the language, and this IDE's
// own additions (theme, autosave interval).
struct Preferences {
    enum class Theme { System, Light, Dark };

    // Each left invalid (the default) is as the theme draws it (LadderColours).
    QColor ladderBackground;
    QColor ladderFocusedBackground;
    QColor ladderComponentBody;
    QColor ladderLines;
    QColor ladderLinesOff;
    QColor ladderLinesOn;
    int screenUpdateMs = 100;
    bool startExpanded = true;
    bool warnUnconfiguredIo = true;
    QString language; // "", the system's, or "en", "sv", "de"
    Theme theme = Theme::System;
    // Autosave has no "off": a copy costs little, and a lost afternoon a lot.
    static constexpr int kMinAutosaveMinutes = 1;
    static constexpr int kMaxAutosaveMinutes = 60;
    int autosaveMinutes = 2; // kept within the range above whatever the settings say
    // Where Simulation > Serve Modbus TCP listens: loopback unless the user
    // opens it to the network (a real gateway's is port 502 on all addresses).
    QString modbusHost = QStringLiteral("127.0.0.1");
    int modbusPort = 1502; // 1-65535

    static Preferences defaults();
    static Preferences load();
    void save() const;

    friend bool operator==(const Preferences&, const Preferences&) = default;
};

} // namespace rs::ui
