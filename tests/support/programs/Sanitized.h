// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Whether this test program runs under AddressSanitizer. The sanitizer run
// (scripts/dev test) looks for memory errors, which a fifth of a property
// test's random cases finds as well as all of them, at a fifth of the time;
// the optimised run keeps the full count.
namespace rs::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

// How many random cases a property test runs: `cases`, a fifth under the sanitizer.
constexpr unsigned randomCases(unsigned cases) {
    return kSanitized ? cases / 5 : cases;
}

} // namespace rs::test
