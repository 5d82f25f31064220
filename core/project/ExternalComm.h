// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Annotation.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

// A unit's External communication setting (manual Part 1, 5.3; Gateway
// manual 4.5): which gateway packet each of its four External Comm Blocks
// receives, and after how long without one the block's data is cleared.
//   ;@ext_comm 01 0 gateway="0" packet="2" timeout_ms="500"
namespace rs::project {

inline constexpr int kExternalCommBlocks = 4;
inline constexpr int kDefaultExternalTimeoutMs = 1000;
inline constexpr int kMaxExternalTimeoutMs = 60'000;

struct ExternalCommBlock {
    int gateway = 0; // the sending gateway's node address 0-15
    int packet = 0;  // its Data to Pluto packet 0-3
    // No packet for this long clears the block's data and validity; 0 never.
    int timeoutMs = kDefaultExternalTimeoutMs;

    friend bool operator==(const ExternalCommBlock&, const ExternalCommBlock&) = default;
};

// A unit's blocks in use, by block number 0-3.
using ExternalComm = std::map<int, ExternalCommBlock>;

std::optional<std::string> externalCommProblem(const ExternalCommBlock& block);

struct ExternalCommRecordError {
    std::string message;
};

// One record per block in use; the timeout only when not the default.
std::vector<Annotation> externalCommRecords(int station, const ExternalComm& comm);
// Reads an "ext_comm" record into the units' settings by station; throws
// ExternalCommRecordError for a malformed one, a block given twice or a value
// out of range.
void readExternalCommRecord(const Annotation& record, std::map<int, ExternalComm>& units);

} // namespace rs::project
