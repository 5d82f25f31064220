// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramCheck.h"

#include "lang/AddressSet.h"
#include "lang/Keywords.h"
#include "lang/Printer.h"
#include "lang/SymbolicName.h"

#include <algorithm>
#include <set>

namespace rs::compiler {

namespace {

using lang::Address;
using lang::AddressKind;
using lang::Expr;
using lang::ExprKind;
using lang::Operand;
using lang::SourceLocation;
using lang::Statement;
using lang::StatementKind;

constexpr int kMaxTimers = 50;
constexpr int kMaxStep = 254;

enum class Use { ReadBit, WriteBit, ReadWord, WriteWord };

std::string two(int station) {
    return (station < 10 ? "0" : "") + std::to_string(station);
}

// The variable a name or use stands for: halves and bits belong to their register.
Address storage(Address a) {
    if (a.kind == AddressKind::DoubleRegisterLow || a.kind == AddressKind::DoubleRegisterHigh)
        a.kind = AddressKind::DoubleRegister;
    if (a.kind == AddressKind::RegisterBit) {
        a.kind = AddressKind::Register;
        a.bit = -1;
    }
    return a;
}

// A register bit or a half of a double register is readable when its register is exported.
bool isExported(const UnitSetup& unit, const Address& a) {
    return unit.exported.contains(storage(a));
}

bool isDoubleWord(const Address& a) {
    return a.kind == AddressKind::DoubleRegister;
}

bool isSixteenBit(const Address& a) {
    return a.kind == AddressKind::Register || a.kind == AddressKind::DoubleRegisterLow ||
           a.kind == AddressKind::DoubleRegisterHigh;
}

// The I/O options that make an IA terminal a value rather than an ordinary input.
bool isValueOption(const std::string& option) {
    return option == lang::kVoltageOption || option == lang::kCurrentOption ||
           option == lang::kCounterUpOption || option == lang::kCounterUpDownOption;
}

std::string shown(const Operand& operand) {
    return operand.isName() ? "'" + operand.name + "' (" + lang::toString(operand.address) + ")"
                            : lang::toString(operand.address);
}

struct Write {
    int sequence;
    int step;
    SourceLocation at;
};

class Checker {
public:
    Checker(const lang::Document& document, const UnitSetups& units, const CheckOptions& options)
        : m_document(document), m_units(units), m_options(options),
          m_scope(options.onlyUnit ? &*options.onlyUnit : nullptr) {}

    lang::Diagnostics run() {
        if (m_scope)
            for (const Address& a : m_scope->usedByOtherUnits) {
                m_used.insert(a);
                m_usedStorage.insert(storage(a));
            }
        for (const auto& [station, unit] : m_units)
            if (unit.program && (!m_scope || station == m_scope->station))
                checkUnit(unit);
        warnUnusedNames();
        return std::move(m_diagnostics);
    }

    // A unit's checks for the variables it uses (used()), its findings dropped.
    void checkUnitAlone(const UnitSetup& unit) {
        checkUnit(unit);
        m_diagnostics.clear();
    }
    const lang::AddressSet& used() const { return m_used; }

private:
    void error(SourceLocation at, std::string message) {
        m_diagnostics.push_back({lang::Severity::Error, at.line, at.column, std::move(message)});
    }
    void warning(SourceLocation at, std::string message) {
        m_diagnostics.push_back({lang::Severity::Warning, at.line, at.column, std::move(message)});
    }

