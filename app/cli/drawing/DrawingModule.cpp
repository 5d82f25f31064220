// SPDX-License-Identifier: GPL-3.0-or-later
#include "DrawingModule.h"

#include "NetworkPicture.h"
#include "ReviewPdf.h"
#include "RungsmithBuildVersion.h"

#include <QGuiApplication>

namespace {

std::unique_ptr<QCoreApplication> makeApplication(int& argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    return std::make_unique<QGuiApplication>(argc, argv);
}

QString writeNetworkPicture(const QString& path, const rs::ladder::NetworkLayout& layout,
                            const rs::render::PowerSnapshot* power, const QString& title) {
    return rs::render::writeNetworkPicture(path, layout, {}, power, title);
}

const rs::cli::DrawingModule kModule{RUNGSMITH_BUILD_VERSION, makeApplication, writeNetworkPicture,
                                     rs::render::writeReviewPdf};

} // namespace

extern "C" __attribute__((visibility("default"))) const rs::cli::DrawingModule*
rungsmithDrawingModule() {
    return &kModule;
}
