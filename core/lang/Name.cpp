// SPDX-License-Identifier: GPL-3.0-or-later
#include "Name.h"

#include <array>
#include <functional>
#include <mutex>
#include <unordered_set>

namespace rs::lang {

namespace {

struct TextHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view text) const {
        return std::hash<std::string_view>{}(text);
    }
};

// The spellings of every thread, behind one lock; each node stays where it
// is while the set grows, so a pointer to its string stays good.
class Spellings {
public:
    const std::string* find(std::string_view text, std::size_t hash) {
        // Most names were met a moment ago: each thread asks its own table
        // of recent ones first, without taking the lock.
        thread_local std::array<const std::string*, 512> recent{};
        const std::string*& slot = recent[hash % recent.size()];
        if (slot && *slot == text)
            return slot;
        const std::lock_guard lock(m_mutex);
        auto found = m_texts.find(text);
        if (found == m_texts.end())
            found = m_texts.emplace(text).first;
        slot = &*found;
        return slot;
    }

private:
    std::mutex m_mutex;
    std::unordered_set<std::string, TextHash, std::equal_to<>> m_texts;
};

Spellings& spellings() {
    // Never destroyed: names in other static objects may outlive any order of destruction.
    static Spellings* all = new Spellings;
    return *all;
}

} // namespace

Name::Name(std::string_view text)
    : m_text(text.empty() ? nullptr : spellings().find(text, TextHash{}(text))) {}

const std::string& Name::emptyText() {
    static const std::string empty;
    return empty;
}

} // namespace rs::lang
