// SPDX-License-Identifier: GPL-3.0-or-later
#include "NativeCodeGenerator.h"

#include "compiler/Compiler.h"
#include "project/ProjectFile.h"

#include <QCoreApplication>
#include <QStringList>

#include <cstdio>

// rungsmith-native FILE.sps OUT.cpp: the project's units as native C++, for
// the simulator benchmark.
int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    const QStringList arguments = app.arguments();
    if (arguments.size() != 3) {
        std::fprintf(stderr, "usage: rungsmith-native FILE.sps OUT.cpp\n");
        return 2;
    }
    const auto file = rs::project::readTextFile(arguments[1]);
    if (!file.error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-native: %s\n", qPrintable(file.error));
        return 2;
    }
    const auto result = rs::compiler::compileText(file.text);
    if (result.errors()) {
        std::fprintf(stderr, "rungsmith-native: %s does not compile\n", qPrintable(arguments[1]));
        return 1;
    }
    const QString error =
        rs::project::writeTextFile(arguments[2], rs::bench::generateNativeCode(result.images));
    if (!error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-native: %s\n", qPrintable(error));
        return 2;
    }
    return 0;
}
