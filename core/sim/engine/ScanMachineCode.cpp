// SPDX-License-Identifier: GPL-3.0-or-later
#include "ScanMachineCode.h"

#include "InstructionMeaning.h"

#include <bit>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <map>

#if defined(RUNGSMITH_JIT)
#include <asmjit/x86.h>
#endif

namespace rs::sim::engine {

#if defined(RUNGSMITH_JIT) && defined(__x86_64__) && !defined(_WIN32)

struct ScanMachineCode::Memory {
    asmjit::JitRuntime runtime;
    void* code = nullptr;
};

namespace {

namespace x86 = asmjit::x86;
using Instruction = ScanMachineCode::Instruction;
using Kind = ScanMachineCode::Kind;

// Remembers that an instruction could not be encoded, so that nothing half
// made is ever run.
class ErrorFlag : public asmjit::ErrorHandler {
public:
    void handleError(asmjit::Error, const char*, asmjit::BaseEmitter*) override { failed = true; }
    bool failed = false;
};

bool disabled() {
    const char* value = std::getenv("RUNGSMITH_NO_JIT");
    return value && std::strcmp(value, "1") == 0;
}

asmjit::Imm address(const void* pointer) {
    return asmjit::Imm(reinterpret_cast<std::uint64_t>(pointer));
}

// Emits one run. The System V calling convention: the context stays in rbx,
// the power in r12d and the address that places are addressed from in r13,
// all kept by the handlers; rax, rcx, rdx, rsi, rdi, r8 and r11 are scratch.
// A handler is called through a jump of its own next to the code, as
// executable memory is usually too far from the program for a direct call.
class RunEmitter {
public:
    RunEmitter(x86::Assembler& a, std::map<ScanMachineCode::Handler, asmjit::Label>& handlers,
               const void* near)
        : a(a), m_handlers(handlers), m_near(reinterpret_cast<std::intptr_t>(near)) {}

    void emit(const Instruction& in) {
        switch (in.kind) {
        case Kind::Rung:
            m_rung = true; // the next condition sets the power instead of and-ing it
            return;
        case Kind::And:
            testBit(in, x86::dl, in.negated);
            a.movzx(x86::edx, x86::dl);
            applyCondition();
            return;
        case Kind::Edge:
            edge(in);
            return;
        case Kind::Compare:
            compare(in);
            return;
        default:
            break;
        }
        settleRung();
        switch (in.kind) {
        case Kind::Call:
            call(in);
            return;
        case Kind::Store:
        case Kind::Set:
        case Kind::Reset:
            output(in);
            return;
        case Kind::Load:
            a.movsx(x86::rcx, at(in.place, 2));
            a.mov(x86::qword_ptr(x86::rbx, in.slot), x86::rcx);
            return;
        case Kind::LoadConst:
            a.mov(x86::qword_ptr(x86::rbx, in.slot), in.constant);
            return;
        case Kind::Open:
            a.mov(x86::dword_ptr(x86::rbx, in.slot), x86::r12d);
            a.mov(x86::dword_ptr(x86::rbx, in.slot + 4), 0);
            return;
        case Kind::Next:
            a.or_(x86::dword_ptr(x86::rbx, in.slot + 4), x86::r12d);
            a.mov(x86::r12d, x86::dword_ptr(x86::rbx, in.slot));
            return;
        case Kind::Close:
            a.or_(x86::r12d, x86::dword_ptr(x86::rbx, in.slot + 4));
            return;
        case Kind::Arithmetic:
            arithmetic(in);
            return;
        default:
            return;
        }
    }

private:
    // A place by its distance from r13, short to encode, or else by its address in `scratch`.
    x86::Mem at(const void* place, std::uint32_t size, const x86::Gp& scratch = x86::r11,
                std::int32_t offset = 0) {
        const std::intptr_t distance = reinterpret_cast<std::intptr_t>(place) - m_near + offset;
        if (distance >= INT32_MIN && distance <= INT32_MAX)
            return x86::ptr(x86::r13, static_cast<std::int32_t>(distance), size);
        a.mov(scratch, address(place));
        return x86::ptr(scratch, offset, size);
    }

