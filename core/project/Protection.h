// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Annotation.h"

#include <string>

// Password protection (manual Part 1, 4.1) as the file keeps it: no password,
// only what verifies that the file is as the holder of the password left it
// (ProjectSeal.h). Tamper evidence, not secrecy: the file stays readable text.
namespace rs::project {

// Who may change the Config Option networks of a protected project.
enum class OptionsAccess {
    Main, // only with the main password
    Free, // anybody, without a password
    Own,  // with their own password (the main one opens them too)
};

// What a user may do with a protected project once opened.
enum class Permission {
    ReadOnly,  // no password: nothing changes
    Configure, // the Config Option networks only
    Full,      // everything
};

// The ;@protected record (docs/file-format.md). Keys and signatures are
// lower-case hexadecimal; `lines` is base64, one byte per line of the file.
struct Protection {
    OptionsAccess options = OptionsAccess::Main;
    int opsLimit = 0;        // Argon2id passes
    long long memLimit = 0;  // Argon2id bytes
    std::string salt;        // the main password's
    std::string key;         // Ed25519 public key derived from the main password
    std::string optionsSalt; // OptionsAccess::Own only
    std::string optionsKey;  // OptionsAccess::Own only
    // Locates a change made outside Rungsmith: a digest byte per line of the
    // file. It is not signed, so it only says where, never whether.
    std::string lines;
    std::string signature;        // by the main key, over all but the options' states
    std::string optionsSignature; // over the options' states; none when they are free
    friend bool operator==(const Protection&, const Protection&) = default;
};

std::string toString(OptionsAccess access); // "main", "free", "own"

Annotation protectionRecord(const Protection& protection);

// The record without `lines` and the signatures: what the signatures cover of it.
Annotation signedPartOf(const Protection& protection);

struct ProtectionRecordError {
    std::string message;
};

// Reads a ;@protected record; throws ProtectionRecordError with what is wrong.
Protection readProtectionRecord(const Annotation& record);

} // namespace rs::project
