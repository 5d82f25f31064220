// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomScanProgram.h"

namespace rs::test {

std::string RandomScanProgram::bit(bool forWriting) {
    const std::string u = std::to_string(m_unit);
    switch (uniform(0, forWriting ? 3 : 6)) {
    case 0:
        return "Q" + u + "." + std::to_string(uniform(0, 3));
    case 1:
        return "M" + u + "." + std::to_string(uniform(0, 5));
    case 2:
        return "GM" + u + "." + std::to_string(uniform(0, 2));
    case 3:
        return "R" + u + "." + std::to_string(uniform(0, 5)) + "." + std::to_string(uniform(0, 15));
    case 4:
        return "I" + u + "." + std::to_string(uniform(0, 4));
    case 5: { // the other unit's globals, over the bus
        const std::string other = std::to_string(1 - m_unit);
        return chance(50) ? "Q" + other + "." + std::to_string(uniform(0, 3))
                          : "GM" + other + "." + std::to_string(uniform(0, 2));
    }
    default:
        return "SM" + u + "." + std::to_string(uniform(0, 1) ? 9 : 11);
    }
}

std::string RandomScanProgram::leaf() {
    switch (uniform(0, 9)) {
    case 0:
        return std::string(chance(50) ? "P(" : "N(") + (chance(20) ? "/" : "") + bit(false) + ")";
    case 1: {
        static const char* const ops[] = {"=", ">", "<", ">=", "<="};
        const std::string right =
            chance(50) ? reg() : std::to_string(uniform(-3, 3) * (chance(20) ? 10000 : 1));
        return "(" + reg() + ops[uniform(0, 4)] + right + ")";
    }
    default:
        return (chance(30) ? "/" : "") + bit(false);
    }
}

std::string RandomScanProgram::term(int depth) {
    std::string text = depth > 0 && chance(25) ? "(" + expression(depth - 1) + ")" : leaf();
    const int more = uniform(0, 2);
    for (int i = 0; i < more; ++i)
        text += " * " + (depth > 0 && chance(20) ? "(" + expression(depth - 1) + ")" : leaf());
    if (chance(20)) {
        static const char* const timers[] = {"TON", "TPS", "TOF"};
        const std::string preset = chance(25) ? reg() : "0s0" + std::to_string(uniform(1, 9));
        text += std::string(" * ") + (chance(20) ? "/" : "") + timers[uniform(0, 2)] + "(" +
                preset + ")";
    }
    return text;
}

std::string RandomScanProgram::expression(int depth) {
    std::string text = term(depth);
    const int more = uniform(0, 1);
    for (int i = 0; i < more; ++i)
        text += " + " + term(depth);
    return text;
}

std::string RandomScanProgram::statement(bool inSequence, int steps) {
    const std::string condition = expression(1);
    switch (uniform(0, inSequence ? 9 : 8)) {
    case 0:
    case 1:
    case 2:
        return bit(true) + " = " + condition;
    case 3: {
        static const char* const latches[] = {"S", "R", "T"};
        return std::string(latches[uniform(0, 2)]) + "(" + bit(true) + ") = " + condition;
    }
    case 4:
    case 5: {
        const std::string target = reg();
        std::string assignment;
        switch (uniform(0, 7)) {
        case 0:
            assignment = target + (chance(50) ? "++" : "--");
            break;
        case 1:
            assignment = target + " = " + std::to_string(uniform(-40000, 40000) / 2);
            break;
        case 2: {
            static const char* const ops[] = {"+", "-", "*", "/"};
            assignment = target + " = " + reg() + " " + ops[uniform(0, 3)] + " " + reg();
            break;
        }
        case 3:
            assignment = target + " += " + (chance(50) ? reg() : std::to_string(uniform(1, 9000)));
            break;
        case 4:
            assignment = target + " -= " + reg();
            break;
        case 5:
            assignment =
                target + " *= " + (chance(50) ? reg() : std::to_string(uniform(-300, 300)));
            break;
        case 6:
            assignment = target + " /= " + reg();
            break;
        default:
            assignment = target + " = " + reg();
            break;
        }
        return "(" + assignment + ")" + (chance(70) ? " = " + condition : "");
    }
    case 6:
        return "R(S" + std::to_string(m_unit) + ".1) = " + condition;
    case 7:
    case 8:
        return bit(true) + " = " + condition;
    default:
        return "J(" + std::to_string(uniform(0, steps - 1)) + ") = " + condition;
    }
}

std::string RandomScanProgram::text() {
    std::string text = "$name Random\n";
    for (m_unit = 0; m_unit < 2; ++m_unit) {
        const std::string u = "0" + std::to_string(m_unit);
        text += "! id_pluto:" + u + "=00000000000" + std::to_string(m_unit) + "\n";
        text += "! type_pluto:" + u + "=A20,is3\n";
    }
    for (m_unit = 0; m_unit < 2; ++m_unit) {
        const std::string u = std::to_string(m_unit);
        text += "! pgm_pluto:0" + u + "\nS" + u + ".0_0\n";
        const int plc = uniform(2, 6);
        for (int i = 0; i < plc; ++i) {
            std::string line = statement(false, 1);
            if (line.rfind("R(S", 0) == 0 && chance(50))
                line = bit(true) + " = " + expression(1);
            text += line + "\n";
        }
        const int steps = uniform(1, 3);
        for (int step = 0; step < steps; ++step) {
            text += "S" + u + ".1_" + std::to_string(step) + "\n";
            const int count = uniform(1, 4);
            for (int i = 0; i < count; ++i) {
                std::string line = statement(true, steps);
                if (line.rfind("R(S", 0) == 0) // a sequence may not hold itself
                    line = bit(true) + " = " + expression(1);
                text += line + "\n";
            }
        }
    }
    return text;
}

} // namespace rs::test
