// SPDX-License-Identifier: GPL-3.0-or-later
#include "Counterexample.h"

#include "sim/ScenarioRunner.h"
#include "sim/Simulation.h"

#include <map>

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

} // namespace

CounterexampleScenario writeCounterexample(const std::vector<compiler::UnitImage>& images,
                                           const PropertyFile& file, const Verdict& verdict,
                                           const sim::OperandNames& names,
                                           const std::string& propertyFileName) {
    CounterexampleScenario out;
    const Property& property = *verdict.property;
    const bool witness = property.kind == Property::Kind::Cover;
    // The scans' inputs as scenario lines, and the simulator run along.
    sim::Simulation simulation(images, file.cycleMs);
    Monitor monitor(property, file.cycleMs);
    std::vector<const Property*> assumptions;
    for (const Property& p : file.properties)
        if (p.kind == Property::Kind::Assume)
            assumptions.push_back(&p);
    std::string body;
    std::map<lang::Address, std::int64_t> set;
    int pendingScans = 0;
    auto flushScans = [&] {
        if (pendingScans > 0)
            body += "scans " + std::to_string(pendingScans) + "\n";
        pendingScans = 0;
    };
    bool brokeEarly = false;
    bool assumed = true;
    for (std::size_t scan = 0; scan < verdict.inputs.size(); ++scan) {
        std::string lines;
        for (const auto& [address, value] : verdict.inputs[scan]) {
            const std::int64_t before =
                set.count(address) ? set[address] : simulation.value(address);
            if (value != before) {
                lines += "set " + lang::toString(address) + " " + std::to_string(value) + "\n";
                simulation.set(address, value);
            }
            set[address] = value;
        }
        if (!lines.empty()) {
            flushScans();
            body += lines;
        }
        ++pendingScans;
        simulation.scan();
        for (const Property* assumption : assumptions)
            assumed = assumed && holds(simulation, assumption->first);
        const bool broken = monitor.breaks(simulation);
        if (broken && scan + 1 < verdict.inputs.size())
            brokeEarly = true;
        if (scan + 1 == verdict.inputs.size() && !broken) {
            out.problem = "the simulator does not break the property in the last scan";
            return out;
        }
    }
    flushScans();
    if (brokeEarly) {
        out.problem = "the simulator breaks the property before the last scan";
        return out;
    }
    if (!assumed) {
        out.problem = "the simulator breaks an assumption";
        return out;
    }
    // The last line: what the property wanted of the last scan.
    const Condition& wantedOf = property.kind == Property::Kind::Implies ||
                                        property.kind == Property::Kind::Within ||
                                        property.kind == Property::Kind::Next
                                    ? property.second
                                    : property.first;
    Shown shown = explain(simulation, wantedOf, property.kind != Property::Kind::Never);
    if (witness) // what the witness reached: the expect holds
        shown.value = simulation.value(shown.operand);
    std::string text = "; " + std::string(witness ? "witness for " : "counterexample to ") +
                       propertyFileName + ":" + std::to_string(property.line) + ": " +
                       property.text + "\n";
    text += "; found by rungsmith-cli prove: " + std::to_string(verdict.inputs.size()) +
            " scans from power on; " + (witness ? "the last line holds" : "the last line fails") +
            "\n";
    if (file.cycleMs != 10)
        text += "cycle " + durationText(file.cycleMs) + "\n";
    text += body;
    text += "expect " + lang::toString(shown.operand) + " " + std::to_string(shown.value) + "\n";
    // Run it as `rungsmith-cli test` would.
    const sim::Scenario scenario = sim::parseScenario(text, names);
    if (!scenario.diagnostics.empty()) {
        out.problem = "the scenario does not read: " + scenario.diagnostics.front().message;
        return out;
    }
    sim::Simulation replay(images);
    const sim::ScenarioReport report = sim::runScenario("cex.scn", scenario, replay);
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
