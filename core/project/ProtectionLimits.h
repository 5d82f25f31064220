// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>

// Sizes and bounds of password protection, shared by the record (Protection.h)
// and the cryptography (ProjectSeal.cpp checks them against libsodium's).
namespace rs::project {

inline constexpr std::size_t kSaltBytes = 16;
inline constexpr std::size_t kPublicKeyBytes = 32;
inline constexpr std::size_t kSignatureBytes = 64;

// Argon2id cost as a file may state it. New protection uses libsodium's
// "interactive" cost (2 passes over 64 MiB, a fraction of a second); the
// bounds keep a hostile file from making a reader work for minutes.
inline constexpr int kMinPasses = 1;
inline constexpr int kMaxPasses = 10;
inline constexpr long long kMinMemoryBytes = 8 * 1024;
inline constexpr long long kMaxMemoryBytes = 1024LL * 1024 * 1024;

} // namespace rs::project
