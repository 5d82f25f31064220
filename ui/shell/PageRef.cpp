// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/PageRef.h"

#include "document/ProjectDocument.h"

namespace rs::ui {

bool PageRef::operator==(const PageRef& other) const {
    return kind == other.kind && document == other.document && station == other.station &&
           sequence == other.sequence;
}

} // namespace rs::ui