    // ----- structure of steps and sequences
    void checkUnit(const UnitSetup& unit) {
        m_unit = &unit;
        m_otherProjectUnitsWarned.clear();
        m_timers = 0;
        m_doubleRegisters.clear();
        m_coils.clear();
        m_latches.clear();
        m_coilAndLatch.clear();
        m_steps.clear();
        const auto& program = *unit.program;

        for (const auto& step : program.steps) {
            const auto& a = step.address;
            if (a.sequence > 9) {
                error(step.location, "sequences are numbered 1-9 (0 is the PLC code), not " +
                                         std::to_string(a.sequence));
                continue;
            }
            if (a.sequence == 0 && a.step != 0) {
                error(step.location, "the PLC code " +
                                         lang::toString(lang::StepAddress{a.unit, 0, 0}) +
                                         " has only step 0; steps belong in sequences 1-9");
                continue;
            }
            if (a.step > kMaxStep) {
                error(step.location, "steps are numbered 0-254, not " + std::to_string(a.step));
                continue;
            }
            auto& steps = m_steps[a.sequence];
            if (auto it = steps.find(a.step); it != steps.end()) {
                error(step.location, lang::toString(a) + " is already declared at line " +
                                         std::to_string(it->second->location.line));
                continue;
            }
            steps[a.step] = &step;
        }
        if (!m_steps.count(0))
            error(program.header.location, "the code of unit " + std::to_string(unit.station) +
                                               " has no PLC code step S" +
                                               std::to_string(unit.station) + ".0_0");
        for (const auto& [sequence, steps] : m_steps)
            if (!steps.count(0)) {
                const auto* first = steps.begin()->second;
                error(first->location,
                      "sequence " + std::to_string(sequence) + " has no step 0 (" +
                          lang::toString(lang::StepAddress{unit.station, sequence, 0}) +
                          "), where it starts");
            }

        collectDoubleRegisters(program);
        std::map<int, std::set<int>> jumpTargets;
        for (const auto& [sequence, steps] : m_steps)
            for (const auto& [number, step] : steps)
                for (const auto& line : step->lines)
                    if (const auto* statement = std::get_if<Statement>(&line.body))
                        checkStatement(*statement, sequence, number, jumpTargets[sequence]);
                    else if (auto call = unit.systemCalls.find(&line);
                             call != unit.systemCalls.end())
                        checkSystemCall(call->second, sequence, number);

        for (const auto& [sequence, steps] : m_steps) {
            if (sequence == 0)
                continue;
            for (const auto& [number, step] : steps)
                if (number != 0 && !jumpTargets[sequence].count(number))
                    warning(step->location,
                            "no jump leads to step " + lang::toString(step->address));
        }
    }

    void collectDoubleRegisters(const lang::UnitProgram& program) {
        auto note = [&](const Operand& operand, SourceLocation at) {
            const Address& a = operand.address;
            if (a.unit == m_unit->station &&
                (a.kind == AddressKind::DoubleRegister ||
                 a.kind == AddressKind::DoubleRegisterLow ||
                 a.kind == AddressKind::DoubleRegisterHigh) &&
                !m_doubleRegisters.count(a.index))
                m_doubleRegisters[a.index] = at;
        };
        forEachOperand(program, note);
        for (const auto& entry : m_unit->systemCalls)
            for (const auto& argument : entry.second.arguments)
                if (argument.operand)
                    note(*argument.operand, argument.location);
    }

    template <typename F> static void forEachOperand(const lang::UnitProgram& program, F&& visit) {
        for (const auto& step : program.steps)
            for (const auto& line : step.lines)
                if (const auto* s = std::get_if<Statement>(&line.body)) {
                    visitStatementOperands(*s, visit);
                }
    }

    template <typename F> static void visitStatementOperands(const Statement& s, F& visit) {
        if (s.kind == StatementKind::Assign) {
            visit(s.assignment->target, s.assignment->target.location);
            if (s.assignment->left.operand)
                visit(*s.assignment->left.operand, s.assignment->left.operand->location);
            if (s.assignment->right.operand)
                visit(*s.assignment->right.operand, s.assignment->right.operand->location);
        } else if (s.kind != StatementKind::Jump) {
            visit(s.target, s.target.location);
        }
        if (s.condition)
            visitExprOperands(*s.condition, visit);
    }

    template <typename F> static void visitExprOperands(const Expr& e, F& visit) {
        for (const auto& child : e.children)
            visitExprOperands(child, visit);
        if (e.kind == ExprKind::Contact || e.kind == ExprKind::Edge || e.kind == ExprKind::Compare)
            visit(e.operand, e.operand.location);
        if (e.kind == ExprKind::Compare && e.right.operand)
            visit(*e.right.operand, e.right.operand->location);
        if (e.kind == ExprKind::Timer && e.preset.registerOperand)
            visit(*e.preset.registerOperand, e.preset.registerOperand->location);
    }

