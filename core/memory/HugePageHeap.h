// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace rs::memory {

// Asks the kernel to back the heap with 2 MB pages where it can
// (docs/performance.md, "Page faults"). Call once, first thing in main.
void backTheHeapWithHugePages();

} // namespace rs::memory
