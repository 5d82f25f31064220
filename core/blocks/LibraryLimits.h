// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>

// What a library file may hold (docs/block-libraries.md, "Limits"). Far
// beyond any real library, and small enough that reading a hostile file
// stays fast and every block can be drawn and expanded.
namespace rs::blocks {

inline constexpr std::size_t kMaxLibraryBytes = 4 * 1024 * 1024;
inline constexpr std::size_t kMaxLineBytes = 4000;
inline constexpr std::size_t kMaxBlocks = 1000;
inline constexpr std::size_t kMaxPins = 64;
inline constexpr std::size_t kMaxPrivates = 256;
inline constexpr std::size_t kMaxBodyLines = 2000;
inline constexpr std::size_t kMaxDescriptionLines = 200;
inline constexpr int kMaxTimers = 50; // a unit's timers (language.md)
inline constexpr std::size_t kMaxNameLength = 40;
inline constexpr std::size_t kMaxPinNameLength = 32;
inline constexpr std::size_t kMaxVersionLength = 20;

} // namespace rs::blocks