    // ----- statements
    void checkStatement(const Statement& s, int sequence, int step, std::set<int>& jumpTargets) {
        switch (s.kind) {
        case StatementKind::Coil:
            if (checkOperand(s.target, Use::WriteBit))
                noteCoil(s.target, sequence, step);
            break;
        case StatementKind::Set:
        case StatementKind::Reset:
            if (checkOperand(s.target, Use::WriteBit))
                noteLatch(s.target);
            break;
        case StatementKind::Toggle:
            checkOperand(s.target, Use::WriteBit);
            break;
        case StatementKind::Jump:
            checkJump(s, sequence, step, jumpTargets);
            break;
        case StatementKind::SequenceReset:
            checkSequenceReset(s, sequence);
            break;
        case StatementKind::Assign:
            checkAssignment(s);
            break;
        }
        if (s.condition)
            checkExpr(*s.condition);
    }

    // A system instruction writes its bit outputs in every scan its step
    // runs, as a coil does.
    void checkSystemCall(const SystemCall& call, int sequence, int step) {
        for (std::size_t i = 0; i < call.arguments.size(); ++i) {
            const SystemParameter& parameter = call.instruction->parameters[i];
            const lang::Value& argument = call.arguments[i];
            if (!argument.operand) {
                checkConstant(argument, parameter.kind == ParameterKind::DoubleRegister);
                continue;
            }
            if (!parameter.analogueOption.empty() &&
                !declaredAs(*argument.operand, parameter.analogueOption, *call.instruction))
                continue;
            const bool output = parameter.direction == ParameterDirection::Out;
            const bool bit = parameter.kind == ParameterKind::Bit;
            const Use use = bit ? (output ? Use::WriteBit : Use::ReadBit)
                                : (output ? Use::WriteWord : Use::ReadWord);
            if (checkOperand(*argument.operand, use) && output && bit)
                noteCoil(*argument.operand, sequence, step);
        }
    }

    // An analogue input that a system instruction reads as a value in the
    // unit of `option` (mV for voltage, µA for current) must not be declared
    // otherwise; undeclared, it is unconfigured I/O, as anywhere.
    bool declaredAs(const Operand& operand, std::string_view option,
                    const SystemInstruction& instruction) {
        const Address& a = operand.address;
        const auto unit = m_units.find(a.unit);
        if (unit == m_units.end())
            return true;
        const auto declared = unit->second.analogTerminals.find(a.index);
        if (declared == unit->second.analogTerminals.end())
            return true;
        const auto& options = declared->second.options;
        if (std::find(options.begin(), options.end(), option) != options.end())
            return true;
        const auto valueOption = std::find_if(options.begin(), options.end(), isValueOption);
        error(operand.location,
              std::string(instruction.name) + " reads " + shown(operand) + " as a " +
                  std::string(option) + " input, but line " +
                  std::to_string(declared->second.location.line) + " declares it " +
                  (valueOption == options.end() ? "an ordinary input"
                                                : "a " + *valueOption + " input"));
        return false;
    }

    void checkJump(const Statement& s, int sequence, int step, std::set<int>& jumpTargets) {
        Statement jump = s;
        jump.condition.reset();
        const std::string text = lang::printStatement(jump);
        if (sequence == 0) {
            error(s.location, text + " in the PLC code: jumps belong in sequences 1-9");
            return;
        }
        const int target = s.relativeJump ? step + s.jumpStep : s.jumpStep;
        const auto& steps = m_steps[sequence];
        if (!steps.count(target)) {
            error(s.location, text + " jumps to step " + std::to_string(target) +
                                  ", which sequence " + std::to_string(sequence) +
                                  " does not have");
            return;
        }
        jumpTargets.insert(target);
    }

    void checkSequenceReset(const Statement& s, int sequence) {
        const Address& a = s.target.address;
        const std::string name = lang::toString(a);
        if (a.unit != m_unit->station) {
            error(s.target.location, "R(" + name + ") resets a sequence of unit " +
                                         std::to_string(a.unit) + "; a unit resets only its own");
            return;
        }
        if (a.index < 1 || a.index > 9) {
            error(s.target.location, "only sequences 1-9 can be reset, not " + name);
            return;
        }
        if (!m_steps.count(a.index)) {
            error(s.target.location, "R(" + name + ") resets sequence " + std::to_string(a.index) +
                                         ", which unit " + std::to_string(a.unit) +
                                         " does not have");
            return;
        }
        if (a.index == sequence)
            error(s.target.location, "sequence " + std::to_string(sequence) +
                                         " cannot reset itself; a reset must come from another "
                                         "sequence or the PLC code");
    }

