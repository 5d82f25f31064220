// SPDX-License-Identifier: GPL-3.0-or-later
#include "Prover.h"

#include "ScanModel.h"
#include "Unrolling.h"

#include <algorithm>
#include <random>
#include <set>

namespace rs::prove {

namespace {

using Clock = std::chrono::steady_clock;

Lit conditionLiteral(ScanModel& model, const Condition& condition) {
    WordBuilder& w = model.words();
    AndGraph& g = model.graph();
    switch (condition.kind) {
    case Condition::Kind::Bit:
        return negate(w.isZero(model.valueAfterScan(condition.operand)));
    case Condition::Kind::Not:
        return negate(conditionLiteral(model, condition.children.front()));
    case Condition::Kind::And: {
        Lit all = kTrue;
        for (const Condition& child : condition.children)
            all = g.conj(all, conditionLiteral(model, child));
        return all;
    }
    case Condition::Kind::Or: {
        Lit any = kFalse;
        for (const Condition& child : condition.children)
            any = g.disj(any, conditionLiteral(model, child));
        return any;
    }
    case Condition::Kind::Compare: {
        const Word left = model.valueAfterScan(condition.operand);
        const Word right = condition.rightIsConstant ? w.constant(condition.constant)
                                                     : model.valueAfterScan(condition.right);
        switch (condition.op) {
        case lang::CompareOp::Equal:
            return w.equal(left, right);
        case lang::CompareOp::Greater:
            return w.less(right, left);
        case lang::CompareOp::Less:
            return w.less(left, right);
        case lang::CompareOp::GreaterEqual:
            return negate(w.less(left, right));
        case lang::CompareOp::LessEqual:
            return negate(w.less(right, left));
        }
    }
    }
    return kFalse;
}

// One property on the shared model: the literal that is true at the end of
// a scan that breaks it, and candidates for invariants about its monitor.
struct PropertyCircuit {
    const Property* property = nullptr;
    Lit bad = kFalse;
    std::vector<Lit> candidates;
};

PropertyCircuit buildCircuit(ScanModel& model, const Property& property) {
    WordBuilder& w = model.words();
    AndGraph& g = model.graph();
    PropertyCircuit circuit;
    circuit.property = &property;
    const Lit a = conditionLiteral(model, property.first);
    switch (property.kind) {
    case Property::Kind::Always:
        circuit.bad = negate(a);
        break;
    case Property::Kind::Never:
    case Property::Kind::Cover:
        circuit.bad = a;
        break;
    case Property::Kind::Implies:
        circuit.bad = g.conj(a, negate(conditionLiteral(model, property.second)));
        break;
    case Property::Kind::Next: {
        const Lit b = conditionLiteral(model, property.second);
        const Word before = model.addState(1, 0); // A at the end of the last scan
        circuit.bad = g.conj(before.bits[0], negate(b));
        model.setNext(before, w.bit(a));
        for (const Word& word : model.stateWords())
            if (word.width() == 1 && word.bits[0] != before.bits[0]) {
                circuit.candidates.push_back(g.disj(negate(before.bits[0]), word.bits[0]));
                circuit.candidates.push_back(g.disj(negate(before.bits[0]), negate(word.bits[0])));
            }
        break;
    }
    case Property::Kind::Within: {
        // The oldest obligation not yet met and its age in scans: one
        // occurrence of B meets every obligation, so one counter is enough.
        const Lit b = conditionLiteral(model, property.second);
        const std::int64_t window = windowScans(property, model.cycleMs());
        int width = 2;
        while ((std::int64_t{1} << (width - 1)) <= window)
            ++width;
        const Word pending = model.addState(1, 0);
        const Word age = model.addState(width, 0);
        const Lit pend = pending.bits[0];
        const Lit stillDue = g.conj(negate(b), g.disj(pend, a));
        const Word newAge = w.choose(pend, w.add(age, w.constant(1)), w.constant(0));
        circuit.bad = g.conj(stillDue, negate(w.less(newAge, w.constant(window))));
        model.setNext(pending, w.bit(stillDue));
        model.setNext(age, w.extended(w.choose(stillDue,
                                               w.choose(w.less(newAge, w.constant(window)), newAge,
                                                        w.constant(window)),
                                               w.constant(0)),
                                      width));
        const Lit inRange = w.less(age, w.constant(window));
        circuit.candidates.push_back(g.disj(negate(pend), inRange));
        circuit.candidates.push_back(g.disj(pend, w.isZero(age)));
        for (const Word& word : model.stateWords())
            if (word.width() == 1 && word.bits[0] != pend) {
                circuit.candidates.push_back(g.disj(negate(pend), word.bits[0]));
                circuit.candidates.push_back(g.disj(negate(pend), negate(word.bits[0])));
            }
        // A timer counting since the obligation began: its count relates to the age.
        for (const auto& [ticks, cap] : model.timerCounters()) {
            const Word capped = w.choose(w.less(age, w.constant(cap)), age, w.constant(cap));
            circuit.candidates.push_back(g.disj(negate(pend), negate(w.less(ticks, capped))));
            circuit.candidates.push_back(
                g.disj(negate(pend), negate(w.less(ticks, w.add(capped, w.constant(1))))));
            circuit.candidates.push_back(g.disj(negate(pend), negate(w.less(age, ticks))));
        }
        break;
    }
    case Property::Kind::Assume:
        break;
    }
    return circuit;
}

// The state bits the literals depend on, through any number of scans.
std::vector<bool> coneOfInfluence(const ScanModel& model, const std::vector<Lit>& roots) {
    const AndGraph& g = model.graph();
    std::vector<int> stateOf(g.nodes(), -1);
    for (std::size_t i = 0; i < model.state().size(); ++i)
        stateOf[nodeOf(model.state()[i].current)] = static_cast<int>(i);
    std::vector<bool> seen(g.nodes(), false);
    std::vector<bool> cone(model.state().size(), false);
    std::vector<std::uint32_t> stack;
    for (Lit root : roots)
        stack.push_back(nodeOf(root));
    while (!stack.empty()) {
        const std::uint32_t node = stack.back();
        stack.pop_back();
        if (node == 0 || seen[node])
            continue;
        seen[node] = true;
        if (g.isVariable(node)) {
            if (const int state = stateOf[node]; state >= 0) {
                cone[static_cast<std::size_t>(state)] = true;
                stack.push_back(nodeOf(model.state()[static_cast<std::size_t>(state)].next));
            }
            continue;
        }
        stack.push_back(nodeOf(g.left(node)));
        stack.push_back(nodeOf(g.right(node)));
    }
    return cone;
}

// Whether every state bit a literal reads is in the cone (inputs it must not read).
bool withinCone(const ScanModel& model, Lit literal, const std::vector<bool>& cone,
                const std::vector<int>& stateOf) {
    const AndGraph& g = model.graph();
    std::vector<std::uint32_t> stack{nodeOf(literal)};
    std::set<std::uint32_t> seen;
    while (!stack.empty()) {
        const std::uint32_t node = stack.back();
        stack.pop_back();
        if (node == 0 || !seen.insert(node).second)
            continue;
        if (g.isVariable(node)) {
            const int state = stateOf[node];
            if (state < 0 || !cone[static_cast<std::size_t>(state)])
                return false;
            continue;
        }
        stack.push_back(nodeOf(g.left(node)));
        stack.push_back(nodeOf(g.right(node)));
    }
    return true;
}

// Drops the candidates that some simulated run breaks: random inputs that
// mostly hold their value, 64 runs at once, from power on; a run that breaks
// an assumption stops counting.
std::vector<Lit> filterBySimulation(const ScanModel& model, Lit assumption,
                                    std::vector<Lit> candidates, int scans) {
    const AndGraph& g = model.graph();
    std::vector<bool> isState(g.nodes(), false);
    for (const StateBit& bit : model.state())
        isState[nodeOf(bit.current)] = true;
    std::vector<std::uint32_t> inputNodes;
    for (std::uint32_t node = 1; node < g.nodes(); ++node)
        if (g.isVariable(node) && !isState[node])
            inputNodes.push_back(node);
    std::mt19937_64 random(20261203);
    std::vector<std::uint64_t> values(g.nodes(), 0);
    for (int run = 0; run < 4 && !candidates.empty(); ++run) {
        std::vector<std::uint64_t> state;
        for (const StateBit& bit : model.state())
            state.push_back(bit.initial ? ~std::uint64_t{0} : 0);
        std::vector<std::uint64_t> inputs(inputNodes.size(), 0);
        std::uint64_t alive = ~std::uint64_t{0};
        for (int scan = 0; scan < scans && alive; ++scan) {
            for (std::size_t i = 0; i < inputs.size(); ++i) {
                // Each run changes inputs at its own pace: every scan to rarely.
                std::uint64_t flip = random();
                for (int k = 0; k < run; ++k)
                    flip &= random();
                inputs[i] ^= flip;
                values[inputNodes[i]] = inputs[i];
            }
            for (std::size_t i = 0; i < state.size(); ++i)
                values[nodeOf(model.state()[i].current)] = state[i];
            g.evaluate(values);
            std::erase_if(candidates, [&](Lit c) { return ~AndGraph::value(values, c) & alive; });
            alive &= AndGraph::value(values, assumption);
            for (std::size_t i = 0; i < state.size(); ++i)
                state[i] = AndGraph::value(values, model.state()[i].next);
        }
    }
    return candidates;
}

class Deadline : public CaDiCaL::Terminator {
public:
    Deadline(Clock::time_point end, const std::function<bool()>& cancelled)
        : m_end(end), m_cancelled(cancelled) {}
    bool terminate() override { return Clock::now() > m_end || (m_cancelled && m_cancelled()); }
    bool passed() { return terminate(); }

private:
    Clock::time_point m_end;
    const std::function<bool()>& m_cancelled;
};

Verdict runEngines(ScanModel& model, const PropertyCircuit& circuit, Lit assumption,
                   std::vector<Lit> candidates, const ProofOptions& options) {
    Verdict verdict;
    verdict.property = circuit.property;
    Deadline deadline(Clock::now() + options.timeLimit, options.cancelled);
    Unrolling base(model, false);
    Unrolling step(model, true);
    base.setTerminator(&deadline);
    step.setTerminator(&deadline);
    std::vector<int> activation;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        activation.push_back(step.newVariable());
    std::vector<bool> active(candidates.size(), true);
    const bool exact = model.unsupported().empty();
    auto stopped = [&](int depth) {
        verdict.status = Verdict::Status::Unknown;
        verdict.depth = depth;
        verdict.reason = options.cancelled && options.cancelled() ? "cancelled" : "time limit";
        return verdict;
    };
    for (int k = 0; k < options.maxDepth; ++k) {
        base.addClause({base.literal(assumption, k)});
        const int badNow = base.literal(circuit.bad, k);
        const int found = base.solve({badNow});
        verdict.clauses = base.clauses();
        verdict.variables = base.variables();
        if (found == 0)
            return stopped(k);
        if (found == 10) {
            verdict.status = Verdict::Status::Failed;
            verdict.depth = k + 1;
            for (int f = 0; f <= k; ++f) {
                ScanInputs scan;
                for (const ScanInput& input : model.inputs())
                    scan.emplace_back(input.address, base.value(input.word, f));
                verdict.inputs.push_back(std::move(scan));
            }
            return verdict;
        }
        base.addClause({-badNow});
        if (!exact)
            continue;
        // The induction step at depth k, with the candidates that still stand.
        step.addClause({step.literal(assumption, k)});
        while (true) {
            const int query = step.newVariable();
            std::vector<int> clause{-query, step.literal(circuit.bad, k)};
            std::vector<int> assumptions{query};
            // From depth 1 on the candidates are assumed in the frames before
            // and must follow in this one; in frame 0 nothing comes before.
            for (std::size_t i = 0; i < candidates.size(); ++i)
                if (active[i] && k > 0) {
                    clause.push_back(-step.literal(candidates[i], k));
                    assumptions.push_back(activation[i]);
                }
            step.addClause(clause);
            const int result = step.solve(assumptions);
            bool dropped = false;
            if (result == 10 && k > 0)
                for (std::size_t i = 0; i < candidates.size(); ++i)
                    if (active[i] && !step.value(candidates[i], k)) {
                        active[i] = false;
                        dropped = true;
                    }
            step.addClause({-query}); // after reading the model: a clause ends it
            if (result == 0)
                return stopped(k + 1);
            if (result == 10) {
                if (!dropped)
                    break; // the property itself needs a longer induction
                continue;
            }
            // Inductive with the candidates: they must hold from power on too.
            const int baseQuery = base.newVariable();
            std::vector<int> broken{-baseQuery};
            for (std::size_t i = 0; i < candidates.size(); ++i)
                if (active[i])
                    for (int f = 0; f <= k; ++f)
                        broken.push_back(-base.literal(candidates[i], f));
            base.addClause(broken);
            const int holds = base.solve({baseQuery});
            if (holds == 10)
                for (std::size_t i = 0; i < candidates.size(); ++i)
                    if (active[i])
                        for (int f = 0; f <= k; ++f)
                            if (!base.value(candidates[i], f))
                                active[i] = false;
            base.addClause({-baseQuery});
            if (holds == 0)
                return stopped(k + 1);
            if (holds == 20) {
                verdict.status = Verdict::Status::Proved;
                verdict.depth = k + 1;
                verdict.invariants =
                    static_cast<int>(std::count(active.begin(), active.end(), true));
                verdict.clauses = base.clauses() + step.clauses();
                verdict.variables = base.variables() + step.variables();
                return verdict;
            }
        }
        step.addClause({-step.literal(circuit.bad, k)});
        for (std::size_t i = 0; i < candidates.size(); ++i)
            if (active[i])
                step.addClause({-activation[i], step.literal(candidates[i], k)});
        if (deadline.passed())
            return stopped(k + 1);
    }
    verdict.status = Verdict::Status::Unknown;
    verdict.depth = options.maxDepth;
    verdict.reason =
        exact ? "no counterexample within " + std::to_string(options.maxDepth) + " scans"
              : "the model leaves out " + model.unsupported().front() +
                    "; no counterexample within " + std::to_string(options.maxDepth) + " scans";
    return verdict;
}

} // namespace

std::vector<Verdict> proveProperties(const std::vector<compiler::UnitImage>& images,
                                     const PropertyFile& file, const ProofOptions& options) {
    ScanModel model(images, file.cycleMs);
    Lit assumption = kTrue;
    for (const Property& property : file.properties)
        if (property.kind == Property::Kind::Assume)
            assumption = model.graph().conj(assumption, conditionLiteral(model, property.first));
    std::vector<PropertyCircuit> circuits;
    for (const Property& property : file.properties)
        if (property.kind != Property::Kind::Assume)
            circuits.push_back(buildCircuit(model, property));
    // Candidates per property, made before the solvers copy the graph's size.
    std::vector<std::vector<Lit>> candidates;
    std::vector<int> stateOf(model.graph().nodes(), -1);
    for (std::size_t i = 0; i < model.state().size(); ++i)
        stateOf[nodeOf(model.state()[i].current)] = static_cast<int>(i);
    for (const PropertyCircuit& circuit : circuits) {
        const std::vector<bool> cone = coneOfInfluence(model, {circuit.bad, assumption});
        std::vector<Lit> list;
        for (Lit invariant : model.structuralInvariants())
            if (withinCone(model, invariant, cone, stateOf))
                list.push_back(invariant);
        for (Lit candidate : circuit.candidates)
            if (withinCone(model, candidate, cone, stateOf))
                list.push_back(candidate);
        candidates.push_back(std::move(list));
    }
    // Pairs of bits in the cone that imply one another, for small cones.
    for (std::size_t p = 0; p < circuits.size(); ++p) {
        const std::vector<bool> cone = coneOfInfluence(model, {circuits[p].bad, assumption});
        std::vector<Lit> bits;
        for (const Word& word : model.stateWords())
            if (word.width() == 1 && cone[static_cast<std::size_t>(stateOf[nodeOf(word.bits[0])])])
                bits.push_back(word.bits[0]);
        if (bits.size() > 48)
            continue;
        for (std::size_t i = 0; i < bits.size(); ++i)
            for (std::size_t j = 0; j < bits.size(); ++j)
                if (i != j)
                    for (Lit x : {bits[i], negate(bits[i])})
                        for (Lit y : {bits[j], negate(bits[j])})
                            if (i < j || isNegated(x) == isNegated(y))
                                candidates[p].push_back(model.graph().disj(negate(x), y));
    }
    std::vector<Verdict> verdicts;
    for (std::size_t p = 0; p < circuits.size(); ++p) {
        std::vector<Lit> kept = filterBySimulation(model, assumption, candidates[p], 400);
        Verdict verdict = runEngines(model, circuits[p], assumption, std::move(kept), options);
        if (circuits[p].property->kind == Property::Kind::Cover) {
            if (verdict.status == Verdict::Status::Failed)
                verdict.status = Verdict::Status::Covered;
            else if (verdict.status == Verdict::Status::Proved)
                verdict.status = Verdict::Status::Unreachable;
        }
        verdicts.push_back(std::move(verdict));
    }
    return verdicts;
}

} // namespace rs::prove
