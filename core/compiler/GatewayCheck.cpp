// SPDX-License-Identifier: GPL-3.0-or-later
#include "GatewayCheck.h"

#include "sim/GatewayTelegram.h"

#include <algorithm>
#include <map>
#include <set>

namespace rs::compiler {

namespace {

constexpr int kMaxUserNumber = 99;

void add(lang::Diagnostics& diagnostics, lang::Severity severity, lang::SourceLocation at,
         std::string message) {
    diagnostics.push_back({severity, at.line, at.column, std::move(message)});
}

bool isUserBlock(SystemInstructionId id) {
    return id == SystemInstructionId::ToGatewayUserA || id == SystemInstructionId::ToGatewayUserB ||
           id == SystemInstructionId::ToGatewayUserC;
}

bool isExtBlock(SystemInstructionId id) {
    return id == SystemInstructionId::ExtSig || id == SystemInstructionId::ExtVal ||
           id == SystemInstructionId::ExtVarBlock;
}

void checkCalls(const project::Project& project, const UnitSetup& unit,
                lang::Diagnostics& diagnostics) {
    std::map<std::int64_t, lang::SourceLocation> userNumbers;
    // Calls that may send in one scan: the PLC code's, and per sequence the
    // most in any one of its steps (one step of a sequence runs a scan).
    std::map<int, std::map<int, int>> sendersByStep; // sequence -> step -> calls
    const lang::SourceLocation* firstSender = nullptr;
    const auto comm = project.externalComm.find(unit.station);
    for (const auto& step : unit.program->steps)
        for (const auto& line : step.lines) {
            const auto found = unit.systemCalls.find(&line);
            if (found == unit.systemCalls.end())
                continue;
            const SystemCall& call = found->second;
            const SystemInstructionId id = call.instruction->id;
            const std::string name(call.instruction->name);
            if (isToGateway(id)) {
                ++sendersByStep[step.address.sequence][step.address.step];
                if (!firstSender)
                    firstSender = &call.location;
            }
            if (isUserBlock(id)) {
                const lang::Value& number = call.arguments.front();
                if (!number.isConstant() || number.constant < 1 ||
                    number.constant > kMaxUserNumber) {
                    add(diagnostics, lang::Severity::Error, number.location,
                        name + ": No must be a number 1-99, the block's IO-type (Gateway "
                               "manual 4.3.2)");
                    continue;
                }
                const auto [first, fresh] = userNumbers.emplace(number.constant, number.location);
                if (!fresh)
                    add(diagnostics, lang::Severity::Error, number.location,
                        name + ": user block number " + std::to_string(number.constant) +
                            " is already used at line " + std::to_string(first->second.line) +
                            "; each user block of a Pluto needs its own number 1-99 (Gateway "
                            "manual 4.3.2)");
            }
            if (isExtBlock(id)) {
                const lang::Value& block = call.arguments.front();
                if (!block.isConstant() || block.constant < 0 ||
                    block.constant >= project::kExternalCommBlocks) {
                    add(diagnostics, lang::Severity::Error, block.location,
                        name + ": BlockNo must be a number 0-3, an External Comm Block");
                    continue;
                }
                const int number = static_cast<int>(block.constant);
                if (comm == project.externalComm.end() || !comm->second.count(number))
                    add(diagnostics, lang::Severity::Warning, block.location,
                        name + ": External Comm Block " + std::to_string(number) + " of unit " +
                            std::to_string(unit.station) +
                            " receives nothing: the unit's External communication setting "
                            "does not set it up, so Valid stays 0");
            }
        }
    int senders = 0;
    for (const auto& [sequence, steps] : sendersByStep) {
        int most = 0;
        for (const auto& [step, calls] : steps)
            most = std::max(most, calls);
        senders += most;
    }
    if (senders > static_cast<int>(sim::kTelegramsPerScan))
        add(diagnostics, lang::Severity::Warning, *firstSender,
            std::to_string(senders) + " ToGateway blocks of unit " + std::to_string(unit.station) +
                " can send in one scan, and a Pluto sends at most 4 telegrams a scan (Gateway "
                "manual 4.3.4): a block past the fourth sends nothing that scan (Q 0)");
}

void checkSetting(const project::Project& project, const UnitSetup& unit,
                  lang::Diagnostics& diagnostics) {
    const auto comm = project.externalComm.find(unit.station);
    if (comm == project.externalComm.end())
        return;
    std::map<std::pair<int, int>, int> received; // (gateway, packet) -> block
    for (const auto& [block, setting] : comm->second) {
        // The records are read into the project: the unit's header stands for them.
        const lang::SourceLocation at = unit.program->header.location;
        const std::string what = "External Comm Block " + std::to_string(block) + " of unit " +
                                 std::to_string(unit.station);
        const auto gateway = project.gateways.find(setting.gateway);
        if (gateway == project.gateways.end()) {
            add(diagnostics, lang::Severity::Warning, at,
                what + " receives from gateway " + std::to_string(setting.gateway) +
                    ", which the project does not have");
            continue;
        }
        if (!gateway->second.toPluto.count(setting.packet))
            add(diagnostics, lang::Severity::Warning, at,
                what + " receives packet " + std::to_string(setting.packet) + " of gateway " +
                    std::to_string(setting.gateway) +
                    ", which does not send it (Data to Pluto is not enabled for it)");
        if (setting.timeoutMs != 0 && setting.timeoutMs <= gateway->second.cycleMs)
            add(diagnostics, lang::Severity::Warning, at,
                what + ": its timeout (" + std::to_string(setting.timeoutMs) +
                    " ms) must be greater than gateway " + std::to_string(setting.gateway) +
                    "'s cycle time (" + std::to_string(gateway->second.cycleMs) +
                    " ms, Gateway manual 4.5.1)");
        const auto [other, fresh] =
            received.emplace(std::pair(setting.gateway, setting.packet), block);
        if (!fresh)
            add(diagnostics, lang::Severity::Warning, at,
                what + " receives the packet block " + std::to_string(other->second) +
                    " receives; a gateway sends one packet to one block (Gateway manual 4.5.1)");
    }
}

} // namespace

void checkGatewayBlocks(const project::Project& project, const UnitSetups& units,
                        lang::Diagnostics& diagnostics) {
    for (const auto& [station, unit] : units) {
        if (!unit.program)
            continue;
        checkCalls(project, unit, diagnostics);
        checkSetting(project, unit, diagnostics);
    }
}

} // namespace rs::compiler
