// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

namespace rs::lang {

// A part of a syntax node that most nodes leave at its default (an
// assignment of a statement that is none): held apart, so that a node
// without it is small (issue 23: a large project's lines were 696 bytes
// each). Read, it is the default until written; written (non-const access,
// assignment), it holds a value of its own. Copies are deep.
template <typename T> class Rare {
public:
    Rare() = default;
    Rare(const T& value) { *this = value; } // implicit: a T is given where a Rare<T> is kept
    Rare(const Rare& other)
        : m_value(other.m_value ? std::make_unique<T>(*other.m_value) : nullptr) {}
    Rare(Rare&&) noexcept = default;
    Rare& operator=(const Rare& other) {
        if (this != &other)
            m_value = other.m_value ? std::make_unique<T>(*other.m_value) : nullptr;
        return *this;
    }
    Rare& operator=(Rare&&) noexcept = default;
    Rare& operator=(const T& value) {
        if (value == defaultValue())
            m_value.reset();
        else if (m_value)
            *m_value = value;
        else
            m_value = std::make_unique<T>(value);
        return *this;
    }

    // Whether it was written; else it is the default.
    bool held() const { return m_value != nullptr; }

    const T& operator*() const { return m_value ? *m_value : defaultValue(); }
    const T* operator->() const { return &**this; }
    T& operator*() {
        if (!m_value)
            m_value = std::make_unique<T>();
        return *m_value;
    }
    T* operator->() { return &**this; }

    friend bool operator==(const Rare& a, const Rare& b) { return *a == *b; }

private:
    static const T& defaultValue() {
        static const T value{};
        return value;
    }

    std::unique_ptr<T> m_value;
};

} // namespace rs::lang
