// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Protection.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// The keys of password protection. A password never leaves this file: it is
// stretched with Argon2id and the salt of the record into the seed of an
// Ed25519 key pair, whose public half the record keeps (libsodium both).
namespace rs::project {

class SigningKey {
public:
    // The pair whose seed is Argon2id(password, salt) at the given cost.
    static SigningKey derive(std::string_view password, const std::string& saltHex, int opsLimit,
                             long long memLimit);
    SigningKey(const SigningKey& other);
    SigningKey& operator=(const SigningKey& other);
    ~SigningKey(); // wipes the secret

    const std::string& publicKey() const { return m_publicKey; } // hexadecimal
    std::string sign(std::string_view message) const;            // hexadecimal

private:
    SigningKey() = default;
    std::array<unsigned char, 64> m_secret{};
    std::string m_publicKey;
};

// Whether `signatureHex` is `publicKeyHex`'s signature of the message; false
// for anything malformed.
bool verifySignature(std::string_view message, const std::string& signatureHex,
                     const std::string& publicKeyHex);

// The secret keys a session holds: every one a password has opened, so that
// undoing a change of password still finds the key of the record it restores.
class Keyring {
public:
    void add(const SigningKey& key);
    void add(const Keyring& other);
    // The secret key of a public one, or nothing.
    const SigningKey* find(const std::string& publicKeyHex) const;
    bool empty() const { return m_keys.empty(); }

private:
    std::vector<SigningKey> m_keys;
};

struct NewProtection {
    Protection record; // without lines and signatures: sealing gives them
    Keyring keys;
};

// Fresh salts and keys. `optionsPassword` counts only for OptionsAccess::Own.
NewProtection protectWith(std::string_view mainPassword, OptionsAccess options,
                          std::string_view optionsPassword);

// The keys a password gives for a permission, as the manual's opening dialog
// asks (4.1.1): full permission takes the main password; permission to
// configure takes the options' own password or the main one, or none when the
// options are free; read only takes none. Nothing when the password does not
// open the project so; the answer never says which password would.
std::optional<Keyring> unlock(const Protection& protection, Permission permission,
                              std::string_view password);

// Seconds the n-th wrong password in a row makes the user wait before the
// next try: 1, 2, 4 ... up to 30.
int waitAfterRefusal(int refusals);

// Whether a permission needs a password at all.
bool needsPassword(const Protection& protection, Permission permission);

} // namespace rs::project
