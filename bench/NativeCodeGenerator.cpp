// SPDX-License-Identifier: GPL-3.0-or-later
#include "NativeCodeGenerator.h"

#include "lang/Ast.h"

#include <map>
#include <set>
#include <stdexcept>

namespace rs::bench {

namespace {

using compiler::Instruction;
using compiler::Op;
using lang::Address;
using lang::AddressKind;

std::string n(std::int64_t value) {
    return std::to_string(value);
}

class UnitWriter {
public:
    explicit UnitWriter(const compiler::UnitImage& image) : m_image(image) {}

    std::string write() {
        const std::string s = n(m_image.station);
        std::string out;
        out += "struct Unit" + s + " {\n";
        out += "    std::array<Timer, " + n(std::max<int>(1, m_image.timers)) + "> timers{};\n";
        out += "    std::array<Edge, " + n(std::max<int>(1, m_image.edges)) + "> edges{};\n";
        out += "    std::array<int, 10> active{};\n";
        out += "    std::array<bool, 10> stepNew{true, true, true, true, true, true, true, true, "
               "true, true};\n";
        out += "    std::array<bool, 10> reset{};\n};\nUnit" + s + " unit" + s + ";\n\n";
        out += leaveFunction();
        out += "void scanUnit" + s + "(Plant& plant, std::int64_t timeMs, int cycleMs) {\n";
        out += "    sim::UnitMemory& m = plant.memory[" + s + "];\n";
        out += "    const auto& bus = plant.bus;\n    auto& u = unit" + s + ";\n";
        out += "    (void)bus;\n    (void)cycleMs;\n";
        out += "    m.systemMemories[9] = plant.scan == 1;\n";
        out += "    m.systemMemories[2] = timeMs % 1000 < 400;\n";
        out += "    m.systemMemories[3] = timeMs % 1000 < 500;\n";
        out += "    m.systemMemories[4] = timeMs % 100 < 50;\n";
        out += "    m.systemMemories[5] = timeMs % 500 < 170;\n";
        out +=
            "    { const std::int64_t phase = timeMs % 1090; m.systemMemories[6] = phase < 110 || "
            "(phase >= 310 && phase < 420); }\n";
        out += "    bool p = true;\n    std::int64_t a = 0;\n    std::int64_t b = 0;\n"
               "    int jump = -1;\n    (void)a;\n    (void)b;\n";
        const int depth = maxDepth();
        for (int d = 0; d < depth; ++d)
            out += "    bool in" + n(d) + " = false, any" + n(d) + " = false;\n";
        std::map<int, std::vector<const compiler::StepCode*>> sequences;
        for (const auto& step : m_image.steps)
            sequences[step.sequence].push_back(&step);
        for (const auto& [sequence, steps] : sequences) {
            const std::string q = n(sequence);
            out += "    {\n        const bool held = u.reset[" + q + "];\n        u.reset[" + q +
                   "] = false;\n";
            out += "        if (held && u.active[" + q + "] != 0) { leave" + s + "(" + q +
                   ", u.active[" + q + "], m); u.active[" + q + "] = 0; u.stepNew[" + q +
                   "] = true; }\n";
            out += "        jump = -1;\n        m.systemMemories[0] = u.stepNew[" + q + "];\n";
            out +=
                "        u.stepNew[" + q + "] = false;\n        switch (u.active[" + q + "]) {\n";
            for (const auto* step : steps) {
                out += "        case " + n(step->step) + ": {\n";
                for (std::uint32_t i = step->first; i < step->first + step->count; ++i)
                    out += "            " + instruction(m_image.code[i]) + "\n";
                out += "            break;\n        }\n";
            }
            out += "        default:\n            break;\n        }\n";
            out += "        if (jump >= 0 && !held) { leave" + s + "(" + q + ", u.active[" + q +
                   "], m); u.active[" + q + "] = jump; u.stepNew[" + q + "] = true; }\n    }\n";
        }
        out += "    (void)p;\n    (void)jump;\n}\n\n";
        return out;
    }

private:
    int maxDepth() const {
        int depth = 0;
        int deepest = 0;
        for (const auto& in : m_image.code) {
            if (in.op == Op::BranchOpen)
                deepest = std::max(deepest, ++depth);
            if (in.op == Op::BranchClose)
                --depth;
        }
        return deepest;
    }

    std::string leaveFunction() const {
        const std::string s = n(m_image.station);
        std::string out = "void leave" + s + "(int sequence, int step, sim::UnitMemory& m) {\n";
        out += "    (void)m;\n";
        for (const auto& step : m_image.steps) {
            std::string body;
            for (std::uint32_t i = step.first; i < step.first + step.count; ++i)
                if (m_image.code[i].op == Op::Coil)
                    body += "        " + writeBit(m_image.code[i].operand, "false") + ";\n";
            if (!body.empty())
                out += "    if (sequence == " + n(step.sequence) + " && step == " + n(step.step) +
                       ") {\n" + body + "    }\n";
        }
        return out + "}\n\n";
    }

