#pragma once
// Session ids and CSRF tokens (SPEC 4): 256 random bits from OpenSSL's CSPRNG, as hex;
// compared in constant time so that a guess learns nothing from the timing.
#include <string>
#include <string_view>

namespace fleetmap::web {

// 64 lowercase hex digits; throws std::runtime_error when the CSPRNG fails.
std::string random_token();

// True when a and b are equal; the time taken depends on the lengths only.
bool tokens_equal(std::string_view a, std::string_view b);

}  // namespace fleetmap::web
