// SPDX-License-Identifier: GPL-3.0-or-later
#include "PowerPaths.h"

#include <algorithm>
#include <set>

namespace rs::ladder {

namespace {

class Explainer {
public:
    explicit Explainer(const std::function<bool(std::uint16_t)>& conducts) : m_conducts(conducts) {}

    // Adds the first blocker of every path through `c` that does not conduct
    // all along; whether some path through it does. `number` is c's own.
    bool blockers(const Circuit& c, std::uint16_t number) {
        switch (c.kind) {
        case Circuit::Kind::Element:
            if (m_conducts(number))
                return true;
            m_blockers.insert(number);
            return false;
        case Circuit::Kind::Series: {
            // A path goes on to the next part only where it conducted through
            // this one; where none did, what follows blocks no path first.
            std::uint16_t part = number + 1;
            for (const Circuit& p : c.parts) {
                if (!blockers(p, part))
                    return false;
                part = static_cast<std::uint16_t>(part + nodeCount(p));
            }
            return true;
        }
        case Circuit::Kind::Parallel: {
            bool any = false;
            std::uint16_t branch = number + 1;
            for (const Circuit& p : c.parts) {
                any = blockers(p, branch) || any;
                branch = static_cast<std::uint16_t>(branch + nodeCount(p));
            }
            return any;
        }
        }
        return false;
    }

    // Whether some path through `c` conducts all along.
    bool conducts(const Circuit& c, std::uint16_t number) const {
        std::uint16_t part = number + 1;
        switch (c.kind) {
        case Circuit::Kind::Element:
            return m_conducts(number);
        case Circuit::Kind::Series:
            for (const Circuit& p : c.parts) {
                if (!conducts(p, part))
                    return false;
                part = static_cast<std::uint16_t>(part + nodeCount(p));
            }
            return true;
        case Circuit::Kind::Parallel:
            for (const Circuit& p : c.parts) {
                if (conducts(p, part))
                    return true;
                part = static_cast<std::uint16_t>(part + nodeCount(p));
            }
            return false;
        }
        return false;
    }

    // The elements of the topmost path through `c` that conducts all along.
    void holding(const Circuit& c, std::uint16_t number, std::vector<std::uint16_t>& path) const {
        std::uint16_t part = number + 1;
        switch (c.kind) {
        case Circuit::Kind::Element:
            path.push_back(number);
            return;
        case Circuit::Kind::Series:
            for (const Circuit& p : c.parts) {
                holding(p, part, path);
                part = static_cast<std::uint16_t>(part + nodeCount(p));
            }
            return;
        case Circuit::Kind::Parallel:
            for (const Circuit& p : c.parts) {
                if (conducts(p, part)) {
                    holding(p, part, path);
                    return;
                }
                part = static_cast<std::uint16_t>(part + nodeCount(p));
            }
            return;
        }
    }

    std::vector<std::uint16_t> found() const { return {m_blockers.begin(), m_blockers.end()}; }

private:
    const std::function<bool(std::uint16_t)>& m_conducts;
    std::set<std::uint16_t> m_blockers; // pre-order numbers sort in pre-order
};

} // namespace

PowerPaths powerPaths(const std::optional<Circuit>& condition,
                      const std::function<bool(std::uint16_t)>& conducts) {
    PowerPaths paths;
    if (!condition) {
        paths.conducting = true; // the rail alone
        return paths;
    }
    Explainer explainer(conducts);
    paths.conducting = explainer.blockers(*condition, 1);
    paths.blockers = explainer.found();
    if (paths.conducting)
        explainer.holding(*condition, 1, paths.holding);
    return paths;
}

} // namespace rs::ladder
