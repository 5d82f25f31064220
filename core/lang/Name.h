// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <compare>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

namespace rs::lang {

// A symbolic name as written (`GuardOk577`), its spelling held once for the
// whole program and shared by every operand that writes it: 8 bytes in an
// operand where a std::string took 32, and a large project writes each name
// many times (issue 23: a checked project's memory). Reads as the
// std::string it stands for. Two names are equal when their spellings are,
// which is when they point at the same spelling.
//
// Spellings are kept until the program ends, from every thread: a day of
// typing in the IDE adds the names typed, prefixes included, some tens of
// kilobytes.
class Name {
public:
    Name() = default;
    Name(std::string_view text); // implicit: a Name is given where a string was
    Name(const std::string& text) : Name(std::string_view(text)) {}
    Name(const char* text) : Name(std::string_view(text)) {}

    const std::string& str() const { return m_text ? *m_text : emptyText(); }
    operator const std::string&() const { return str(); }
    operator std::string_view() const { return str(); }

    bool empty() const { return m_text == nullptr; }
    std::size_t size() const { return str().size(); }
    const char* c_str() const { return str().c_str(); }

    friend bool operator==(const Name& a, const Name& b) { return a.m_text == b.m_text; }
    friend bool operator==(const Name& a, std::string_view b) { return a.str() == b; }
    friend bool operator==(const Name& a, const char* b) { return a.str() == b; }
    friend std::strong_ordering operator<=>(const Name& a, const Name& b) {
        return a.str() <=> b.str();
    }

    friend std::string operator+(const std::string& a, const Name& b) { return a + b.str(); }
    friend std::string operator+(std::string&& a, const Name& b) { return std::move(a) + b.str(); }
    friend std::string operator+(const char* a, const Name& b) { return a + b.str(); }

private:
    static const std::string& emptyText();

    const std::string* m_text = nullptr; // none: the empty name
};

} // namespace rs::lang