    // After a rung the power is 1: emitted only when something reads it.
    void settleRung() {
        if (m_rung)
            a.mov(x86::r12d, 1);
        m_rung = false;
    }

    // The power and the condition in edx.
    void applyCondition() {
        if (m_rung)
            a.mov(x86::r12d, x86::edx);
        else
            a.and_(x86::r12d, x86::edx);
        m_rung = false;
    }

    // to = ((*byte & mask) != 0) ^ negated, as 0 or 1.
    void testBit(const Instruction& in, const x86::Gpb& to, bool negated) {
        a.test(at(in.place, 1), in.mask);
        if (negated)
            a.setz(to);
        else
            a.setnz(to);
    }

    // The value of the bit as it is and as it was; rising: now and not
    // before, falling: before and not now; only once the occurrence has seen
    // its operand.
    void edge(const Instruction& in) {
        testBit(in, x86::cl, in.operandNegated);
        const x86::Mem seen = at(in.state, 1, x86::rax);
        const x86::Mem last = at(in.state, 1, x86::rax, 1);
        a.movzx(x86::esi, seen);
        a.movzx(x86::edx, last);
        a.mov(seen, 1);
        a.mov(last, x86::cl);
        a.movzx(x86::ecx, x86::cl);
        if (in.rising)
            a.xor_(x86::edx, 1);
        else
            a.xor_(x86::ecx, 1);
        a.and_(x86::edx, x86::ecx);
        a.and_(x86::edx, x86::esi);
        if (in.negated)
            a.xor_(x86::edx, 1);
        applyCondition();
    }

    void compare(const Instruction& in) {
        using Condition = ScanMachineCode::Condition;
        a.mov(x86::rax, x86::qword_ptr(x86::rbx, in.slot));
        a.cmp(x86::rax, x86::qword_ptr(x86::rbx, in.slot2));
        const bool n = in.negated;
        switch (in.condition) {
        case Condition::Equal:
            n ? a.setne(x86::dl) : a.sete(x86::dl);
            break;
        case Condition::Greater:
            n ? a.setle(x86::dl) : a.setg(x86::dl);
            break;
        case Condition::Less:
            n ? a.setge(x86::dl) : a.setl(x86::dl);
            break;
        case Condition::GreaterEqual:
            n ? a.setl(x86::dl) : a.setge(x86::dl);
            break;
        case Condition::LessEqual:
            n ? a.setg(x86::dl) : a.setle(x86::dl);
            break;
        }
        a.movzx(x86::edx, x86::dl);
        applyCondition();
    }

    void call(const Instruction& in) {
        auto [place, added] = m_handlers.try_emplace(in.handler);
        if (added)
            place->second = a.newLabel();
        a.mov(x86::rdi, x86::rbx);
        a.mov(x86::rsi, address(in.place));
        a.mov(x86::edx, x86::r12d);
        a.call(place->second);
        a.mov(x86::r12d, x86::eax);
    }

    // A whole byte holds the power; a bit of a byte is the mask's only bit.
    void output(const Instruction& in) {
        const bool whole = in.mask == 0xFF;
        const int shift = whole ? 0 : std::countr_zero(in.mask);
        const x86::Mem target = at(in.place, 1);
        a.mov(x86::edx, x86::r12d);
        if (shift)
            a.shl(x86::edx, shift);
        switch (in.kind) {
        case Kind::Store:
            if (!whole) {
                a.movzx(x86::ecx, target);
                a.and_(x86::ecx, ~in.mask & 0xFF);
                a.or_(x86::edx, x86::ecx);
            }
            a.mov(target, x86::dl);
            return;
        case Kind::Set:
            a.or_(target, x86::dl);
            return;
        default: // Reset
            if (whole) {
                a.xor_(x86::edx, 1);
                a.neg(x86::edx);
            } else {
                a.not_(x86::edx);
            }
            a.and_(target, x86::dl);
            return;
        }
    }

