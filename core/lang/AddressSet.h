// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Address.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <set>
#include <vector>

namespace rs::lang {

// A set of addresses in one array (open addressing, linear probing). The
// checks ask it for every operand of a project: a node-based hash set spent
// more time finding its nodes than the checks spent checking.
class AddressSet {
public:
    // True when `address` was not in the set before.
    bool insert(const Address& address) {
        if (!address.valid()) {
            const bool added = m_invalid.insert(address).second;
            m_size += added;
            return added;
        }
        if ((m_size + 1) * 4 > m_slots.size() * 3)
            grow();
        Address& slot = m_slots[find(address)];
        if (slot.valid())
            return false;
        slot = address;
        ++m_size;
        return true;
    }

    bool contains(const Address& address) const {
        if (!address.valid())
            return m_invalid.count(address) != 0;
        return !m_slots.empty() && m_slots[find(address)].valid();
    }

    std::size_t size() const { return m_size; }

    // Every address in the set, in the order of Address.
    std::vector<Address> sorted() const {
        std::vector<Address> all;
        all.reserve(m_size);
        all.insert(all.end(), m_invalid.begin(), m_invalid.end());
        for (const Address& slot : m_slots)
            if (slot.valid())
                all.push_back(slot);
        std::sort(all.begin(), all.end());
        return all;
    }

private:
    static std::uint64_t hashOf(const Address& a) {
        // Fibonacci hashing spreads the fields over the high bits used below.
        return std::hash<Address>{}(a)*0x9E3779B97F4A7C15ULL;
    }

    // The slot holding `address`, or the empty slot where it would go.
    std::size_t find(const Address& address) const {
        const std::size_t mask = m_slots.size() - 1;
        std::size_t at = static_cast<std::size_t>(hashOf(address) >> m_shift) & mask;
        while (m_slots[at].valid() && !(m_slots[at] == address))
            at = (at + 1) & mask;
        return at;
    }

    void grow() {
        std::vector<Address> old = std::move(m_slots);
        const std::size_t capacity = old.empty() ? 64 : old.size() * 2;
        m_slots.assign(capacity, Address{});
        m_shift = 64 - std::countr_zero(capacity);
        for (const Address& slot : old)
            if (slot.valid())
                m_slots[find(slot)] = slot;
    }

    // A slot is free while it holds no valid address; the addresses that are
    // not valid (of unresolved names, rare) are kept apart, so that a slot is
    // an address and no more.
    std::vector<Address> m_slots;
    std::set<Address> m_invalid;
    std::size_t m_size = 0;
    int m_shift = 64;
};

} // namespace rs::lang
