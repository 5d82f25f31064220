// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Invocation.h"

namespace rs::cli {

// `prove FILE.sps PROPS.prop [--cex DIR] [--depth N]`: proves each property
// of the property file over the compiled project, or writes the input
// sequence that breaks it as a scenario (../shared/spec/properties.md).
int runProve(const Invocation& invocation);

} // namespace rs::cli
