// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "PowerSnapshot.h"
#include "Review.h"
#include "ladder/Layout.h"

#include <QCoreApplication>
#include <QString>

#include <memory>

namespace rs::cli {

// What the module rungsmith-drawing.so gives the command line: the drawing
// verbs' work on QtGui and QtSvg. rungsmith-cli links neither, as they cost
// every command 6 MB of memory and 8 ms at start (issue 23); it loads the
// module for `ladder` and `diff --pdf` only. The module takes the core from
// the program, so both must come from one build: `build` says which.
struct DrawingModule {
    const char* build; // RUNGSMITH_BUILD_VERSION of the module
    // Fonts need a QGuiApplication; it runs on the offscreen platform.
    std::unique_ptr<QCoreApplication> (*makeApplication)(int& argc, char** argv);
    // render::writeNetworkPicture in the editor's style.
    QString (*writeNetworkPicture)(const QString& path, const ladder::NetworkLayout& layout,
                                   const render::PowerSnapshot* power, const QString& title);
    QString (*writeReviewPdf)(const QString& path, const render::Review& review);
};

// The name of the module's one exported function, of type DrawingModuleEntry.
inline constexpr char kDrawingModuleEntry[] = "rungsmithDrawingModule";
using DrawingModuleEntry = const DrawingModule* (*)();

} // namespace rs::cli
