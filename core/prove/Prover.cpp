// SPDX-License-Identifier: GPL-3.0-or-later
#include "Prover.h"

#include "Counterexample.h"
#include "ScanModel.h"
#include "Unrolling.h"

#include <algorithm>
#include <random>

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
    std::vector<bool> cone(model.state().size(), false);
    for (std::uint32_t node : model.cone(roots))
        if (const int state = model.stateOf(node); state >= 0)
            cone[static_cast<std::size_t>(state)] = true;
    return cone;
}

// Whether every state bit a literal reads is in the cone (inputs it must
// not read): a walk that marks what it saw with a number of its own.
class ConeCheck {
public:
    explicit ConeCheck(const ScanModel& model) : m_model(model), m_seen(model.graph().nodes(), 0) {}

    bool within(Lit literal, const std::vector<bool>& cone) {
        const AndGraph& g = m_model.graph();
        ++m_walk;
        m_stack.assign(1, nodeOf(literal));
        while (!m_stack.empty()) {
            const std::uint32_t node = m_stack.back();
            m_stack.pop_back();
            if (node == 0 || m_seen[node] == m_walk)
                continue;
            m_seen[node] = m_walk;
            if (g.isVariable(node)) {
                const int state = m_model.stateOf(node);
                if (state < 0 || !cone[static_cast<std::size_t>(state)])
                    return false;
                continue;
            }
            m_stack.push_back(nodeOf(g.left(node)));
            m_stack.push_back(nodeOf(g.right(node)));
        }
        return true;
    }

private:
    const ScanModel& m_model;
    std::vector<std::uint32_t> m_seen;
    std::vector<std::uint32_t> m_stack;
    std::uint32_t m_walk = 0;
};

// The candidates that no simulated run breaks: random inputs that mostly
// hold their value, 64 runs at once, from power on; a run that breaks an
// assumption stops counting. Only the gates the candidates and the state in
// `cone` need are computed.
std::vector<bool> survivesSimulation(const ScanModel& model, Lit assumption,
                                     const std::vector<Lit>& candidates,
                                     const std::vector<bool>& cone, int scans) {
    const AndGraph& g = model.graph();
    std::vector<bool> isState(g.nodes(), false);
    std::vector<Lit> roots = candidates;
    roots.push_back(assumption);
    std::vector<std::size_t> carried; // state bits in the cone
    for (std::size_t i = 0; i < model.state().size(); ++i) {
        isState[nodeOf(model.state()[i].current)] = true;
        if (cone[i]) {
            carried.push_back(i);
            roots.push_back(model.state()[i].next);
        }
    }
    std::vector<std::uint32_t> gates;
    for (std::uint32_t node : model.cone(roots))
        if (node != 0 && !g.isVariable(node))
            gates.push_back(node);
    std::sort(gates.begin(), gates.end()); // fanins first
    std::vector<std::uint32_t> inputNodes;
    for (std::uint32_t node = 1; node < g.nodes(); ++node)
        if (g.isVariable(node) && !isState[node])
            inputNodes.push_back(node);
    std::vector<bool> survives(candidates.size(), true);
    std::mt19937_64 random(20261203);
    std::vector<std::uint64_t> values(g.nodes(), 0);
    for (int run = 0; run < 4; ++run) {
        std::vector<std::uint64_t> state;
        for (std::size_t i : carried)
            state.push_back(model.state()[i].initial ? ~std::uint64_t{0} : 0);
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
            for (std::size_t j = 0; j < carried.size(); ++j)
                values[nodeOf(model.state()[carried[j]].current)] = state[j];
            g.evaluate(values, gates);
            for (std::size_t c = 0; c < candidates.size(); ++c)
                if (survives[c] && (~AndGraph::value(values, candidates[c]) & alive))
                    survives[c] = false;
            alive &= AndGraph::value(values, assumption);
            for (std::size_t j = 0; j < carried.size(); ++j)
                state[j] = AndGraph::value(values, model.state()[carried[j]].next);
        }
    }
    return survives;
}

