// SPDX-License-Identifier: GPL-3.0-or-later
#include "AsiCheck.h"

#include "lang/OperandWalk.h"
#include "project/UnitAsiOptions.h"
#include "target/UnitType.h"

#include <algorithm>
#include <set>

namespace rs::compiler {

namespace {

using lang::AddressKind;
using project::AsiMode;

bool isAsi(const lang::Address& address) {
    return address.kind == AddressKind::AsiInput || address.kind == AddressKind::AsiOutput;
}

class UnitAsiCheck {
public:
    UnitAsiCheck(const project::Project& project, const UnitSetup& unit,
                 lang::Diagnostics& diagnostics)
        : m_unit(unit), m_options(project::asiOptionsOf(project, unit.station)),
          m_diagnostics(diagnostics) {}

    void operand(const lang::Operand& operand, bool written) {
        const lang::Address& a = operand.address;
        // A variable the unit lacks is already an error of its own.
        if (!isAsi(a) || a.unit != m_unit.station || !m_unit.type->asiSlaves ||
            !target::hasVariable(*m_unit.type, a, m_unit.instructionSet))
            return;
        const project::AsiSlaveAddress slaveAddress = project::slaveOf(a);
        const std::string slave = project::slaveLabel(a.unit, slaveAddress);
        if (m_options.mode == AsiMode::Unused) {
            once(slave, operand.location,
                 lang::toString(a) + ": the AS-i bus of unit " + std::to_string(a.unit) +
                     " is set as not used (AS-i Options)");
            return;
        }
        auto it = m_options.slaves.find(slaveAddress);
        if (it == m_options.slaves.end()) {
            once(slave, operand.location,
                 lang::toString(a) + ": AS-i slave " + slave +
                     " is not defined on the AS-i Options page");
            return;
        }
        const auto variables =
            project::slaveVariables(*m_unit.type, a.unit, slaveAddress, it->second.type);
        if (std::find(variables.begin(), variables.end(), a) == variables.end()) {
            once(lang::toString(a), operand.location,
                 lang::toString(a) + ": AS-i slave " + slave + " is a " +
                     std::string(project::slaveTypeName(it->second.type)) +
                     " slave, which has no such variable");
            return;
        }
        const bool monitoring = m_options.mode != AsiMode::Master;
        if (written && a.kind == AddressKind::AsiOutput && monitoring)
            once(lang::toString(a) + " written", operand.location,
                 lang::toString(a) +
                     ": this unit only monitors the AS-i bus; the external master sets the "
                     "slaves' outputs, not this program");
    }

private:
    void once(const std::string& key, lang::SourceLocation at, std::string message) {
        if (m_reported.insert(key).second)
            m_diagnostics.push_back(
                {lang::Severity::Warning, at.line, at.column, std::move(message)});
    }

    const UnitSetup& m_unit;
    project::AsiOptions m_options;
    lang::Diagnostics& m_diagnostics;
    std::set<std::string> m_reported;
};

} // namespace

void checkAsiSlaves(const project::Project& project, const UnitSetups& units,
                    lang::Diagnostics& diagnostics) {
    for (const auto& [station, options] : project.asiOptions) {
        auto unit = units.find(station);
        if (unit != units.end() && unit->second.type && !unit->second.type->asiSlaves)
            diagnostics.push_back({lang::Severity::Warning, unit->second.declared.line,
                                   unit->second.declared.column,
                                   "unit " + std::to_string(station) +
                                       " is no Pluto AS-i or B42 AS-i; its AS-i options do "
                                       "nothing"});
    }
    for (const auto& [station, unit] : units) {
        if (!unit.program || !unit.type)
            continue;
        UnitAsiCheck check(project, unit, diagnostics);
        for (const auto& step : unit.program->steps)
            for (const auto& line : step.lines)
                if (const auto* statement = std::get_if<lang::Statement>(&line.body)) {
                    const lang::Operand* written[] = {&statement->target,
                                                      &statement->assignment->target};
                    lang::forEachOperand(*statement, [&](const lang::Operand& operand) {
                        const bool isWritten = std::find(std::begin(written), std::end(written),
                                                         &operand) != std::end(written);
                        check.operand(operand, isWritten);
                    });
                }
    }
}

} // namespace rs::compiler
