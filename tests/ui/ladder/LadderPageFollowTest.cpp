// SPDX-License-Identifier: GPL-3.0-or-later
// The ladder page follows a change of a run of lines by reading and laying
// out only the networks it touches; whatever the edit, the page must end as
// a page opened on the project anew would be.
#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "ladder/NetworkItem.h"
#include "project/Annotation.h"
#include "project/ProjectFile.h"

#include <QUndoStack>

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>

namespace {

using rs::ui::LadderPage;
using rs::ui::ProjectDocument;

// A unit whose PLC code has networks with and without records, comment and
// blank lines and rungs of several outputs, and a sequence after it.
std::string projectText(std::mt19937& random) {
    const auto uniform = [&](int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(random);
    };
    const auto statements = [&](int count) {
        std::string code;
        for (int i = 0; i < count; ++i) {
            switch (uniform(0, 9)) {
            case 0:
                code += ";" +
                        rs::project::formatAnnotation(
                            {"network", {}, {{"comment", "Network " + std::to_string(i)}}}) +
                        "\n";
                break;
            case 1:
                code += "; a comment line\n";
                break;
            case 2:
                code += "\n";
                break;
            default:
                break;
            }
            const int condition = uniform(0, 7);
            code += "Q0." + std::to_string(uniform(0, 3)) + " = I0." + std::to_string(condition) +
                    " * /I0." + std::to_string((condition + 1) % 8) + "\n";
            if (uniform(0, 4) == 0)
                code += "M0." + std::to_string(uniform(0, 9)) + " = I0." +
                        std::to_string(condition) + " * /I0." +
                        std::to_string((condition + 1) % 8) + "\n";
        }
        return code;
    };
    return "! id_pluto:00=000034AD4AE1\n! pgm_pluto:00\n\nS0.0_0\n" + statements(40) +
           "\nS0.1_0\n" + statements(6) + "J(+1) = I0.1\nS0.1_1\n" + statements(6) +
           "J(0) = I0.2\n";
}

void expectSamePages(const LadderPage& page, const LadderPage& fresh, const std::string& after) {
    ASSERT_EQ(page.stepCount(), fresh.stepCount()) << after;
    for (int s = 0; s < fresh.stepCount(); ++s) {
        ASSERT_EQ(page.networkCount(s), fresh.networkCount(s)) << after << ", step " << s;
        for (int n = 0; n < fresh.networkCount(s); ++n) {
            const rs::ui::NetworkItem* item = page.networkItem(s, n);
            ASSERT_EQ(item->step(), s);
            ASSERT_EQ(item->index(), n);
            ASSERT_EQ(item->network(), fresh.networkItem(s, n)->network())
                << after << ", step " << s << ", network " << n;
            ASSERT_TRUE(item->layout() == fresh.networkItem(s, n)->layout())
                << after << ", step " << s << ", network " << n;
            ASSERT_EQ(item->pos(), fresh.networkItem(s, n)->pos()) << after;
        }
    }
}

TEST(LadderPageFollow, RandomEditsUndoAndRedoLeaveThePagesAsPagesOpenedAnew) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
        std::mt19937 random(seed);
        const auto uniform = [&](int low, int high) {
            return std::uniform_int_distribution<int>(low, high)(random);
        };
        auto read = rs::project::readProject(projectText(random));
        ASSERT_TRUE(read.diagnostics.empty());
        ProjectDocument document(std::move(read.project));
        // The PLC code's page, and the sequence's after it, whose statements
        // an edit of the PLC code numbers anew.
        LadderPage code;
        code.showUnit(&document, 0, 0);
        LadderPage sequence;
        sequence.showUnit(&document, 0, 1);
        for (int round = 0; round < 60; ++round) {
            LadderPage& page = uniform(0, 3) == 0 ? sequence : code;
            const int step = uniform(0, page.stepCount() - 1);
            const int networks = page.networkCount(step);
            std::string what;
            switch (uniform(0, 7)) {
            case 0:
            case 1:
                what = "paste";
                page.setCursor({step, uniform(0, networks - 1), std::nullopt, std::nullopt, -1});
                page.copyNetworks();
                page.setCursor({step, uniform(0, networks - 1), std::nullopt, std::nullopt, -1});
                page.pasteNetworks();
                break;
            case 2:
                what = "delete";
                if (networks > 1) {
                    page.setCursor(
                        {step, uniform(0, networks - 1), std::nullopt, std::nullopt, -1});
                    page.deleteNetworks();
                }
                break;
            case 3:
                what = "cut";
                if (networks > 1) {
                    page.setCursor(
                        {step, uniform(0, networks - 1), std::nullopt, std::nullopt, -1});
                    page.cutNetworks();
                }
                break;
            case 4: {
                // An edit of one network: an element or output of it deleted.
                what = "delete element";
                const auto& elements =
                    page.networkItem(step, uniform(0, networks - 1))->layout().elements;
                if (!elements.empty()) {
                    const auto& element = elements[static_cast<std::size_t>(
                        uniform(0, static_cast<int>(elements.size()) - 1))];
                    ASSERT_TRUE(page.selectElement(element.statement, element.element));
                    page.deleteSelection();
                }
                break;
            }
            case 5:
                what = "undo";
                document.undoStack()->undo();
                break;
            case 6:
                what = "redo";
                document.undoStack()->redo();
                break;
            default: {
                // As the text view types: a line of the unit's code changed.
                what = "text";
                const auto& unit = document.project().program.units.front();
                const auto stepIndex =
                    static_cast<std::size_t>(uniform(0, static_cast<int>(unit.steps.size()) - 1));
                const auto& lines = unit.steps[stepIndex].lines;
                const auto first =
                    static_cast<std::size_t>(uniform(0, static_cast<int>(lines.size())));
                const auto removed = static_cast<std::size_t>(
                    uniform(0, std::min(3, static_cast<int>(lines.size() - first))));
                std::vector<rs::lang::Line> added;
                for (int i = uniform(0, 3); i > 0 && !lines.empty(); --i)
                    added.push_back(lines[static_cast<std::size_t>(
                        uniform(0, static_cast<int>(lines.size()) - 1))]);
                document.replaceStepLines(QStringLiteral("Typing"), 0, stepIndex, first, removed,
                                          std::move(added));
                break;
            }
            }
            what += " in round " + std::to_string(round) + ", seed " + std::to_string(seed);
            for (const LadderPage* shown : {&code, &sequence}) {
                LadderPage fresh;
                fresh.showUnit(&document, 0, shown->sequence());
                expectSamePages(*shown, fresh, what);
            }
        }
    }
}

} // namespace