// At most three, then how many more.
std::string listed(const std::vector<std::string>& items) {
    std::string text;
    for (std::size_t i = 0; i < items.size() && i < 3; ++i)
        text += (i ? "; " : "") + items[i];
    if (items.size() > 3)
        text += "; and " + std::to_string(items.size() - 3) + " more";
    return text;
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
    std::vector<Lit> roots = candidates;
    roots.push_back(circuit.bad);
    roots.push_back(assumption);
    Unrolling base(model, false, roots);
    Unrolling step(model, true, roots);
    base.setTerminator(&deadline);
    step.setTerminator(&deadline);
    std::vector<int> activation;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        activation.push_back(step.newVariable());
    std::vector<bool> active(candidates.size(), true);
    auto stopped = [&](int depth) {
        verdict.status = Verdict::Status::Unknown;
        verdict.depth = depth;
        const bool cancelled = options.cancelled && options.cancelled();
        verdict.why = cancelled ? Verdict::Why::Cancelled : Verdict::Why::TimeLimit;
        verdict.reason = cancelled ? "cancelled" : "time limit";
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
    verdict.why = Verdict::Why::DepthReached;
    verdict.reason = "no counterexample within " + std::to_string(options.maxDepth) + " scans";
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
    // Candidates per property, all made before the solvers copy the graph's
    // size: what the compiler knows, the monitor's relations, and for small
    // cones pairs of bits that imply one another.
    ConeCheck check(model);
    std::vector<bool> anyCone(model.state().size(), false);
    std::vector<std::vector<Lit>> candidates;
    for (const PropertyCircuit& circuit : circuits) {
        const std::vector<bool> cone = coneOfInfluence(model, {circuit.bad, assumption});
        for (std::size_t i = 0; i < cone.size(); ++i)
            if (cone[i])
                anyCone[i] = true;
        std::vector<Lit> list;
        for (Lit invariant : model.structuralInvariants())
            if (check.within(invariant, cone))
                list.push_back(invariant);
        for (Lit candidate : circuit.candidates)
            if (check.within(candidate, cone))
                list.push_back(candidate);
        std::vector<Lit> bits;
        for (const Word& word : model.stateWords())
            if (word.width() == 1 &&
                cone[static_cast<std::size_t>(model.stateOf(nodeOf(word.bits[0])))])
                bits.push_back(word.bits[0]);
        if (bits.size() <= 48)
            for (std::size_t i = 0; i < bits.size(); ++i)
                for (std::size_t j = i + 1; j < bits.size(); ++j)
                    for (Lit x : {bits[i], negate(bits[i])})
                        for (Lit y : {bits[j], negate(bits[j])})
                            list.push_back(model.graph().disj(negate(x), y));
        candidates.push_back(std::move(list));
    }
    // One simulation for every property's candidates.
    std::vector<Lit> all;
    for (const auto& list : candidates)
        all.insert(all.end(), list.begin(), list.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    const std::vector<bool> survives = survivesSimulation(model, assumption, all, anyCone, 400);
    std::vector<Verdict> verdicts;
    for (std::size_t p = 0; p < circuits.size(); ++p) {
        std::vector<Lit> kept;
        for (Lit candidate : candidates[p])
            if (survives[static_cast<std::size_t>(
                    std::lower_bound(all.begin(), all.end(), candidate) - all.begin())])
                kept.push_back(candidate);
        Verdict verdict = runEngines(model, circuits[p], assumption, std::move(kept), options);
        // What the solver found must be what the simulator does.
        if (verdict.status == Verdict::Status::Failed) {
            if (const std::string problem = replayProblem(images, file, verdict);
                !problem.empty()) {
                verdict.status = Verdict::Status::Unknown;
                verdict.why = Verdict::Why::NotRepeated;
                verdict.reason =
                    model.abstractions().empty()
                        ? "internal error: the counterexample of " + std::to_string(verdict.depth) +
                              " scans does not replay (" + problem + "); please report it"
                        : "the counterexample of " + std::to_string(verdict.depth) +
                              " scans needs values the prover leaves free, and the simulator " +
                              "does not repeat it (" + listed(model.abstractions()) + ")";
                verdict.inputs.clear();
            }
        }
        if (circuits[p].property->kind == Property::Kind::Cover) {
            if (verdict.status == Verdict::Status::Failed)
                verdict.status = Verdict::Status::Covered;
            else if (verdict.status == Verdict::Status::Proved)
                verdict.status = Verdict::Status::Unreachable;
        }
        if (options.verdictFound)
            options.verdictFound(verdict);
        verdicts.push_back(std::move(verdict));
    }
    return verdicts;
}

} // namespace rs::prove
