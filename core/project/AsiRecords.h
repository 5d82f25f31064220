// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Annotation.h"
#include "AsiOptions.h"

#include <map>
#include <string>
#include <vector>

// The AS-i Options page's records in the project file (docs/file-format.md):
//   ;@asi 00 mode="monitor_slave" address="5" optimize="immunity"
//   ;@asi_slave ASi0.3 type="safe_input" model="General" param="F"
//               profile="S-0.B.F" id1="F" monitoring="simultaneous" time_limit_ms="500"
namespace rs::project {

struct AsiRecordError {
    std::string message;
};

// The records of one unit's options; none for the defaults (bus master,
// short stop time, no slave defined).
std::vector<Annotation> asiRecords(int station, const AsiOptions& options);

// Reads an "asi" or "asi_slave" record into the options by station; throws
// AsiRecordError for a malformed one.
void readAsiRecord(const Annotation& record, std::map<int, AsiOptions>& options);

} // namespace rs::project
