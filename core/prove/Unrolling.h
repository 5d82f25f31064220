// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ScanModel.h"

#include <cadical.hpp>

#include <cstdint>
#include <memory>
#include <vector>

// Scans one after another in a SAT solver: frame f is the state before scan
// f + 1 and that scan's inputs. Only what a question reaches is encoded (the
// cone of the literals asked for), frame by frame, on demand.
namespace rs::prove {

class Unrolling {
public:
    // From power on, or (`freeStart`) from any state at all, as an induction
    // step starts. Only the cone of `roots` (through any number of scans)
    // can be asked for; no roots: the whole model.
    Unrolling(const ScanModel& model, bool freeStart, const std::vector<Lit>& roots = {});
    ~Unrolling();
    Unrolling(const Unrolling&) = delete;
    Unrolling& operator=(const Unrolling&) = delete;

    // The solver's literal for `a` in frame `frame`.
    int literal(Lit a, int frame);
    int newVariable() { return ++m_variables; }
    void addClause(std::initializer_list<int> literals);
    void addClause(const std::vector<int>& literals);

    // 10 satisfiable, 20 not, 0 stopped by the deadline's terminator.
    int solve(const std::vector<int>& assumptions);
    bool failed(int literal) { return m_solver->failed(literal); }
    // After a satisfiable solve; 0 for what no question reached.
    bool value(Lit a, int frame);
    std::int64_t value(const Word& word, int frame);
    void setTerminator(CaDiCaL::Terminator* terminator) {
        m_solver->connect_terminator(terminator);
    }

    std::int64_t clauses() const { return m_clauses; }
    int variables() const { return m_variables; }

private:
    const ScanModel& m_model;
    bool m_freeStart;
    std::unique_ptr<CaDiCaL::Solver> m_solver;
    // Per frame, by the node's place in the cone: its solver variable, 0 none
    // yet. Sized by the cone, not the model, so deep unrollings of a large
    // project stay small.
    std::vector<std::vector<int>> m_frames;
    std::vector<std::int32_t> m_place; // node -> place in the cone, or -1
    std::size_t m_coneSize = 0;
    int m_variables = 0;
    int m_true = 0;
    std::int64_t m_clauses = 0;
};

} // namespace rs::prove
