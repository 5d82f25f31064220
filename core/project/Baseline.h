// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Annotation.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

// The version of a project last marked as validated (docs/review.md): who,
// when and why, and enough of what it was to say what changed since then.
// Rungsmith's answer to the manual's seal (Part 1, 15.7): like the seal it
// changes nothing a unit does.
namespace rs::project {

struct ValidatedUnit {
    std::uint32_t signature = 0;
    // By (sequence, step): the CRC-32 of what each network did, in order.
    std::map<std::pair<int, int>, std::vector<std::uint32_t>> networks;
    friend bool operator==(const ValidatedUnit&, const ValidatedUnit&) = default;
};

struct Baseline {
    std::string date; // YYYY-MM-DD
    std::string by;
    std::string comment;
    std::uint32_t signature = 0;        // the project's
    std::map<int, ValidatedUnit> units; // by station
    friend bool operator==(const Baseline&, const Baseline&) = default;
};

// The ;@validated records: one for the project, one per unit
// (docs/file-format.md).
std::vector<Annotation> baselineRecords(const Baseline& baseline);

struct BaselineRecordError {
    std::string message;
};

// Reads one ;@validated record into the baseline; throws BaselineRecordError.
void readBaselineRecord(const Annotation& record, Baseline& baseline);

} // namespace rs::project
