// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"
#include "ProtectionKeys.h"
#include "lang/Diagnostic.h"

#include <optional>
#include <string>
#include <string_view>

// The signatures of a password-protected project file (docs/file-format.md,
// "Password protection"). The main key signs the file's text without its
// ;@protected record and with each Config Option's state masked; the options
// are signed apart (by the options' own key or the main one), so that they can
// change with the permission to configure alone.
namespace rs::project {

// The text with every Config Option's state masked (a ;@network record with
// option="on|off" directly followed by its S(...) or R(...) alone on a line):
// two texts whose masks are equal differ in their options' states only.
std::string withoutOptionStates(std::string_view text);

// Whether `after` differs from `before` in its Config Options' states alone
// (or not at all): what permission to configure may change.
bool changesOnlyOptions(const Project& before, const Project& after);

// The text with its ;@protected record (as writeProject writes it) sealed: its
// line digest and signatures made by the keys held. Without the main key the
// main signature stays as it was, so only the options may have changed. A
// text without the record comes back unchanged.
std::string sealProjectText(std::string_view text, const Keyring& keys);

// For a text with a ;@protected record: nothing when it is as its signatures
// say, else an error at the first line a change outside Rungsmith touched (at
// the record when only the record was touched, or it cannot be read). Nothing
// for a text without the record.
std::optional<lang::Diagnostic> verifyProjectText(std::string_view text);

} // namespace rs::project