    void checkAssignment(const Statement& s) {
        const auto& a = *s.assignment;
        if (!checkOperand(a.target, Use::WriteWord))
            return;
        const bool set3 = m_unit->instructionSet >= 3;
        switch (a.op) {
        case lang::AssignOp::MulAssign:
        case lang::AssignOp::DivAssign:
            if (!set3)
                needsSet3(s.location, "multiplication and division");
            break;
        case lang::AssignOp::Binary:
            if (!set3)
                needsSet3(s.location, "arithmetic with three operands (R = a op b)");
            break;
        default:
            break;
        }
        for (const lang::Value* value : {&a.left, &a.right}) {
            const bool used = a.op == lang::AssignOp::Binary || value == &a.left;
            if (!used || a.op == lang::AssignOp::Increment || a.op == lang::AssignOp::Decrement)
                continue;
            if (value->operand)
                checkOperand(*value->operand, Use::ReadWord);
            else
                checkConstant(*value, isDoubleWord(a.target.address));
        }
        const bool divide = a.op == lang::AssignOp::DivAssign ||
                            (a.op == lang::AssignOp::Binary && a.binary == lang::BinaryOp::Div);
        if (divide) {
            if (isDoubleWord(a.target.address))
                error(a.target.location, shown(a.target) +
                                             ": a double register cannot be divided; "
                                             "divide into a register, as in (R0.1 = DR0.2 / R0.4)");
            const lang::Value& divisor = a.op == lang::AssignOp::DivAssign ? a.left : a.right;
            if (divisor.operand && isDoubleWord(divisor.operand->address))
                error(divisor.operand->location, "a double register cannot be a divisor");
            if (divisor.isConstant() && divisor.constant == 0)
                warning(divisor.location,
                        "division by zero: the result is 0 and SM_DivByZero is set");
        }
    }

    void checkConstant(const lang::Value& value, bool doubleWord) {
        const std::int64_t low = doubleWord ? INT32_MIN : -32768;
        const std::int64_t high = doubleWord ? INT32_MAX : 32767;
        if (value.constant < low || value.constant > high)
            error(value.location,
                  std::to_string(value.constant) + " does not fit a " +
                      (doubleWord ? "double register (32 bits)" : "register (-32768..32767)"));
    }

    void checkExpr(const Expr& e) {
        switch (e.kind) {
        case ExprKind::Or:
        case ExprKind::And:
            for (const auto& child : e.children)
                checkExpr(child);
            return;
        case ExprKind::Contact:
            checkOperand(e.operand, Use::ReadBit);
            return;
        case ExprKind::Edge:
            if (e.negated && m_unit->instructionSet < 3)
                needsSet3(e.location, std::string(e.risingEdge ? "'Not positive edge' /P(...)"
                                                               : "'Not negative edge' /N(...)"));
            checkOperand(e.operand, Use::ReadBit);
            return;
        case ExprKind::Timer:
            if (++m_timers == kMaxTimers + 1)
                error(e.location, "more than 50 timers in unit " + std::to_string(m_unit->station));
            if (lang::timerKind(e.timer) == lang::TimerKind::OffDelay && m_unit->instructionSet < 3)
                needsSet3(e.location, "the off-delay timer TOF");
            if (e.preset.registerOperand) {
                const Operand& preset = *e.preset.registerOperand;
                if (checkOperand(preset, Use::ReadWord) && !isSixteenBit(preset.address))
                    error(preset.location, shown(preset) +
                                               " cannot hold a timer's time: use a register (R) "
                                               "holding hundredths of a second");
            } else if (e.preset.hundredths < 1 || e.preset.hundredths > 65535)
                error(e.location, "a time must be between 0s01 and 655s35, not " +
                                      lang::formatTime(e.preset.hundredths));
            return;
        case ExprKind::Compare:
            checkOperand(e.operand, Use::ReadWord);
            if (e.right.operand)
                checkOperand(*e.right.operand, Use::ReadWord);
            else
                checkConstant(e.right, !isSixteenBit(e.operand.address));
            return;
        }
    }

    void needsSet3(SourceLocation at, const std::string& feature) {
        const int station = m_unit->station;
        error(at, feature + ": only with instruction set 3; unit " + std::to_string(station) +
                      " uses instruction set 2 (declare '! type_pluto:" + two(station) + "=" +
                      std::string(m_unit->type->name) + ",is3')");
    }

