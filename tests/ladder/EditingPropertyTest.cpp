// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomCondition.h"
#include "Sanitized.h"
#include "StepText.h"
#include "ladder/Editing.h"
#include "ladder/LadderToText.h"
#include "ladder/TextToLadder.h"

#include <gtest/gtest.h>

namespace {

using namespace rs::ladder;

class RandomEdits {
public:
    explicit RandomEdits(unsigned seed) : m_random(seed) {}

    Network network() {
        Network n;
        const int rungs = m_random.uniform(1, 3);
        for (int i = 0; i < rungs; ++i) {
            Rung rung;
            if (m_random.chance(85))
                rung.condition = toCircuit(m_random.expression(m_random.uniform(0, 3)));
            rung.outputs.push_back(output());
            // Through the editing operation, so the start is canonical too.
            EXPECT_TRUE(insertRung(n, n.items.size(), std::move(rung)).done());
        }
        return n;
    }

    Element element() { return toCircuit(m_random.leaf()).element; }

    // Outputs write memories the random conditions never read.
    Output output() {
        Output o;
        o.kind = m_random.chance(70) ? rs::lang::StatementKind::Coil : rs::lang::StatementKind::Set;
        o.target = {{}, {rs::lang::AddressKind::Memory, 0, m_random.uniform(10, 19)}, {}};
        return o;
    }

    // A path to some node of some rung, now and then one that leads nowhere.
    ElementPath path(const Network& n) {
        ElementPath p{
            static_cast<std::size_t>(m_random.uniform(0, static_cast<int>(n.items.size()))), {}};
        if (p.item >= n.items.size() || !std::holds_alternative<Rung>(n.items[p.item]))
            return p;
        const auto& rung = std::get<Rung>(n.items[p.item]);
        if (!rung.condition)
            return p;
        const Circuit* node = &*rung.condition;
        while (!node->isElement() && m_random.chance(70)) {
            p.node.push_back(static_cast<std::size_t>(
                m_random.uniform(0, static_cast<int>(node->parts.size()) - 1)));
            node = &node->parts[p.node.back()];
        }
        return p;
    }

    EditResult edit(Network& n, Network& other) {
        const Side side = m_random.chance(50) ? Side::Before : Side::After;
        switch (m_random.uniform(0, 11)) {
        case 0:
        case 1:
            return insertInSeries(n, path(n), element(), side);
        case 2:
            return insertInParallel(n, path(n), element(),
                                    static_cast<std::size_t>(m_random.uniform(1, 3)));
        case 3:
            return removeNode(n, path(n));
        case 4:
            return replaceElement(n, path(n), element());
        case 5:
            return moveNode(n, path(n), n, path(n), side);
        case 6:
            return moveNode(n, path(n), other, path(other), side);
        case 7:
            return addOutput(n, path(n).item, output());
        case 8:
            return removeOutput(n, path(n).item, static_cast<std::size_t>(m_random.uniform(0, 1)));
        case 9:
            return copyNode(n, path(n), n, path(n), side);
        case 10:
            return copyNode(other, path(other), n, path(n), side);
        default:
            return insertRung(n, path(n).item, std::get<Rung>(network().items[0]));
        }
    }

private:
    rs::test::RandomCondition m_random;
};

bool isCanonical(const Network& network) {
    for (const auto& item : network.items)
        if (const auto* rung = std::get_if<Rung>(&item)) {
            if (!isExpressible(*rung))
                return false;
            if (rung->condition) {
                Circuit copy = *rung->condition;
                normalize(copy);
                if (copy != *rung->condition)
                    return false;
            }
        }
    return true;
}

// What reading the network's text gives, record aside.
Network reread(const Network& network) {
    const std::string text = rs::test::printLines(toLines(StepLadder{{}, {network}}));
    StepLadder ladder =
        toLadder(rs::test::stepWithCode(text)); // throws when the text does not read
    EXPECT_EQ(ladder.networks.size(), 1U) << text;
    Network back = ladder.networks.at(0);
    back.record = network.record;
    return back;
}

// Whatever the editing operations do, the network stays one the text can
// say: in canonical form, and its text reads back as the same network.
// Refused edits change nothing.
TEST(EditingProperty, EveryEditLeavesANetworkTheTextReadsBackUnchanged) {
    int done = 0;
    int refused = 0;
    const unsigned cases = rs::test::randomCases(300);
    for (unsigned seed = 1; seed <= cases; ++seed) {
        RandomEdits random(seed);
        Network network = random.network();
        Network other = random.network();
        for (int step = 0; step < 30; ++step) {
            const Network before = network;
            const Network otherBefore = other;
            const EditResult result = random.edit(network, other);
            if (!result.done()) {
                ASSERT_EQ(network, before) << result.refusal;
                ASSERT_EQ(other, otherBefore) << result.refusal;
                ++refused;
                continue;
            }
            ++done;
            for (const Network* n : {&network, &other}) {
                ASSERT_TRUE(isCanonical(*n)) << "seed " << seed << " step " << step;
                ASSERT_EQ(reread(*n), *n) << "seed " << seed << " step " << step << ":\n"
                                          << rs::test::printLines(toLines(StepLadder{{}, {*n}}));
            }
            if (network.items.empty())
                network = random.network();
        }
    }
    EXPECT_GT(done, static_cast<int>(cases * 40 / 3)); // 4,000 of 300 networks' edits
    EXPECT_GT(refused, 300);
}

} // namespace
