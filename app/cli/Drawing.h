// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "drawing/DrawingModule.h"

#include <QCoreApplication>

#include <memory>

namespace rs::cli {

// The application for this command line: a QGuiApplication from the drawing
// module when it draws (`ladder`, `diff --pdf`), else a QCoreApplication.
// Null, with a message on stderr, when the module cannot be loaded.
std::unique_ptr<QCoreApplication> makeApplication(int& argc, char** argv);

// The drawing module makeApplication loaded; only for the verbs that draw.
const DrawingModule& drawing();

} // namespace rs::cli
