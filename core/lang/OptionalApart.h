// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>
#include <optional>
#include <utility>

namespace rs::lang {

// An optional value held apart, with std::optional's interface: for a part
// of a syntax node that few nodes have (a register as a timer's preset or a
// comparison's right side, a line's trailing comment), so that a node
// without it stays small (issue 23: an operand takes 72 bytes in a
// std::optional, 8 here). Copies are deep.
template <typename T> class OptionalApart {
public:
    OptionalApart() = default;
    OptionalApart(std::nullopt_t) {}
    OptionalApart(const T& value) : m_value(std::make_unique<T>(value)) {}
    OptionalApart(T&& value) : m_value(std::make_unique<T>(std::move(value))) {}
    OptionalApart(const std::optional<T>& value)
        : m_value(value ? std::make_unique<T>(*value) : nullptr) {}
    OptionalApart(const OptionalApart& other)
        : m_value(other.m_value ? std::make_unique<T>(*other.m_value) : nullptr) {}
    OptionalApart(OptionalApart&&) noexcept = default;
    OptionalApart& operator=(const OptionalApart& other) {
        if (this != &other)
            m_value = other.m_value ? std::make_unique<T>(*other.m_value) : nullptr;
        return *this;
    }
    OptionalApart& operator=(OptionalApart&&) noexcept = default;
    OptionalApart& operator=(std::nullopt_t) {
        m_value.reset();
        return *this;
    }
    OptionalApart& operator=(const T& value) {
        emplace(value);
        return *this;
    }
    OptionalApart& operator=(T&& value) {
        emplace(std::move(value));
        return *this;
    }

    template <typename... Args> T& emplace(Args&&... args) {
        m_value = std::make_unique<T>(std::forward<Args>(args)...);
        return *m_value;
    }
    void reset() { m_value.reset(); }

    bool has_value() const { return m_value != nullptr; }
    explicit operator bool() const { return has_value(); }
    const T& operator*() const { return *m_value; }
    T& operator*() { return *m_value; }
    const T* operator->() const { return m_value.get(); }
    T* operator->() { return m_value.get(); }
    const T& value() const {
        if (!m_value)
            throw std::bad_optional_access();
        return *m_value;
    }
    T& value() {
        if (!m_value)
            throw std::bad_optional_access();
        return *m_value;
    }

    template <typename U> T value_or(U&& fallback) const {
        return m_value ? *m_value : static_cast<T>(std::forward<U>(fallback));
    }
    // What std::optional code is given.
    operator std::optional<T>() const {
        return m_value ? std::optional<T>(*m_value) : std::nullopt;
    }

    friend bool operator==(const OptionalApart& a, const OptionalApart& b) {
        return a.has_value() == b.has_value() && (!a.has_value() || *a == *b);
    }
    friend bool operator==(const OptionalApart& a, std::nullopt_t) { return !a.has_value(); }

private:
    std::unique_ptr<T> m_value;
};

} // namespace rs::lang