    std::string memory(const Address& a) const {
        return a.unit == m_image.station ? "m." : "bus[" + n(a.unit) + "].";
    }

    std::string readBit(const Address& a) const {
        const std::string m = memory(a);
        const std::string i = n(a.index);
        switch (a.kind) {
        case AddressKind::Input:
        case AddressKind::InputOutput:
            return m + "inputs[" + i + "]";
        case AddressKind::Output:
            return m + "outputs[" + i + "]";
        case AddressKind::AnalogInput:
            return "(" + m + "analogInputs[" + i + "] != 0)";
        case AddressKind::Memory:
            return m + "memories[" + i + "]";
        case AddressKind::GlobalMemory:
            return m + "globalMemories[" + i + "]";
        case AddressKind::SystemMemory:
            return m + "systemMemories[" + i + "]";
        case AddressKind::RegisterBit:
            return "readBit(" + m + "registers[" + i + "], " + n(a.bit) + ")";
        case AddressKind::AsiInput:
            if (a.bit < 0)
                return m + "asiSafeInputs[" + i + "]";
            return m + "asiInputs[" + n(a.index + (a.asiB ? 32 : 0)) + "][" + n(a.bit - 1) + "]";
        case AddressKind::AsiOutput:
            return m + "asiOutputs[" + n(a.index + (a.asiB ? 32 : 0)) + "][" + n(a.bit - 1) + "]";
        default:
            throw std::logic_error("not a bit: " + lang::toString(a));
        }
    }

    std::string writeBit(const Address& a, const std::string& value) const {
        const std::string i = n(a.index);
        switch (a.kind) {
        case AddressKind::Output:
        case AddressKind::InputOutput:
            return "m.outputs[" + i + "] = " + value;
        case AddressKind::RegisterBit:
            return "writeBit(m.registers[" + i + "], " + n(a.bit) + ", " + value + ")";
        default:
            return readBit(a) + " = " + value;
        }
    }

    std::string readWord(const Address& a) const {
        const std::string m = memory(a);
        const std::string i = n(a.index);
        switch (a.kind) {
        case AddressKind::Register:
        case AddressKind::DoubleRegisterLow:
            return "std::int64_t{" + m + "registers[" + i + "]}";
        case AddressKind::DoubleRegisterHigh:
            return "std::int64_t{" + m + "registers[" + n(a.index + 1) + "]}";
        case AddressKind::DoubleRegister:
            return "readDouble(&" + m + "registers[" + i + "])";
        case AddressKind::SystemRegister:
            return "std::int64_t{" + m + "systemRegisters[" + i + "]}";
        case AddressKind::AnalogInput:
            return "std::int64_t{" + m + "analogInputs[" + i + "]}";
        default:
            throw std::logic_error("not a word: " + lang::toString(a));
        }
    }

    std::string writeWord(const Address& a, const std::string& value) const {
        const std::string i = n(a.index);
        switch (a.kind) {
        case AddressKind::Register:
        case AddressKind::DoubleRegisterLow:
            return "m.registers[" + i + "] = static_cast<std::int16_t>(" + value + ")";
        case AddressKind::DoubleRegisterHigh:
            return "m.registers[" + n(a.index + 1) + "] = static_cast<std::int16_t>(" + value + ")";
        case AddressKind::DoubleRegister:
            return "writeDouble(&m.registers[" + i + "], " + value + ")";
        default:
            return "m.systemRegisters[" + i + "] = static_cast<std::int32_t>(" + value + ")";
        }
    }

    // An illuminated push button is written (and toggled) on its lamp, the output.
    static Address lamp(Address a) {
        if (a.kind == AddressKind::InputOutput)
            a.kind = AddressKind::Output;
        return a;
    }

    static bool wide(const Address& a) {
        return a.kind == AddressKind::DoubleRegister || a.kind == AddressKind::SystemRegister ||
               a.kind == AddressKind::AnalogInput;
    }

    std::string operand(const Instruction& in) const {
        return (in.flags & compiler::ConstantOperand) ? "std::int64_t{" + n(in.constant) + "}"
                                                      : readWord(in.operand);
    }