    // ----- operands
    bool checkOperand(const Operand& operand, Use use) {
        const Address& a = operand.address;
        if (!a.valid())
            return false; // an unknown name, reported by name resolution
        m_used.insert(a);
        m_usedStorage.insert(storage(a));
        const SourceLocation at = operand.location;
        if (a.unit > 31) {
            error(at, shown(operand) + " belongs to unit " + std::to_string(a.unit) +
                          ", but stations are numbered 0-31");
            return false;
        }
        auto owner = m_units.find(a.unit);
        if (owner == m_units.end())
            return checkOtherProjectOperand(operand, use);
        const UnitSetup& unit = owner->second;
        if (a.kind == AddressKind::DoubleRegister || a.kind == AddressKind::DoubleRegisterLow ||
            a.kind == AddressKind::DoubleRegisterHigh) {
            if (a.index % 2 != 0) {
                error(at, shown(operand) + ": a double register has an even number (DR" +
                              std::to_string(a.unit) + "." + std::to_string(a.index - 1) + " is R" +
                              std::to_string(a.unit) + "." + std::to_string(a.index - 1) +
                              " and R" + std::to_string(a.unit) + "." + std::to_string(a.index) +
                              ")");
                return false;
            }
        }
        if (!target::hasVariable(*unit.type, a, unit.instructionSet)) {
            const bool moreWithSet3 = a.kind == AddressKind::Memory && unit.instructionSet < 3 &&
                                      a.index < target::memoryCount(*unit.type, 3);
            error(at, shown(operand) + " does not exist on unit " + std::to_string(a.unit) + ", " +
                          target::withArticle(*unit.type) +
                          (moreWithSet3 ? " with instruction set 2" : ""));
            return false;
        }
        if (operand.isName() && lang::systemName(operand.name, a.unit).valid()) {
            const target::SystemVariable* system = target::systemVariable(*unit.type, a);
            if (!system || lang::foldName(system->name) != lang::foldName(operand.name)) {
                error(at, "'" + operand.name + "' is not a system " +
                              (a.kind == AddressKind::SystemMemory ? "memory" : "register") +
                              " of " + target::withArticle(*unit.type));
                return false;
            }
        }
        if (auto feature = target::instructionSet3Feature(a);
            feature && m_unit->instructionSet < 3) {
            needsSet3(at, std::string(*feature) + " (" + lang::toString(a) + ")");
            return false;
        }
        const bool write = use == Use::WriteBit || use == Use::WriteWord;
        if (a.unit != m_unit->station) {
            if (write) {
                error(at, shown(operand) + " belongs to unit " + std::to_string(a.unit) +
                              "; a unit writes only its own variables");
                return false;
            }
            if (!target::isGlobal(*unit.type, a) && !isExported(unit, a)) {
                error(at, shown(operand) + " is local to unit " + std::to_string(a.unit) +
                              " and not exported; other units cannot read it");
                return false;
            }
        }
        if (write && !checkWritable(operand, unit))
            return false;
        checkRegisterHalves(operand);
        checkTerminal(operand, unit, use);
        return true;
    }

    // A unit that is not in the project may be on the bus with a project of
    // its own: its globals can be read (language.md), with a warning once per
    // reading unit, since this project cannot check what they are.
    bool checkOtherProjectOperand(const Operand& operand, Use use) {
        const Address& a = operand.address;
        const bool write = use == Use::WriteBit || use == Use::WriteWord;
        if (write || !isGlobalOfSomeType(a)) {
            error(operand.location,
                  shown(operand) + " belongs to unit " + std::to_string(a.unit) +
                      ", which the project does not have (no '! id_pluto:" + two(a.unit) +
                      "=...')" + (write ? "" : "; only its globals can be read"));
            return false;
        }
        if (m_otherProjectUnitsWarned.insert(a.unit).second)
            warning(operand.location, "unit " + std::to_string(a.unit) +
                                          " is not in this project; its globals come from "
                                          "another project on the bus");
        return true;
    }

    static bool isGlobalOfSomeType(const Address& a) {
        return std::any_of(target::unitTypes().begin(), target::unitTypes().end(),
                           [&](const target::UnitTypeInfo& type) {
                               return target::hasVariable(type, a, 3) && target::isGlobal(type, a);
                           });
    }

