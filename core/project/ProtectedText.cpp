// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProtectedText.h"

#include "ProjectFile.h"

#include <sodium.h>

#include <regex>
#include <vector>

namespace rs::project {

namespace {

// A text as lines, each without its '\n'; a text ending in '\n' has no empty last line.
std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) {
            lines.push_back(text.substr(start));
            break;
        }
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

std::string_view trimmedLeft(std::string_view line) {
    const std::size_t first = line.find_first_not_of(" \t");
    return first == std::string_view::npos ? std::string_view{} : line.substr(first);
}

// The record's index among the lines, or -1; -2 when there are several.
int recordIndex(const std::vector<std::string_view>& lines) {
    int found = -1;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string_view trimmed = trimmedLeft(lines[i]);
        if (trimmed.substr(0, 11) == ";@protected" &&
            (trimmed.size() == 11 || trimmed[11] == ' ' || trimmed[11] == '\t' ||
             trimmed[11] == '\r')) {
            if (found >= 0)
                return -2;
            found = static_cast<int>(i);
        }
    }
    return found;
}

struct Masked {
    std::string text;                     // every option's state masked
    std::string states;                   // "LINE STATE\n" for each option, lines from 1
    std::vector<std::size_t> optionLines; // indices of the options' lines, both of each
};

// The option value of a ;@network record line, or nothing.
std::optional<Annotation> optionRecord(std::string_view line) {
    const std::string_view trimmed = trimmedLeft(line);
    if (trimmed.substr(0, 9) != ";@network")
        return std::nullopt;
    try {
        std::optional<Annotation> record = parseAnnotation(trimmed.substr(1));
        if (record && (record->value("option") == "on" || record->value("option") == "off"))
            return record;
    } catch (const AnnotationError&) {
    }
    return std::nullopt;
}

Masked mask(const std::vector<std::string_view>& lines, bool endsWithNewline) {
    static const std::regex statement(R"(^[ \t]*([SR])\([ \t]*[^()\s;]+[ \t]*\)[ \t]*(;.*)?\r?$)");
    Masked masked;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        std::string line(lines[i]);
        std::optional<Annotation> record = optionRecord(line);
        std::smatch match;
        const std::string next = i + 1 < lines.size() ? std::string(lines[i + 1]) : std::string();
        if (record && i + 1 < lines.size() && std::regex_match(next, match, statement)) {
            const std::string state = record->value("option");
            masked.states += std::to_string(i + 1) + ' ' + state + ' ' + match.str(1) + '\n';
            masked.optionLines.push_back(i);
            masked.optionLines.push_back(i + 1);
            // Only the value goes: any other change of the line stays in sight.
            const std::string written = "option=\"" + state + "\"";
            const std::size_t at = line.rfind(written);
            if (at != std::string::npos)
                line.replace(at, written.size(), "option=\"?\"");
            std::string maskedStatement = next;
            maskedStatement[static_cast<std::size_t>(match.position(1))] = '?';
            masked.text += line + '\n' + maskedStatement;
            ++i;
        } else {
            masked.text += line;
        }
        if (i + 1 < lines.size() || endsWithNewline)
            masked.text += '\n';
    }
    return masked;
}

unsigned char lineDigest(std::string_view line) {
    std::array<unsigned char, crypto_generichash_BYTES_MIN> hash{};
    crypto_generichash(hash.data(), hash.size(),
                       reinterpret_cast<const unsigned char*>(line.data()), line.size(), nullptr,
                       0);
    return hash[0];
}

std::string base64(const std::vector<unsigned char>& bytes) {
    std::string text(sodium_base64_encoded_len(bytes.size(), sodium_base64_VARIANT_ORIGINAL), '\0');
    sodium_bin2base64(text.data(), text.size(), bytes.data(), bytes.size(),
                      sodium_base64_VARIANT_ORIGINAL);
    text.resize(text.find('\0'));
    return text;
}

std::vector<unsigned char> readDigests(const std::string& text) {
    std::vector<unsigned char> bytes(text.size());
    std::size_t length = 0;
    if (sodium_base642bin(bytes.data(), bytes.size(), text.data(), text.size(), nullptr, &length,
                          nullptr, sodium_base64_VARIANT_ORIGINAL) != 0)
        return {};
    bytes.resize(length);
    return bytes;
}

// The digest of each line of the file; the record's own line counts as the
// bare kind, so that lines removed or added above it are found where they were.
std::vector<unsigned char> fileDigests(const std::vector<std::string_view>& lines,
                                       std::size_t record) {
    std::vector<unsigned char> bytes;
    bytes.reserve(lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i)
        bytes.push_back(lineDigest(i == record ? std::string_view(";@protected") : lines[i]));
    return bytes;
}

// The protected content: the lines without the record's.
struct Content {
    std::vector<std::string_view> lines;
    bool endsWithNewline = false;
    std::size_t record = 0; // the record's index in the file
    std::string recordLine;
};