    std::string instruction(const Instruction& in) {
        const bool negated = in.flags & compiler::Negated;
        const std::string neg = negated ? "true" : "false";
        switch (in.op) {
        case Op::Rung:
            return "p = true;";
        case Op::Contact:
            return "p = p && " + std::string(negated ? "!" : "") + readBit(in.operand) + ";";
        case Op::Edge:
            return "{ const bool v = " + readBit(in.operand) +
                   ((in.flags & compiler::OperandNegated) ? " == 0" : " != 0") +
                   "; const bool e = edge(u.edges[" + n(in.slot) + "], v, " +
                   ((in.flags & compiler::Rising) ? "true" : "false") + "); p = p && (e != " + neg +
                   "); }";
        case Op::Timer:
            return "p = timer(u.timers[" + n(in.slot) + "], p, " + n(in.aux) + ", " + operand(in) +
                   ", " + neg + ", cycleMs, plant.scan, m.systemMemories[10]);";
        case Op::LoadA:
            return "a = " + operand(in) + ";";
        case Op::LoadB:
            return "b = " + operand(in) + ";";
        case Op::Compare: {
            static constexpr const char* ops[] = {"==", ">", "<", ">=", "<="};
            return "p = p && ((a " + std::string(ops[in.aux]) + " b) != " + neg + ");";
        }
        case Op::BranchOpen:
            ++m_depth;
            return "in" + n(m_depth - 1) + " = p; any" + n(m_depth - 1) + " = false;";
        case Op::BranchNext:
            return "any" + n(m_depth - 1) + " = any" + n(m_depth - 1) + " || p; p = in" +
                   n(m_depth - 1) + ";";
        case Op::BranchClose:
            --m_depth;
            return "p = any" + n(m_depth) + " || p;";
        case Op::Coil:
            return writeBit(in.operand, "p") + "; m.systemMemories[1] = p;";
        case Op::Set:
            return "if (p) { " + writeBit(in.operand, "true") + "; } m.systemMemories[1] = p;";
        case Op::Reset:
            return "if (p) { " + writeBit(in.operand, "false") + "; } m.systemMemories[1] = p;";
        case Op::Toggle:
            return "if (p) { " + writeBit(in.operand, "!" + readBit(lamp(in.operand))) +
                   "; } m.systemMemories[1] = p;";
        case Op::Jump:
            return "if (p) { jump = " + n(in.slot) + "; }";
        case Op::SequenceReset:
            return "if (p) { u.reset[" + n(in.slot) + "] = true; }";
        case Op::Arith:
            return arithmetic(in);
        case Op::System:
        case Op::Argument:
            // The benchmark's projects make no system calls.
            throw std::logic_error("system instructions are not translated");
        }
        return "";
    }

    std::string arithmetic(const Instruction& in) const {
        const std::string current = readWord(in.operand);
        std::string result;
        switch (static_cast<compiler::ArithOp>(in.aux)) {
        case compiler::ArithOp::Increment:
            result = current + " + 1";
            break;
        case compiler::ArithOp::Decrement:
            result = current + " - 1";
            break;
        case compiler::ArithOp::Add:
            result = current + " + a";
            break;
        case compiler::ArithOp::Sub:
            result = current + " - a";
            break;
        case compiler::ArithOp::Mul:
            result = current + " * a";
            break;
        case compiler::ArithOp::Div:
            result = "divide(" + current + ", a, m)";
            break;
        case compiler::ArithOp::Copy:
            result = "a";
            break;
        case compiler::ArithOp::AddAB:
            result = "a + b";
            break;
        case compiler::ArithOp::SubAB:
            result = "a - b";
            break;
        case compiler::ArithOp::MulAB:
            result = "a * b";
            break;
        case compiler::ArithOp::DivAB:
            result = "divide(a, b, m)";
            break;
        }
        return "if (p) { " +
               writeWord(in.operand, "saturate(" + result + ", " +
                                         (wide(in.operand) ? "true" : "false") + ", m)") +
               "; }";
    }

    const compiler::UnitImage& m_image;
    int m_depth = 0;
};

} // namespace

std::string generateNativeCode(const std::vector<compiler::UnitImage>& images) {
    std::string out = "// Generated by rungsmith-native: do not edit.\n"
                      "#include \"NativeRuntime.h\"\n\nnamespace rs::native {\n\nnamespace {\n\n";
    std::string calls;
    std::string present;
    for (const auto& image : images) {
        out += UnitWriter(image).write();
        calls += "    scanUnit" + n(image.station) + "(plant, timeMs, cycleMs);\n";
        present += n(image.station) + ", ";
    }
    out += "} // namespace\n\n";
    out += "void scanPlant(Plant& plant, std::int64_t timeMs, int cycleMs) {\n";
    out += "    ++plant.scan;\n";
    out += "    for (int station : {" + present + "}) {\n";
    out += "        for (int other : {" + present + "})\n";
    out += "            plant.memory[station].systemMemories[100 + other] = 1;\n    }\n";
    out += calls;
    out += "    for (int station : {" + present + "})\n";
    out += "        plant.bus[station] = plant.memory[station];\n}\n\n} // namespace rs::native\n";
    return out;
}

} // namespace rs::bench
