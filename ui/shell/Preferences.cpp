// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/Preferences.h"

#include <QSettings>

#include <algorithm>

namespace rs::ui {

namespace {

const QString kGroup = QStringLiteral("preferences/");
// Colours under keys of their own: the first versions stored fixed colours
// that the view did not draw, which must not come back as the user's choice.
const QString kColours = QStringLiteral("preferences/ladderColours/");

} // namespace

Preferences Preferences::defaults() {
    return Preferences{};
}

Preferences Preferences::load() {
    const QSettings settings;
    const Preferences d = defaults();
    auto color = [&](const char* key, const QColor& fallback) {
        const QColor stored(settings.value(kColours + QLatin1String(key)).toString());
        return stored.isValid() ? stored : fallback;
    };
    Preferences p;
    p.ladderBackground = color("ladderBackground", d.ladderBackground);
    p.ladderFocusedBackground = color("ladderFocusedBackground", d.ladderFocusedBackground);
    p.ladderComponentBody = color("ladderComponentBody", d.ladderComponentBody);
    p.ladderLines = color("ladderLines", d.ladderLines);
    p.ladderLinesOff = color("ladderLinesOff", d.ladderLinesOff);
    p.ladderLinesOn = color("ladderLinesOn", d.ladderLinesOn);
    p.screenUpdateMs =
        settings.value(kGroup + QStringLiteral("screenUpdateMs"), d.screenUpdateMs).toInt();
    p.startExpanded =
        settings.value(kGroup + QStringLiteral("startExpanded"), d.startExpanded).toBool();
    p.warnUnconfiguredIo =
        settings.value(kGroup + QStringLiteral("warnUnconfiguredIo"), d.warnUnconfiguredIo)
            .toBool();
    p.language = settings.value(kGroup + QStringLiteral("language")).toString();
    p.theme = static_cast<Theme>(
        settings.value(kGroup + QStringLiteral("theme"), static_cast<int>(d.theme)).toInt());
    // A settings file edited by hand or by an older version: 0 would autosave
    // on every pass of the event loop, a negative number never.
    p.autosaveMinutes = std::clamp(
        settings.value(kGroup + QStringLiteral("autosaveMinutes"), d.autosaveMinutes).toInt(),
        kMinAutosaveMinutes, kMaxAutosaveMinutes);
    p.modbusHost = settings.value(kGroup + QStringLiteral("modbusHost"), d.modbusHost).toString();
    if (p.modbusHost.trimmed().isEmpty())
        p.modbusHost = d.modbusHost;
    p.modbusPort = std::clamp(
        settings.value(kGroup + QStringLiteral("modbusPort"), d.modbusPort).toInt(), 1, 65535);
    return p;
}

void Preferences::save() const {
    QSettings settings;
    auto color = [&](const char* key, const QColor& value) {
        if (value.isValid())
            settings.setValue(kColours + QLatin1String(key), value.name());
        else
            settings.remove(kColours + QLatin1String(key));
    };
    color("ladderBackground", ladderBackground);
    color("ladderFocusedBackground", ladderFocusedBackground);
    color("ladderComponentBody", ladderComponentBody);
    color("ladderLines", ladderLines);
    color("ladderLinesOff", ladderLinesOff);
    color("ladderLinesOn", ladderLinesOn);
    settings.setValue(kGroup + QStringLiteral("screenUpdateMs"), screenUpdateMs);
    settings.setValue(kGroup + QStringLiteral("startExpanded"), startExpanded);
    settings.setValue(kGroup + QStringLiteral("warnUnconfiguredIo"), warnUnconfiguredIo);
    settings.setValue(kGroup + QStringLiteral("language"), language);
    settings.setValue(kGroup + QStringLiteral("theme"), static_cast<int>(theme));
    settings.setValue(kGroup + QStringLiteral("autosaveMinutes"), autosaveMinutes);
    settings.setValue(kGroup + QStringLiteral("modbusHost"), modbusHost);
    settings.setValue(kGroup + QStringLiteral("modbusPort"), modbusPort);
}

} // namespace rs::ui
