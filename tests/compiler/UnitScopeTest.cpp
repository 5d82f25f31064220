// SPDX-License-Identifier: GPL-3.0-or-later
// A check of one unit's code alone (CheckOptions::onlyUnit, what the text
// view runs as the user types) finds in that code what the whole project's
// check finds there.
#include "RandomProgram.h"
#include "compiler/Compiler.h"
#include "lang/OperandWalk.h"
#include "lang/Printer.h"
#include "project/ProjectFile.h"
#include "project/TextPlace.h"
#include "project/UnitText.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>

#include <algorithm>
#include <set>
#include <tuple>

namespace {

using namespace rs;

using Finding = std::tuple<int, int, lang::Severity, std::string>;

// The findings in the code of `station`, at lines of that code.
std::vector<Finding> findingsInUnit(const std::string& text, const lang::Diagnostics& found,
                                    int station) {
    const project::TextPlaces places(text);
    std::vector<Finding> inUnit;
    for (const auto& diagnostic : found) {
        const project::TextPlace place = places.of(diagnostic.line);
        if (place.kind == project::TextPlace::Kind::UnitCode && place.station == station)
            inUnit.emplace_back(place.line, diagnostic.column, diagnostic.severity,
                                diagnostic.message);
    }
    std::sort(inUnit.begin(), inUnit.end());
    return inUnit;
}

std::vector<Finding> wholeCheck(const std::string& text, int station) {
    const project::ProjectReadResult read = project::readProject(text);
    const compiler::CompileResult result =
        compiler::compile(read.project, {}, text, compiler::Output::DiagnosticsOnly);
    return findingsInUnit(text, result.diagnostics, station);
}

std::vector<Finding> unitCheck(const project::Project& whole, int station) {
    compiler::CheckOptions options;
    options.onlyUnit = compiler::unitScope(whole, station, options);
    const std::string text = project::writeProject(project::withOnlyCodeOf(whole, station));
    const project::ProjectReadResult read = project::readProject(text);
    const compiler::CompileResult result =
        compiler::compile(read.project, options, text, compiler::Output::DiagnosticsOnly);
    return findingsInUnit(text, result.diagnostics, station);
}

// Every unit of the project is checked alone and compared with the whole check.
int expectSameFindings(const std::string& text, const std::string& what) {
    const project::ProjectReadResult read = project::readProject(text);
    if (!read.ok())
        return 0;
    const std::string canonical = project::writeProject(read.project);
    const project::ProjectReadResult whole = project::readProject(canonical);
    int findings = 0;
    for (int station : whole.project.stations()) {
        const auto expected = wholeCheck(canonical, station);
        EXPECT_EQ(unitCheck(whole.project, station), expected) << what << ", unit " << station;
        findings += static_cast<int>(expected.size());
    }
    return findings;
}

// A random program whose units are declared (id and type), so that their
// code is checked against a unit type, with names the units share.
std::string randomProject(unsigned seed) {
    test::RandomProgram random(seed);
    lang::Document document = random.document();
    std::set<int> stations;
    for (const auto& unit : document.units)
        stations.insert(unit.station());
    std::vector<lang::Line> declared;
    for (int station : stations) {
        declared.push_back(
            {lang::Declaration{
                 lang::IdDeclaration{lang::UnitFamily::Pluto, station, "000000000000"}, {}},
             std::nullopt,
             {}});
        declared.push_back(
            {lang::Declaration{lang::TypeDeclaration{station, "A20", 3}, {}}, std::nullopt, {}});
    }
    // Every name the code uses stands for a global memory of its own.
    std::set<std::string> names;
    std::set<std::string> declaredNames;
    auto noteDeclared = [&](const std::vector<lang::Line>& lines) {
        for (const auto& line : lines)
            if (const auto* declaration = std::get_if<lang::Declaration>(&line.body))
                if (const auto* name = std::get_if<lang::NameDeclaration>(&declaration->body))
                    declaredNames.insert(name->name);
    };
    noteDeclared(document.preamble);
    for (const auto& unit : document.units) {
        noteDeclared(unit.declarations);
        for (const auto& step : unit.steps)
            for (const auto& line : step.lines)
                if (const auto* statement = std::get_if<lang::Statement>(&line.body))
                    lang::forEachOperand(*statement, [&](const lang::Operand& operand) {
                        if (operand.isName() && !declaredNames.count(operand.name))
                            names.insert(operand.name);
                    });
    }
    int memory = 100;
    for (const auto& name : names) {
        lang::Operand variable{{}, {lang::AddressKind::GlobalMemory, 0, memory++}, {}};
        declared.push_back(
            {lang::Declaration{lang::NameDeclaration{variable, name, {}}, {}}, std::nullopt, {}});
    }
    document.preamble.insert(document.preamble.begin(), declared.begin(), declared.end());
    // Each unit names variables that the code of the units uses, its own or
    // others': whether those names are used depends on the other units' code.
    std::vector<lang::Address> used;
    for (const auto& unit : document.units)
        for (const auto& step : unit.steps)
            for (const auto& line : step.lines)
                if (const auto* statement = std::get_if<lang::Statement>(&line.body))
                    lang::forEachOperand(*statement, [&](const lang::Operand& operand) {
                        if (!operand.isName() && operand.address.valid() &&
                            operand.address.kind != lang::AddressKind::Sequence)
                            used.push_back(operand.address);
                    });
    for (std::size_t u = 0; u < document.units.size() && !used.empty(); ++u)
        for (std::size_t k = 0; k < 4; ++k) {
            const lang::Operand variable{{}, used[(seed + 7 * u + 3 * k) % used.size()], {}};
            const std::string name = "Shared" + std::to_string(u) + "_" + std::to_string(k);
            document.units[u].declarations.push_back(
                {lang::Declaration{lang::NameDeclaration{variable, name, {}}, {}},
                 std::nullopt,
                 {}});
        }
    return lang::print(document);
}

TEST(UnitScope, EachUnitCheckedAloneFindsWhatTheWholeCheckFindsInRandomProjects) {
    int findings = 0;
    for (unsigned seed = 1; seed <= 300; ++seed)
        findings += expectSameFindings(randomProject(seed), "seed " + std::to_string(seed));
    EXPECT_GT(findings, 300); // the programs are checked in depth, not refused early
}

TEST(UnitScope, EachUnitCheckedAloneFindsWhatTheWholeCheckFindsInTheExamples) {
    const QDir examples(QStringLiteral(RUNGSMITH_EXAMPLES));
    int projects = 0;
    for (const QString& name : examples.entryList({QStringLiteral("*.sps")})) {
        QFile file(examples.filePath(name));
        ASSERT_TRUE(file.open(QIODevice::ReadOnly));
        expectSameFindings(file.readAll().toStdString(), name.toStdString());
        ++projects;
    }
    EXPECT_GE(projects, 5);
}

// A name is used when another unit's code uses its variable: the unit's
// check alone must not call it unused.
TEST(UnitScope, ANameOnlyAnotherUnitUsesIsNotUnused) {
    const std::string text = "! id_pluto:00=000000000000\n"
                             "! type_pluto:00=A20,is3\n"
                             "! id_pluto:01=000000000000\n"
                             "! type_pluto:01=A20,is3\n"
                             "! pgm_pluto:00\n"
                             "! GM0.3=Shared\n"
                             "! GM0.5=Unused\n"
                             "S0.0_0\n"
                             "GM0.4 = I0.1\n"
                             "! pgm_pluto:01\n"
                             "S1.0_0\n"
                             "Q1.2 = GM0.3\n";
    const project::ProjectReadResult read = project::readProject(text);
    ASSERT_TRUE(read.ok());
    compiler::CheckOptions options;
    options.warnUnconfiguredIo = false;
    options.onlyUnit = compiler::unitScope(read.project, 0, options);
    const compiler::CompileResult alone =
        compiler::compile(read.project, options, {}, compiler::Output::DiagnosticsOnly);
    std::vector<std::string> messages;
    for (const auto& diagnostic : alone.diagnostics)
        messages.push_back(diagnostic.message);
    EXPECT_EQ(messages, std::vector<std::string>{"'Unused' (GM0.5) is named but never used"});
}

} // namespace
