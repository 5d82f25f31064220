// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProtectionKeys.h"

#include "ProtectionLimits.h"

#include <sodium.h>

#include <algorithm>
#include <stdexcept>

namespace rs::project {

static_assert(kSaltBytes == crypto_pwhash_SALTBYTES);
static_assert(kPublicKeyBytes == crypto_sign_PUBLICKEYBYTES);
static_assert(kSignatureBytes == crypto_sign_BYTES);
static_assert(crypto_sign_SECRETKEYBYTES == 64);

namespace {

void initialise() {
    static const bool ready = sodium_init() >= 0;
    if (!ready)
        throw std::runtime_error("libsodium cannot start");
}

std::string toHex(const unsigned char* bytes, std::size_t size) {
    std::string text(2 * size + 1, '\0');
    sodium_bin2hex(text.data(), text.size(), bytes, size);
    text.pop_back();
    return text;
}

template <std::size_t N>
std::optional<std::array<unsigned char, N>> fromHex(const std::string& text) {
    std::array<unsigned char, N> bytes{};
    std::size_t length = 0;
    if (text.size() != 2 * N ||
        sodium_hex2bin(bytes.data(), N, text.data(), text.size(), nullptr, &length, nullptr) != 0 ||
        length != N)
        return std::nullopt;
    return bytes;
}

std::string freshSalt() {
    std::array<unsigned char, kSaltBytes> salt{};
    randombytes_buf(salt.data(), salt.size());
    return toHex(salt.data(), salt.size());
}

} // namespace

SigningKey SigningKey::derive(std::string_view password, const std::string& saltHex, int opsLimit,
                              long long memLimit) {
    initialise();
    const auto salt = fromHex<kSaltBytes>(saltHex);
    if (!salt)
        throw std::invalid_argument("malformed salt");
    std::array<unsigned char, crypto_sign_SEEDBYTES> seed{};
    if (crypto_pwhash(seed.data(), seed.size(), password.data(), password.size(), salt->data(),
                      static_cast<unsigned long long>(opsLimit), static_cast<std::size_t>(memLimit),
                      crypto_pwhash_ALG_ARGON2ID13) != 0)
        throw std::runtime_error("not enough memory to check the password");
    SigningKey key;
    std::array<unsigned char, kPublicKeyBytes> publicKey{};
    crypto_sign_seed_keypair(publicKey.data(), key.m_secret.data(), seed.data());
    sodium_memzero(seed.data(), seed.size());
    key.m_publicKey = toHex(publicKey.data(), publicKey.size());
    return key;
}

SigningKey::SigningKey(const SigningKey& other)
    : m_secret(other.m_secret), m_publicKey(other.m_publicKey) {}

SigningKey& SigningKey::operator=(const SigningKey& other) {
    m_secret = other.m_secret;
    m_publicKey = other.m_publicKey;
    return *this;
}

SigningKey::~SigningKey() {
    sodium_memzero(m_secret.data(), m_secret.size());
}

std::string SigningKey::sign(std::string_view message) const {
    std::array<unsigned char, kSignatureBytes> signature{};
    crypto_sign_detached(signature.data(), nullptr,
                         reinterpret_cast<const unsigned char*>(message.data()), message.size(),
                         m_secret.data());
    return toHex(signature.data(), signature.size());
}

bool verifySignature(std::string_view message, const std::string& signatureHex,
                     const std::string& publicKeyHex) {
    initialise();
    const auto signature = fromHex<kSignatureBytes>(signatureHex);
    const auto publicKey = fromHex<kPublicKeyBytes>(publicKeyHex);
    return signature && publicKey &&
           crypto_sign_verify_detached(signature->data(),
                                       reinterpret_cast<const unsigned char*>(message.data()),
                                       message.size(), publicKey->data()) == 0;
}

void Keyring::add(const SigningKey& key) {
    if (!find(key.publicKey()))
        m_keys.push_back(key);
}

void Keyring::add(const Keyring& other) {
    for (const SigningKey& key : other.m_keys)
        add(key);
}

const SigningKey* Keyring::find(const std::string& publicKeyHex) const {
    for (const SigningKey& key : m_keys)
        if (key.publicKey() == publicKeyHex)
            return &key;
    return nullptr;
}

NewProtection protectWith(std::string_view mainPassword, OptionsAccess options,
                          std::string_view optionsPassword) {
    initialise();
    NewProtection result;
    Protection& record = result.record;
    record.options = options;
    record.opsLimit = crypto_pwhash_OPSLIMIT_INTERACTIVE;
    record.memLimit = crypto_pwhash_MEMLIMIT_INTERACTIVE;
    record.salt = freshSalt();
    const SigningKey main =
        SigningKey::derive(mainPassword, record.salt, record.opsLimit, record.memLimit);
    record.key = main.publicKey();
    result.keys.add(main);
    if (options == OptionsAccess::Own) {
        record.optionsSalt = freshSalt();
        const SigningKey own = SigningKey::derive(optionsPassword, record.optionsSalt,
                                                  record.opsLimit, record.memLimit);
        record.optionsKey = own.publicKey();
        result.keys.add(own);
    }
    return result;
}

int waitAfterRefusal(int refusals) {
    return refusals <= 0 ? 0 : std::min(30, 1 << std::min(refusals - 1, 5));
}

bool needsPassword(const Protection& protection, Permission permission) {
    return permission == Permission::Full ||
           (permission == Permission::Configure && protection.options != OptionsAccess::Free);
}

std::optional<Keyring> unlock(const Protection& protection, Permission permission,
                              std::string_view password) {
    Keyring keys;
    if (!needsPassword(protection, permission))
        return keys;
    const SigningKey main =
        SigningKey::derive(password, protection.salt, protection.opsLimit, protection.memLimit);
    if (main.publicKey() == protection.key) {
        keys.add(main);
        return keys;
    }
    if (permission == Permission::Configure && protection.options == OptionsAccess::Own) {
        const SigningKey own = SigningKey::derive(password, protection.optionsSalt,
                                                  protection.opsLimit, protection.memLimit);
        if (own.publicKey() == protection.optionsKey) {
            keys.add(own);
            return keys;
        }
    }
    return std::nullopt;
}

} // namespace rs::project