Content contentOf(std::string_view text, const std::vector<std::string_view>& lines, int record) {
    Content content;
    content.record = static_cast<std::size_t>(record);
    content.recordLine = std::string(lines[content.record]);
    content.lines = lines;
    content.lines.erase(content.lines.begin() + record);
    content.endsWithNewline = text.ends_with('\n');
    return content;
}

std::string signedMessage(const Protection& protection, const std::string& body) {
    return ';' + formatAnnotation(signedPartOf(protection)) + '\n' + body;
}

lang::Diagnostic errorAt(std::size_t line, std::string message) {
    return {lang::Severity::Error, static_cast<int>(line) + 1, 1, std::move(message)};
}

} // namespace

std::string withoutOptionStates(std::string_view text) {
    return mask(splitLines(text), text.ends_with('\n')).text;
}

bool changesOnlyOptions(const Project& before, const Project& after) {
    return withoutOptionStates(writeProject(before)) == withoutOptionStates(writeProject(after));
}

std::string sealProjectText(std::string_view text, const Keyring& keys) {
    const std::vector<std::string_view> lines = splitLines(text);
    const int index = recordIndex(lines);
    if (index < 0)
        return std::string(text);
    const Content content = contentOf(text, lines, index);
    std::optional<Annotation> annotation =
        parseAnnotation(trimmedLeft(content.recordLine).substr(1));
    Protection protection = readProtectionRecord(*annotation);
    const Masked masked = mask(content.lines, content.endsWithNewline);

    std::vector<unsigned char> digests = fileDigests(lines, content.record);
    if (const SigningKey* main = keys.find(protection.key)) {
        protection.signature = main->sign(signedMessage(protection, masked.text));
    } else {
        // Only the options may have changed: the other lines keep the bytes the
        // main key's holder left, so that a change of theirs is still found.
        std::vector<unsigned char> kept = readDigests(protection.lines);
        if (kept.size() == digests.size())
            for (std::size_t option : masked.optionLines) {
                const std::size_t line = option + (option >= content.record ? 1 : 0);
                kept[line] = digests[line];
            }
        digests = std::move(kept);
    }
    protection.lines = base64(digests);
    if (protection.options != OptionsAccess::Free) {
        const SigningKey* signer = keys.find(protection.key);
        if (!signer && protection.options == OptionsAccess::Own)
            signer = keys.find(protection.optionsKey);
        if (signer)
            protection.optionsSignature = signer->sign(signedMessage(protection, masked.states));
    }

    std::string sealed;
    sealed.reserve(text.size() + 128);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (i == content.record)
            sealed += ';' + formatAnnotation(protectionRecord(protection));
        else
            sealed += lines[i];
        if (i + 1 < lines.size() || content.endsWithNewline)
            sealed += '\n';
    }
    return sealed;
}

std::optional<lang::Diagnostic> verifyProjectText(std::string_view text) {
    // Most projects are not protected: no record, nothing to split.
    if (text.find(";@protected") == std::string_view::npos)
        return std::nullopt;
    const std::vector<std::string_view> lines = splitLines(text);
    const int index = recordIndex(lines);
    if (index == -1)
        return std::nullopt;
    if (index == -2)
        return errorAt(0, "more than one @protected record; a protected project has one");
    const Content content = contentOf(text, lines, index);
    Protection protection;
    try {
        std::optional<Annotation> annotation =
            parseAnnotation(trimmedLeft(content.recordLine).substr(1));
        protection = readProtectionRecord(*annotation);
    } catch (const AnnotationError& problem) {
        return errorAt(content.record, problem.message);
    } catch (const ProtectionRecordError& problem) {
        return errorAt(content.record, problem.message);
    }

    const Masked masked = mask(content.lines, content.endsWithNewline);
    const bool mainHolds = verifySignature(signedMessage(protection, masked.text),
                                           protection.signature, protection.key);
    bool optionsHold = true;
    if (protection.options != OptionsAccess::Free) {
        const std::string message = signedMessage(protection, masked.states);
        optionsHold =
            verifySignature(message, protection.optionsSignature, protection.key) ||
            (protection.options == OptionsAccess::Own &&
             verifySignature(message, protection.optionsSignature, protection.optionsKey));
    }
    if (mainHolds && optionsHold)
        return std::nullopt;

    const std::vector<unsigned char> stored = readDigests(protection.lines);
    const std::vector<unsigned char> digests = fileDigests(lines, content.record);
    for (std::size_t i = 0; i < digests.size() || i < stored.size(); ++i) {
        if (i < digests.size() && i < stored.size() && digests[i] == stored[i])
            continue;
        // Lines removed at the end: the change touched the last line left.
        return errorAt(std::min(i, digests.size() - 1),
                       "changed outside Rungsmith after the project was password protected: "
                       "the password holder's signature does not cover this line");
    }
    return errorAt(content.record, "the @protected record was changed outside Rungsmith, or the "
                                   "project was never sealed with it: its signature does not "
                                   "match the project");
}

} // namespace rs::project
