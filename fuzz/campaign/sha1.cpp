// SHA-1 in hex (sha1.hpp) through OpenSSL's libcrypto (Debian libssl-dev). Why libcrypto rather than
// nettle: it is the most widely deployed and security-maintained digest library in Debian, CMake finds it
// with its own FindOpenSSL module (OpenSSL::Crypto, no pkg-config), and EVP_Digest is one call.
#include "sha1.hpp"

#include <openssl/evp.h>

#include <fmt/format.h>

namespace ricochet::fuzz {

std::string sha1_hex(std::string_view data) {
    unsigned char md[EVP_MAX_MD_SIZE];
    unsigned int len = 0;
    // Degenerate: libcrypto failed (out of memory); no digest to name the input by.
    if (EVP_Digest(data.data(), data.size(), md, &len, EVP_sha1(), nullptr) != 1) return "unknown";
    std::string hex;
    hex.reserve(2 * len);
    for (unsigned int i = 0; i < len; ++i) hex += fmt::format("{:02x}", md[i]);
    return hex;
}

}  // namespace ricochet::fuzz
