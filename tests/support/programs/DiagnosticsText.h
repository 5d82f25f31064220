// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "compiler/Compiler.h"
#include "lang/Address.h"
#include "lang/Diagnostic.h"

#include <string>

namespace rs::test {

// "line:column: message", a line each, for the messages of failed expectations.
std::string diagnosticsText(const lang::Diagnostics& diagnostics);

// "line:column: error: message" (or "warning"), a line each.
std::string problemsText(const compiler::CompileResult& result);

// The address an address word such as "I0.1" or "R0.5" names.
lang::Address addressOf(const char* word);

} // namespace rs::test