    bool checkWritable(const Operand& operand, const UnitSetup& unit) {
        const Address& a = operand.address;
        switch (a.kind) {
        case AddressKind::Input:
        case AddressKind::AnalogInput:
        case AddressKind::AsiInput:
            error(operand.location, shown(operand) + " is an input; the program cannot write it");
            return false;
        case AddressKind::SystemMemory:
        case AddressKind::SystemRegister: {
            const target::SystemVariable* system = target::systemVariable(*unit.type, a);
            if (system && system->access == target::Access::Write)
                return true;
            error(
                operand.location,
                shown(operand) +
                    (system && lang::foldName(operand.name) != lang::foldName(system->name)
                         ? " (" + std::string(system->name) + ")"
                         : std::string()) +
                    " is read-only; the program may write only SM_TimerFreeze and SR_PlutoDisplay");
            return false;
        }
        default:
            return true;
        }
    }

    void checkRegisterHalves(const Operand& operand) {
        const Address& a = operand.address;
        if (a.unit != m_unit->station ||
            (a.kind != AddressKind::Register && a.kind != AddressKind::RegisterBit))
            return;
        const int low = a.index - a.index % 2;
        auto it = m_doubleRegisters.find(low);
        if (it == m_doubleRegisters.end())
            return;
        const std::string dr = "DR" + std::to_string(a.unit) + "." + std::to_string(low);
        const std::string half = lang::toString(Address{AddressKind::Register, a.unit, a.index});
        const std::string used = " (used at line " + std::to_string(it->second.line) + ")";
        if (a.kind == AddressKind::RegisterBit)
            error(operand.location, lang::toString(a) + " is a bit of " + half +
                                        ", which is half of " + dr + used +
                                        "; bits of a double register cannot be addressed");
        else
            error(operand.location, half + " is half of " + dr + used + "; write " + dr +
                                        (a.index == low ? ".Lo" : ".Hi"));
    }

    void checkTerminal(const Operand& operand, const UnitSetup& unit, Use use) {
        const bool write = use == Use::WriteBit || use == Use::WriteWord;
        const Address& a = operand.address;
        const auto* type = unit.type;
        const TerminalDeclaration* declared = nullptr;
        switch (a.kind) {
        case AddressKind::Input:
        case AddressKind::InputOutput:
            break;
        case AddressKind::Output:
            if (!target::contains(type->nonSafetyOutputs, a.index))
                return;
            break;
        case AddressKind::AnalogInput:
            if (auto it = unit.analogTerminals.find(a.index); it != unit.analogTerminals.end())
                checkAnalogUse(operand, it->second, use);
            else
                warnUnconfigured(operand, a);
            return;
        default:
            return;
        }
        if (auto it = unit.terminals.find(a.index); it != unit.terminals.end())
            declared = &it->second;
        if (!declared) {
            warnUnconfigured(operand, a);
            return;
        }
        const std::string line = std::to_string(declared->location.line);
        const std::string terminal = "terminal " + std::to_string(a.index);
        if (a.kind == AddressKind::Input && declared->kind == AddressKind::Output)
            error(operand.location,
                  shown(operand) + ": " + terminal + " is declared as an output at line " + line);
        else if (a.kind == AddressKind::Output && declared->kind == AddressKind::Input)
            error(operand.location, shown(operand) + ": " + terminal +
                                        " is declared as an input at line " + line +
                                        (write ? ""
                                               : "; read the input I" + std::to_string(a.unit) +
                                                     "." + std::to_string(a.index) + " instead"));
        else if (a.kind == AddressKind::InputOutput && declared->kind != AddressKind::InputOutput)
            error(operand.location,
                  shown(operand) + ": " + terminal + " is declared as an " +
                      (declared->kind == AddressKind::Input ? "input" : "output") + " at line " +
                      line + ", not as an illuminated push button (IQ)");
    }

    // An IA terminal is declared either as a value (voltage, current, counter)
    // or as an ordinary input; the code must use it the same way.
    void checkAnalogUse(const Operand& operand, const TerminalDeclaration& declared, Use use) {
        const bool value =
            std::any_of(declared.options.begin(), declared.options.end(), isValueOption);
        const std::string line = std::to_string(declared.location.line);
        if (value && use == Use::ReadBit)
            error(operand.location, shown(operand) + " is declared as a " +
                                        declared.options.front() + " input at line " + line +
                                        "; compare its value, as in (" +
                                        lang::toString(operand.address) + ">0)");
        else if (!value && use == Use::ReadWord)
            error(operand.location, shown(operand) + " is declared as an ordinary input at line " +
                                        line + "; use it as a contact");
    }

