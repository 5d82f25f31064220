// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "compiler/Compiler.h"
#include "sim/Simulation.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace rs::test {

// A compiled program running in the simulator, addressed by address words.
class Simulated {
public:
    explicit Simulated(const std::string& text) {
        compiler::CompileResult result = compiler::compileText(text);
        for (const auto& d : result.diagnostics)
            if (d.severity == lang::Severity::Error)
                ADD_FAILURE() << d.line << ":" << d.column << ": " << d.message << "\n" << text;
        simulation = std::make_unique<sim::Simulation>(result.images);
    }

    static lang::Address at(const std::string& word) { return lang::readAddressWord(word).address; }
    std::int64_t operator[](const std::string& word) const { return simulation->value(at(word)); }
    void set(const std::string& word, std::int64_t value) { simulation->set(at(word), value); }
    void scans(int count) {
        for (int i = 0; i < count; ++i)
            simulation->scan();
    }

    std::unique_ptr<sim::Simulation> simulation;
};

// One A20 unit with instruction set 3, its PLC code being `code`.
inline std::string unitZero(const std::string& code, const std::string& sequences = "") {
    return "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n! pgm_pluto:00\nS0.0_0\n" + code +
           sequences;
}

} // namespace rs::test
