// SPDX-License-Identifier: GPL-3.0-or-later
#include "Counterexample.h"

#include "sim/ScenarioRunner.h"
#include "sim/Simulation.h"

#include <algorithm>
#include <memory>

namespace rs::prove {

namespace {

std::int64_t rightValue(const sim::Simulation& simulation, const Condition& condition) {
    return condition.rightIsConstant ? condition.constant : simulation.value(condition.right);
}

bool holds(const sim::Simulation& simulation, const Condition& condition) {
    switch (condition.kind) {
    case Condition::Kind::Bit:
        return simulation.value(condition.operand) != 0;
    case Condition::Kind::Not:
        return !holds(simulation, condition.children.front());
    case Condition::Kind::And:
        for (const Condition& child : condition.children)
            if (!holds(simulation, child))
                return false;
        return true;
    case Condition::Kind::Or:
        for (const Condition& child : condition.children)
            if (holds(simulation, child))
                return true;
        return false;
    case Condition::Kind::Compare: {
        const std::int64_t left = simulation.value(condition.operand);
        const std::int64_t right = rightValue(simulation, condition);
        switch (condition.op) {
        case lang::CompareOp::Equal:
            return left == right;
        case lang::CompareOp::Greater:
            return left > right;
        case lang::CompareOp::Less:
            return left < right;
        case lang::CompareOp::GreaterEqual:
            return left >= right;
        case lang::CompareOp::LessEqual:
            return left <= right;
        }
    }
    }
    return false;
}

// One operand and a value that shows why the condition is not `wanted`: the
// operand would need that value for the condition to be. `expect` of it
// fails for a counterexample.
struct Shown {
    lang::Address operand;
    std::int64_t value = 0;
};

Shown explain(const sim::Simulation& simulation, const Condition& condition, bool wanted) {
    switch (condition.kind) {
    case Condition::Kind::Bit:
        return {condition.operand, wanted ? 1 : 0};
    case Condition::Kind::Not:
        return explain(simulation, condition.children.front(), !wanted);
    case Condition::Kind::And:
    case Condition::Kind::Or:
        // The first child that is not as wanted; when all are (an And not
        // wanted, an Or wanted), any of them shows it.
        for (const Condition& child : condition.children)
            if (holds(simulation, child) != wanted)
                return explain(simulation, child, wanted);
        return explain(simulation, condition.children.front(), wanted);
    case Condition::Kind::Compare: {
        const std::int64_t right = rightValue(simulation, condition);
        lang::CompareOp op = condition.op;
        if (!wanted) // the value that would make the comparison false
            switch (op) {
            case lang::CompareOp::Equal:
                return {condition.operand, right + 1};
            case lang::CompareOp::Greater:
                op = lang::CompareOp::LessEqual;
                break;
            case lang::CompareOp::Less:
                op = lang::CompareOp::GreaterEqual;
                break;
            case lang::CompareOp::GreaterEqual:
                op = lang::CompareOp::Less;
                break;
            case lang::CompareOp::LessEqual:
                op = lang::CompareOp::Greater;
                break;
            }
        switch (op) {
        case lang::CompareOp::Greater:
            return {condition.operand, right + 1};
        case lang::CompareOp::Less:
            return {condition.operand, right - 1};
        default:
            return {condition.operand, right};
        }
    }
    }
    return {};
}

// The property's own reading, scan by scan on the simulator, as a second
// opinion on the circuit's.
class Monitor {
public:
    Monitor(const Property& property, int cycleMs)
        : m_property(property), m_window(windowScans(property, cycleMs)) {}