    void warnUnconfigured(const Operand& operand, const Address& a) {
        if (!m_options.warnUnconfiguredIo || !m_unconfigured.insert(a).second)
            return;
        warning(operand.location, "unconfigured I/O: " + lang::toString(a) +
                                      " has no I/O declaration in the code of unit " +
                                      std::to_string(a.unit));
    }

    // A coil written in two places fights itself, unless the places are steps
    // of one sequence, of which only one runs at a time.
    void noteCoil(const Operand& target, int sequence, int step) {
        Address output = target.address;
        if (output.kind == AddressKind::InputOutput)
            output.kind = AddressKind::Output; // IQ12 lights the lamp Q12
        auto& writes = m_coils[output];
        for (const auto& previous : writes)
            if (previous.sequence != sequence || sequence == 0 || previous.step == step) {
                warning(target.location, shown(target) + " is also written at line " +
                                             std::to_string(previous.at.line) +
                                             "; the write that runs last in each scan wins");
                break;
            }
        writes.push_back({sequence, step, target.location});
        if (auto latch = m_latches.find(output); latch != m_latches.end())
            warnCoilAndLatch(target, latch->second);
    }

    void noteLatch(const Operand& target) {
        Address output = target.address;
        if (output.kind == AddressKind::InputOutput)
            output.kind = AddressKind::Output;
        if (!m_latches.count(output))
            m_latches[output] = target.location;
        if (auto coil = m_coils.find(output); coil != m_coils.end() && !coil->second.empty())
            warnCoilAndLatch(target, coil->second.front().at);
    }

    void warnCoilAndLatch(const Operand& target, SourceLocation other) {
        if (!m_coilAndLatch.insert(target.address).second)
            return;
        warning(target.location, shown(target) +
                                     " is both a coil and latched with S(...)/R(...) "
                                     "(see line " +
                                     std::to_string(other.line) +
                                     "); the coil sets it every scan the line runs");
    }

    // A whole register is used when any bit or half of it is; a bit or half
    // only when it, or the whole register, is.
    bool isUsed(const Address& a) const {
        const Address whole = storage(a);
        if (a == whole)
            return m_usedStorage.contains(whole);
        return m_used.contains(a) || m_used.contains(whole);
    }

    void warnUnusedNames() {
        auto scan = [&](const std::vector<lang::Line>& lines) {
            for (const auto& line : lines)
                if (const auto* declaration = std::get_if<lang::Declaration>(&line.body))
                    if (const auto* name = std::get_if<lang::NameDeclaration>(&declaration->body))
                        if (!isUsed(name->variable.address))
                            warning(name->nameLocation, "'" + name->name + "' (" +
                                                            lang::toString(name->variable.address) +
                                                            ") is named but never used");
        };
        if (!m_scope)
            scan(m_document.preamble);
        for (const auto& program : m_document.units)
            if (!m_scope || program.station() == m_scope->station)
                scan(program.declarations);
    }

    const lang::Document& m_document;
    const UnitSetups& m_units;
    const CheckOptions& m_options;
    const UnitScope* m_scope;
    lang::Diagnostics m_diagnostics;

    const UnitSetup* m_unit = nullptr;
    int m_timers = 0;
    std::map<int, SourceLocation> m_doubleRegisters;         // by low register, first use
    std::map<int, std::map<int, const lang::Step*>> m_steps; // sequence -> step -> step
    std::map<Address, std::vector<Write>> m_coils;
    std::map<Address, SourceLocation> m_latches;
    std::set<Address> m_coilAndLatch;
    lang::AddressSet m_used;        // as used
    lang::AddressSet m_usedStorage; // the registers those belong to
    std::set<Address> m_unconfigured;
    std::set<int> m_otherProjectUnitsWarned; // stations not in the project that this unit reads
};

} // namespace

lang::Diagnostics checkProgram(const lang::Document& document, const UnitSetups& units,
                               const CheckOptions& options) {
    return Checker(document, units, options).run();
}

std::vector<Address> usedByOtherUnits(const lang::Document& document, const UnitSetups& units,
                                      const CheckOptions& options, int station) {
    // The checks themselves say what counts as a use (an operand checked).
    Checker checker(document, units, options);
    for (const auto& [other, unit] : units)
        if (unit.program && other != station)
            checker.checkUnitAlone(unit);
    return checker.used().sorted();
}

} // namespace rs::compiler