    // Without a jump: the result is computed always and kept with the power.
    void arithmetic(const Instruction& in) {
        using Operation = ScanMachineCode::Operation;
        const x86::Mem target = at(in.place, 2, x86::rdi);
        a.movsx(x86::rcx, target);
        if (in.slot == ScanMachineCode::kCurrent)
            a.mov(x86::rax, x86::rcx);
        else
            a.mov(x86::rax, x86::qword_ptr(x86::rbx, in.slot));
        if (in.slot2 == ScanMachineCode::kConstant)
            a.mov(x86::rdx, in.constant);
        else
            a.mov(x86::rdx, x86::qword_ptr(x86::rbx, in.slot2));
        switch (in.operation) {
        case Operation::Add:
            a.add(x86::rax, x86::rdx);
            break;
        case Operation::Subtract:
            a.sub(x86::rax, x86::rdx);
            break;
        case Operation::Multiply:
            a.imul(x86::rax, x86::rdx);
            break;
        }
        constexpr Bounds bounds = kRegisterBounds;
        a.lea(x86::rdx, x86::ptr(x86::rax, static_cast<std::int32_t>(-bounds.low)));
        a.cmp(x86::rdx, bounds.high - bounds.low);
        a.seta(x86::dl); // outside(rax, bounds)
        a.movzx(x86::edx, x86::dl);
        a.mov(x86::esi, bounds.high);
        a.cmp(x86::rax, x86::rsi);
        a.cmovg(x86::rax, x86::rsi);
        a.mov(x86::rsi, bounds.low);
        a.cmp(x86::rax, x86::rsi);
        a.cmovl(x86::rax, x86::rsi);
        const x86::Mem overflow = at(in.state, 1, x86::r11);
        a.movzx(x86::r8d, overflow);
        a.test(x86::r12d, x86::r12d);
        a.cmovz(x86::rax, x86::rcx);
        a.cmovnz(x86::r8d, x86::edx);
        a.mov(target, x86::ax);
        a.mov(overflow, x86::r8b);
    }

    x86::Assembler& a;
    std::map<ScanMachineCode::Handler, asmjit::Label>& m_handlers;
    std::intptr_t m_near;
    bool m_rung = false;
};

} // namespace

ScanMachineCode::ScanMachineCode() : m_memory(std::make_unique<Memory>()) {}

ScanMachineCode::~ScanMachineCode() {
    if (m_memory->code)
        m_memory->runtime.release(m_memory->code);
}

std::unique_ptr<ScanMachineCode> ScanMachineCode::compile(const std::vector<Run>& runs,
                                                          const void* near) {
    if (disabled() || runs.empty())
        return nullptr;
    std::unique_ptr<ScanMachineCode> code(new ScanMachineCode);
    asmjit::CodeHolder holder;
    ErrorFlag errors;
    holder.init(code->m_memory->runtime.environment());
    holder.setErrorHandler(&errors);
    x86::Assembler a(&holder);
    std::map<Handler, asmjit::Label> handlers;
    std::vector<asmjit::Label> starts;
    starts.reserve(runs.size());
    for (const Run& run : runs) {
        starts.push_back(a.newLabel());
        a.bind(starts.back());
        a.push(x86::rbx); // three pushes: calls find the stack aligned to 16 bytes
        a.push(x86::r12);
        a.push(x86::r13);
        a.mov(x86::rbx, x86::rdi);
        a.mov(x86::r13, address(near));
        a.mov(x86::r12d, 1);
        RunEmitter emitter(a, handlers, near);
        for (const Instruction& in : run)
            emitter.emit(in);
        a.pop(x86::r13);
        a.pop(x86::r12);
        a.pop(x86::rbx);
        a.ret();
    }
    for (const auto& [handler, label] : handlers) {
        a.bind(label);
        a.jmp(address(reinterpret_cast<const void*>(handler)));
    }
    void*& base = code->m_memory->code;
    if (errors.failed || code->m_memory->runtime.add(&base, &holder) != asmjit::kErrorOk)
        return nullptr;
    for (const asmjit::Label& start : starts)
        code->m_entries.push_back(reinterpret_cast<Entry>(static_cast<std::uint8_t*>(base) +
                                                          holder.labelOffsetFromBase(start)));
    return code;
}

#else

struct ScanMachineCode::Memory {};

ScanMachineCode::ScanMachineCode() = default;
ScanMachineCode::~ScanMachineCode() = default;

std::unique_ptr<ScanMachineCode> ScanMachineCode::compile(const std::vector<Run>&, const void*) {
    return nullptr;
}

#endif

} // namespace rs::sim::engine
