// SPDX-License-Identifier: GPL-3.0-or-later
#include "Protection.h"

#include "ProtectionLimits.h"

#include <charconv>

namespace rs::project {

namespace {

void requireHex(const std::string& value, std::size_t bytes, const char* what) {
    if (value.size() != 2 * bytes ||
        value.find_first_not_of("0123456789abcdef") != std::string::npos)
        throw ProtectionRecordError{std::string("@protected ") + what + " must be " +
                                    std::to_string(2 * bytes) + " lower-case hexadecimal digits"};
}

template <typename Number> Number readNumber(const std::string& text, const char* what) {
    Number value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        throw ProtectionRecordError{std::string("@protected ") + what + " must be a number, not '" +
                                    text + "'"};
    return value;
}

} // namespace

std::string toString(OptionsAccess access) {
    switch (access) {
    case OptionsAccess::Main:
        return "main";
    case OptionsAccess::Free:
        return "free";
    case OptionsAccess::Own:
        return "own";
    }
    return "main";
}

Annotation signedPartOf(const Protection& protection) {
    Annotation record{"protected", {}, {}};
    record.attributes = {{"options", toString(protection.options)},
                         {"kdf", "argon2id:" + std::to_string(protection.opsLimit) + ":" +
                                     std::to_string(protection.memLimit)},
                         {"salt", protection.salt},
                         {"key", protection.key}};
    if (protection.options == OptionsAccess::Own) {
        record.attributes.emplace_back("options_salt", protection.optionsSalt);
        record.attributes.emplace_back("options_key", protection.optionsKey);
    }
    return record;
}

Annotation protectionRecord(const Protection& protection) {
    Annotation record = signedPartOf(protection);
    record.attributes.emplace_back("lines", protection.lines);
    record.attributes.emplace_back("signature", protection.signature);
    if (protection.options != OptionsAccess::Free)
        record.attributes.emplace_back("options_signature", protection.optionsSignature);
    return record;
}

Protection readProtectionRecord(const Annotation& record) {
    Protection protection;
    const std::string options = record.value("options");
    if (options == "main")
        protection.options = OptionsAccess::Main;
    else if (options == "free")
        protection.options = OptionsAccess::Free;
    else if (options == "own")
        protection.options = OptionsAccess::Own;
    else
        throw ProtectionRecordError{"@protected options must be main, free or own, not '" +
                                    options + "'"};

    const std::string kdf = record.value("kdf");
    const auto first = kdf.find(':');
    const auto second = kdf.find(':', first == std::string::npos ? first : first + 1);
    if (kdf.substr(0, first) != "argon2id" || second == std::string::npos)
        throw ProtectionRecordError{"@protected kdf must be argon2id:PASSES:BYTES, not '" + kdf +
                                    "'"};
    protection.opsLimit = readNumber<int>(kdf.substr(first + 1, second - first - 1), "kdf passes");
    protection.memLimit = readNumber<long long>(kdf.substr(second + 1), "kdf bytes");
    // A file states the cost of its own check; an absurd one would hang the reader.
    if (protection.opsLimit < kMinPasses || protection.opsLimit > kMaxPasses ||
        protection.memLimit < kMinMemoryBytes || protection.memLimit > kMaxMemoryBytes)
        throw ProtectionRecordError{
            "@protected kdf asks for " + std::to_string(protection.opsLimit) + " passes over " +
            std::to_string(protection.memLimit) + " bytes; Rungsmith takes " +
            std::to_string(kMinPasses) + "-" + std::to_string(kMaxPasses) + " passes over " +
            std::to_string(kMinMemoryBytes) + "-" + std::to_string(kMaxMemoryBytes) + " bytes"};

    protection.salt = record.value("salt");
    requireHex(protection.salt, kSaltBytes, "salt");
    protection.key = record.value("key");
    requireHex(protection.key, kPublicKeyBytes, "key");
    if (protection.options == OptionsAccess::Own) {
        protection.optionsSalt = record.value("options_salt");
        requireHex(protection.optionsSalt, kSaltBytes, "options_salt");
        protection.optionsKey = record.value("options_key");
        requireHex(protection.optionsKey, kPublicKeyBytes, "options_key");
    }
    protection.lines = record.value("lines");
    // Empty until sealed (ProtectedText.h); a record never sealed verifies as changed.
    protection.signature = record.value("signature");
    if (!protection.signature.empty())
        requireHex(protection.signature, kSignatureBytes, "signature");
    if (protection.options != OptionsAccess::Free) {
        protection.optionsSignature = record.value("options_signature");
        if (!protection.optionsSignature.empty())
            requireHex(protection.optionsSignature, kSignatureBytes, "options_signature");
    }
    return protection;
}

} // namespace rs::project
