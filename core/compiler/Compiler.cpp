// SPDX-License-Identifier: GPL-3.0-or-later
#include "Compiler.h"

#include "AsiCheck.h"
#include "CodeGenerator.h"
#include "ExportCheck.h"
#include "GatewayCheck.h"
#include "ImageCodec.h"
#include "ImageSetup.h"
#include "Signature.h"
#include "project/ProjectFile.h"

#include <algorithm>
#include <future>
#include <iterator>
#include <string>
#include <tuple>

namespace rs::compiler {

namespace {

// The units as their declarations, the project's exports and their system
// calls set them up; what contradicts itself is reported.
UnitSetups setUpUnits(const project::Project& project, lang::Diagnostics& diagnostics) {
    UnitSetups units = collectUnits(project.program, diagnostics);
    collectExports(project, units, diagnostics);
    collectSystemCalls(project.program, units, diagnostics);
    return units;
}

// A unit's image larger than a Pluto holds is an error at its code's header.
// Encoding (and compressing the source) only to measure is needed just near
// the limit.
bool fitsTheUnit(const UnitImage& image, const UnitSetup& unit, const UnitSetups& checked,
                 lang::Diagnostics& diagnostics) {
    const std::size_t size =
        encodedSizeBound(image) > kMaxUnitImageBytes ? encodeImage(image).size() : 0;
    if (size <= kMaxUnitImageBytes)
        return true;
    const auto original = checked.find(unit.station);
    const lang::SourceLocation at = original != checked.end() && original->second.program
                                        ? original->second.program->header.location
                                        : lang::SourceLocation{};
    diagnostics.push_back({lang::Severity::Error, at.line, at.column,
                           "program of unit " + std::to_string(unit.station) + " is " +
                               std::to_string(size) + " bytes; a Pluto " +
                               std::string(unit.type->display) + " holds at most " +
                               std::to_string(kMaxUnitImageBytes) + " bytes"});
    return false;
}

} // namespace

CompileResult compile(const project::Project& project, const CheckOptions& options,
                      std::string_view readFrom, Output output) {
    CompileResult result;
    // The canonical text (for the images' source CRC, and to know whether the
    // project was read from it) is printed on another core while this one
    // checks: the printing reads the project as the checks do and changes
    // nothing (issue 23: 12 of a large project's 60 ms of checking and printing).
    std::future<std::string> printing;
    if (output == Output::Images)
        printing = std::async(std::launch::async, [&project, readFrom] {
            // Read from its canonical text, as a saved project is, the text is
            // as long as that: a little room more, and it is never moved.
            return project::writeProject(project, readFrom.size() + readFrom.size() / 64 + 4096);
        });
    UnitSetups units = setUpUnits(project, result.diagnostics);
    checkAsiSlaves(project, units, result.diagnostics);
    checkGatewayBlocks(project, units, result.diagnostics);
    lang::Diagnostics checks = checkProgram(project.program, units, options);
    // A large project's thousands of warnings are taken over, not copied.
    if (result.diagnostics.empty())
        result.diagnostics = std::move(checks);
    else
        result.diagnostics.insert(result.diagnostics.end(), std::make_move_iterator(checks.begin()),
                                  std::make_move_iterator(checks.end()));
    lang::sortByPlace(result.diagnostics);
    if (result.errors())
        return result;
    if (output == Output::DiagnosticsOnly) {
        // Only the size of each image can still be an error; the canonical
        // text counts only when the images carry it.
        const std::string canonical =
            project.includeSource ? project::writeProject(project) : std::string();
        for (const auto& [station, unit] : units) {
            if (!unit.program || (options.onlyUnit && options.onlyUnit->station != station))
                continue;
            UnitImage image = generateCode(unit);
            addSetup(image, unit, project);
            image.projectName = project.name(); // it counts, as the source does
            image.source = canonical;
            fitsTheUnit(image, unit, units, result.diagnostics);
        }
        lang::sortByPlace(result.diagnostics);
        return result;
    }
    std::string canonical = printing.get();
    const std::uint32_t sourceCrc = crc32(canonical);
    // The code is generated from the canonical text read back, so the line
    // and column each instruction keeps are places in that text: formatting
    // cannot move them, and they are places in the source an image includes.
    // A project read from its canonical text has those places already: a file
    // saved by Rungsmith is not parsed twice.
    const bool canonicalAlready = !readFrom.empty() && readFrom == canonical;
    const project::ProjectReadResult reread =
        canonicalAlready ? project::ProjectReadResult{} : project::readProject(canonical);
    const project::Project& source = canonicalAlready || !reread.ok() ? project : reread.project;
    if (!project.includeSource) // the images do not carry it: its memory goes to the code
        std::string().swap(canonical);
    lang::Diagnostics again; // the same as above: the checks passed
    UnitSetups sourceUnits = setUpUnits(source, again);
    for (const auto& [station, unit] : sourceUnits) {
        UnitImage image = generateCode(unit);
        addSetup(image, unit, source);
        result.signatures.push_back({station, unitSignature(image)});
        if (!unit.program)
            continue;
        image.projectName = project.name();
        image.sourceCrc = sourceCrc;
        if (project.includeSource)
            image.source = canonical;
        if (!fitsTheUnit(image, unit, units, result.diagnostics))
            continue;
        result.images.push_back(std::move(image));
    }
    result.projectSignature = projectSignature(result.signatures);
    for (auto& image : result.images)
        image.projectSignature = result.projectSignature;
    if (result.errors()) {
        result.images.clear();
        result.signatures.clear();
        result.projectSignature = 0;
        lang::sortByPlace(result.diagnostics);
    }
    return result;
}

UnitScope unitScope(const project::Project& project, int station, const CheckOptions& options) {
    lang::Diagnostics ignored; // the whole check reports them
    const UnitSetups units = setUpUnits(project, ignored);
    return {station, usedByOtherUnits(project.program, units, options, station)};
}

CompileResult compileText(std::string_view text, const CheckOptions& options) {
    project::ProjectReadResult read = project::readProject(text);
    if (!read.ok()) {
        CompileResult failed;
        failed.diagnostics = std::move(read.diagnostics);
        return failed;
    }
    CompileResult result = compile(read.project, options);
    result.diagnostics.insert(result.diagnostics.begin(), read.diagnostics.begin(),
                              read.diagnostics.end());
    lang::sortByPlace(result.diagnostics);
    return result;
}

} // namespace rs::compiler
