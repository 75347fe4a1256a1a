#pragma once
// The session cookie (SPEC 4): reading it from a Cookie header, and the Set-Cookie
// that gives or clears it.
#include <optional>
#include <string>
#include <string_view>

namespace fleetmap::web {

inline constexpr const char* kSessionCookie = "fleetmap_session";

// The value of cookie `name` in a Cookie header ("a=1; fleetmap_session=ab12"), or
// nullopt. Names match exactly; surrounding blanks and double quotes are dropped.
std::optional<std::string> cookie_value(std::string_view header, std::string_view name);

// HttpOnly (no script reads it), SameSite=Strict (no other site's page sends it),
// Path=/, Secure when the connection is TLS.
std::string session_cookie(const std::string& id, bool secure);
// The same cookie, expired: what logout sends.
std::string cleared_session_cookie(bool secure);

}  // namespace fleetmap::web
