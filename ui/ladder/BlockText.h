// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "blocks/LibrarySearch.h"
#endif

#include <QCoreApplication>
#include <QString>

#include <string>

namespace rs::ui {

// How the IDE words a library block for its reader: the description in the
// language the manual's "Block Description Language" (14) would pick, which
// is the window's language, and the pins.
class BlockText {
    Q_DECLARE_TR_FUNCTIONS(BlockText)
public:
    // "en", "sv" or "de", from the locale the window speaks.
    static std::string descriptionLanguage();
    static QString description(const blocks::BlockDefinition& block);
    // "input, bit, default 0s50" or "output, register, may stay open".
    static QString pinSummary(const blocks::Pin& pin);
    // The block as rich text: name, library and version, kind, description
    // and a table of its pins.
    static QString html(const blocks::LoadedLibrary& library, const blocks::BlockDefinition& block);
};

} // namespace rs::ui
