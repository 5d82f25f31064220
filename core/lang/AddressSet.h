// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Address.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace rs::lang {

// A set of addresses in one array (open addressing, linear probing). The
// checks ask it for every operand of a project: a node-based hash set spent
// more time finding its nodes than the checks spent checking.
class AddressSet {
public:
    // True when `address` was not in the set before.
    bool insert(const Address& address) {
        if ((m_size + 1) * 4 > m_slots.size() * 3)
            grow();
        Slot& slot = m_slots[find(address)];
        if (slot.used)
            return false;
        slot = {address, true};
        ++m_size;
        return true;
    }

    bool contains(const Address& address) const {
        return !m_slots.empty() && m_slots[find(address)].used;
    }

    std::size_t size() const { return m_size; }

    // Every address in the set, in the order of Address.
    std::vector<Address> sorted() const {
        std::vector<Address> all;
        all.reserve(m_size);
        for (const Slot& slot : m_slots)
            if (slot.used)
                all.push_back(slot.address);
        std::sort(all.begin(), all.end());
        return all;
    }

private:
    struct Slot {
        Address address;
        bool used = false;
    };

    static std::uint64_t hashOf(const Address& a) {
        // Fibonacci hashing spreads the fields over the high bits used below.
        return std::hash<Address>{}(a)*0x9E3779B97F4A7C15ULL;
    }

    // The slot holding `address`, or the empty slot where it would go.
    std::size_t find(const Address& address) const {
        const std::size_t mask = m_slots.size() - 1;
        std::size_t at = static_cast<std::size_t>(hashOf(address) >> m_shift) & mask;
        while (m_slots[at].used && !(m_slots[at].address == address))
            at = (at + 1) & mask;
        return at;
    }

    void grow() {
        std::vector<Slot> old = std::move(m_slots);
        const std::size_t capacity = old.empty() ? 64 : old.size() * 2;
        m_slots.assign(capacity, Slot{});
        m_shift = 64 - std::countr_zero(capacity);
        for (const Slot& slot : old)
            if (slot.used)
                m_slots[find(slot.address)] = slot;
    }

    std::vector<Slot> m_slots;
    std::size_t m_size = 0;
    int m_shift = 64;
};

} // namespace rs::lang