    // After a scan: whether it breaks the property (reaches a cover).
    bool breaks(const sim::Simulation& simulation) {
        const bool a = holds(simulation, m_property.first);
        switch (m_property.kind) {
        case Property::Kind::Always:
            return !a;
        case Property::Kind::Never:
        case Property::Kind::Cover:
            return a;
        case Property::Kind::Implies:
            return a && !holds(simulation, m_property.second);
        case Property::Kind::Next: {
            const bool broken = m_before && !holds(simulation, m_property.second);
            m_before = a;
            return broken;
        }
        case Property::Kind::Within: {
            const bool b = holds(simulation, m_property.second);
            const bool due = !b && (m_pending || a);
            const std::int64_t age = m_pending ? m_age + 1 : 0;
            m_pending = due;
            m_age = due ? std::min(age, m_window) : 0;
            return due && age >= m_window;
        }
        case Property::Kind::Assume:
            break;
        }
        return false;
    }

private:
    const Property& m_property;
    std::int64_t m_window;
    bool m_before = false;
    bool m_pending = false;
    std::int64_t m_age = 0;
};

std::string durationText(std::int64_t ms) {
    return std::to_string(ms) + "ms";
}

// How a scenario names a variable: its declared name where it has one (an
// input read through an IQ button by the button's name), else its address.
std::string operandText(const lang::Address& address, const sim::OperandNames& names) {
    std::string name = names.nameOf(address);
    if (name.empty() && address.kind == lang::AddressKind::Input) {
        lang::Address button = address;
        button.kind = lang::AddressKind::InputOutput;
        name = names.nameOf(button);
    }
    return name.empty() ? lang::toString(address) : name;
}

// The trace run on the simulator from power on, the property watched by its
// own reading: whether it breaks the property in the last scan and in no
// scan before, with every assumption kept.
struct Replay {
    std::string problem;                         // empty when it does
    std::unique_ptr<sim::Simulation> simulation; // as the last scan left it
};

Replay replay(const std::vector<compiler::UnitImage>& images, const PropertyFile& file,
              const Property& property, const std::vector<ScanInputs>& trace) {
    Replay result;
    result.simulation = std::make_unique<sim::Simulation>(images, file.cycleMs);
    sim::Simulation& simulation = *result.simulation;
    Monitor monitor(property, file.cycleMs);
    for (std::size_t scan = 0; scan < trace.size(); ++scan) {
        for (const auto& [address, value] : trace[scan])
            if (address.valid() && simulation.value(address) != value)
                simulation.set(address, value);
        simulation.scan();
        for (const Property& assumption : file.properties)
            if (assumption.kind == Property::Kind::Assume && !holds(simulation, assumption.first))
                result.problem = "the simulator breaks an assumption";
        const bool broken = monitor.breaks(simulation);
        if (broken && scan + 1 < trace.size())
            result.problem = "the simulator breaks the property before the last scan";
        if (!broken && scan + 1 == trace.size())
            result.problem = "the simulator does not break the property in the last scan";
        if (!result.problem.empty())
            return result;
    }
    return result;
}

// Fewer input changes, the same violation: each change the violation does
// without is taken back, so that the scenario shows what matters.
std::vector<ScanInputs> simplified(const std::vector<compiler::UnitImage>& images,
                                   const PropertyFile& file, const Property& property,
                                   std::vector<ScanInputs> trace) {
    constexpr int kMaxReplays = 2000;
    int replays = 0;
    const sim::Simulation powerOn(images, file.cycleMs);
    for (std::size_t scan = 0; scan < trace.size(); ++scan)
        for (std::size_t i = 0; i < trace[scan].size(); ++i) {
            const auto& [address, value] = trace[scan][i];
            if (!address.valid())
                continue;
            const std::int64_t before =
                scan == 0 ? powerOn.value(address) : trace[scan - 1][i].second;
            if (value == before || ++replays > kMaxReplays)
                continue;
            std::vector<ScanInputs> candidate = trace;
            for (std::size_t later = scan; later < trace.size(); ++later) {
                if (later > scan && candidate[later][i].second != value)
                    break; // the input changes again on its own
                candidate[later][i].second = before;
            }
            if (replay(images, file, property, candidate).problem.empty())
                trace = std::move(candidate);
        }
    return trace;
}

} // namespace

std::string replayProblem(const std::vector<compiler::UnitImage>& images, const PropertyFile& file,
                          const Verdict& verdict) {
    return replay(images, file, *verdict.property, verdict.inputs).problem;
}

CounterexampleScenario writeCounterexample(const std::vector<compiler::UnitImage>& images,
                                           const PropertyFile& file, const Verdict& verdict,
                                           const sim::OperandNames& names,
                                           const std::string& propertyFileName) {
    CounterexampleScenario out;
    const Property& property = *verdict.property;
    const bool witness = property.kind == Property::Kind::Cover;
    Replay found = replay(images, file, property, verdict.inputs);
    if (!found.problem.empty()) {
        out.problem = found.problem;
        return out;
    }
    const std::vector<ScanInputs> trace = simplified(images, file, property, verdict.inputs);
    found = replay(images, file, property, trace);
    // The scans' inputs as scenario lines: what changes, then how many scans.
    std::string body;
    int pendingScans = 0;
    const sim::Simulation powerOn(images, file.cycleMs);
    for (std::size_t scan = 0; scan < trace.size(); ++scan) {
        std::string lines;
        for (std::size_t i = 0; i < trace[scan].size(); ++i) {
            const auto& [address, value] = trace[scan][i];
            if (!address.valid())
                continue;
            const std::int64_t before =
                scan == 0 ? powerOn.value(address) : trace[scan - 1][i].second;
            if (value != before)
                lines += "set " + operandText(address, names) + " " + std::to_string(value) + "\n";
        }
        if (!lines.empty() && pendingScans > 0) {
            body += "scans " + std::to_string(pendingScans) + "\n";
            pendingScans = 0;
        }
        body += lines;
        ++pendingScans;
    }
    body += "scans " + std::to_string(pendingScans) + "\n";
    // The last line: what the property wanted of the last scan.
    const sim::Simulation& simulation = *found.simulation;
    const Condition& wantedOf = property.kind == Property::Kind::Implies ||
                                        property.kind == Property::Kind::Within ||
                                        property.kind == Property::Kind::Next
                                    ? property.second
                                    : property.first;
    Shown shown = explain(simulation, wantedOf, property.kind != Property::Kind::Never);
    const std::int64_t actual = simulation.value(shown.operand);
    if (witness) { // what the witness reached: the expect holds
        shown.value = actual;
    } else {
        // A value the operand can hold that it does not have: what the
        // property wanted, where the operand can hold that (S0.1 >= 0 can
        // never be false).
        const sim::ValueRange range = sim::valueRange(shown.operand);
        shown.value = std::clamp(shown.value, range.low, range.high);
        if (shown.value == actual)
            shown.value = actual < range.high ? actual + 1 : actual - 1;
    }
    const std::size_t scans = trace.size();
    std::string text = "; " + std::string(witness ? "witness for " : "counterexample to ") +
                       propertyFileName + ":" + std::to_string(property.line) + ": " +
                       property.text + "\n";
    text += "; found by rungsmith-cli prove: " + std::to_string(scans) +
            (scans == 1 ? " scan" : " scans") + " from power on; " +
            (witness ? "the last line holds" : "the last line fails") + "\n";
    if (file.cycleMs != 10)
        text += "cycle " + durationText(file.cycleMs) + "\n";
    text += body;
    text +=
        "expect " + operandText(shown.operand, names) + " " + std::to_string(shown.value) + "\n";
    // Run it as `rungsmith-cli test` would.
    const sim::Scenario scenario = sim::parseScenario(text, names);
    if (!scenario.diagnostics.empty()) {
        out.problem = "the scenario does not read: " + scenario.diagnostics.front().message;
        return out;
    }
    sim::Simulation run(images);
    const sim::ScenarioReport report = sim::runScenario("cex.scn", scenario, run);
    int lines = 0;
    for (char c : text)
        lines += c == '\n';
    if (witness ? report.failed != 0
                : report.failed != 1 || report.failureLines.size() != 1 ||
                      report.failureLines.front() != lines) {
        out.problem = witness ? "the witness's last line does not hold in the simulator"
                              : "the scenario's last line does not fail in the simulator";
        return out;
    }
    out.text = std::move(text);
    out.reproduced = true;
    return out;
}

} // namespace rs::prove
