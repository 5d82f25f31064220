// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Ast.h"

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rs::project {

// A structured comment ";@kind word key="value" ...": what the IDE records
// that the language has no words for. Plain text editors and the original
// compiler read it as a comment.
struct Annotation {
    std::string kind;                   // "project", "unit", "var", "network"
    std::vector<std::string> arguments; // bare words after the kind
    std::vector<std::pair<std::string, std::string>> attributes;

    std::string value(std::string_view key) const;
};

struct AnnotationError {
    int offset = 0; // characters into the comment text
    std::string message;
};

// Reads the text after ';'. Returns nothing when the comment is no annotation
// (does not start with '@'); throws AnnotationError when it is one but malformed.
std::optional<Annotation> parseAnnotation(std::string_view commentText);

// The well-formed annotation a comment line holds; nothing for any other
// line or a malformed annotation (reading the project reports that).
std::optional<Annotation> annotationOn(const lang::Line& line);

// The comment text (without ';') for an annotation; values are always quoted.
std::string formatAnnotation(const Annotation& annotation);

} // namespace rs::project
