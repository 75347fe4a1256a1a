#include "server/web/http/tokens.h"

#include <stdexcept>

#include <openssl/crypto.h>
#include <openssl/rand.h>

namespace fleetmap::web {

std::string random_token() {
  unsigned char bits[32];
  if (RAND_bytes(bits, sizeof bits) != 1) throw std::runtime_error("no random bits from OpenSSL (RAND_bytes)");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 * sizeof bits);
  for (unsigned char b : bits) {
    out.push_back(kHex[b >> 4]);
    out.push_back(kHex[b & 15]);
  }
  return out;
}

bool tokens_equal(std::string_view a, std::string_view b) {
  if (a.size() != b.size() || a.empty()) return false;
  return CRYPTO_memcmp(a.data(), b.data(), a.size()) == 0;
}

}  // namespace fleetmap::web
