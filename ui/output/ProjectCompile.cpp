// SPDX-License-Identifier: GPL-3.0-or-later
#include "output/ProjectCompile.h"

#include "blocks/ProjectInstances.h"
#include "project/TextPlace.h"

namespace rs::ui {

compiler::CompileResult compileProjectText(const std::string& canonicalText,
                                           const QString& executableDir, const QString& projectPath,
                                           const compiler::CheckOptions& options,
                                           compiler::Output output) {
    const blocks::ProjectWithInstances read = blocks::readProjectWithInstances(
        canonicalText, blocks::LibraryPlaces{executableDir, projectPath, {}});
    // Given the text it was read from, the compile need not read it again
    // for its canonical places (it compares the two first).
    return blocks::compileProject(read.read.project, read.read.diagnostics, options, canonicalText,
                                  output);
}

lang::Diagnostics unitCodeDiagnostics(const std::string& canonicalText,
                                      const lang::Diagnostics& diagnostics, int station) {
    const project::TextPlaces places(canonicalText);
    lang::Diagnostics ofUnit;
    for (lang::Diagnostic diagnostic : diagnostics) {
        const project::TextPlace place = places.of(diagnostic.line);
        if (place.kind != project::TextPlace::Kind::UnitCode || place.station != station)
            continue;
        diagnostic.line = place.line;
        ofUnit.push_back(std::move(diagnostic));
    }
    return ofUnit;
}

} // namespace rs::ui
