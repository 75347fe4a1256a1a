// The session cookie (server/web/http/cookies.h): finding it among others in a Cookie
// header, and the flags it is given (SPEC 4).
#include "server/web/http/cookies.h"

#include <gtest/gtest.h>

namespace fleetmap::web {
namespace {

TEST(Cookies, FindsTheSessionAmongOthers) {
  EXPECT_EQ(cookie_value("a=1; fleetmap_session=ab12; b=2", kSessionCookie), "ab12");
  EXPECT_EQ(cookie_value("fleetmap_session=ab12", kSessionCookie), "ab12");
  EXPECT_EQ(cookie_value("  fleetmap_session = \"ab12\" ;x=y", kSessionCookie), "ab12");
}

TEST(Cookies, NamesMatchExactly) {
  // A cookie whose name merely contains or extends the session's is not it.
  EXPECT_EQ(cookie_value("xfleetmap_session=evil; fleetmap_session2=evil", kSessionCookie), std::nullopt);
  EXPECT_EQ(cookie_value("xfleetmap_session=evil; fleetmap_session=good", kSessionCookie), "good");
  EXPECT_EQ(cookie_value("", kSessionCookie), std::nullopt);
  EXPECT_EQ(cookie_value("fleetmap_session", kSessionCookie), std::nullopt);
  EXPECT_EQ(cookie_value("fleetmap_session=", kSessionCookie), "");
}

TEST(Cookies, SessionCookieFlags) {
  const std::string plain = session_cookie("abc", false);
  EXPECT_EQ(plain.rfind("fleetmap_session=abc;", 0), 0u) << plain;
  EXPECT_NE(plain.find("HttpOnly"), std::string::npos);
  EXPECT_NE(plain.find("SameSite=Strict"), std::string::npos);
  EXPECT_NE(plain.find("Path=/"), std::string::npos);
  EXPECT_EQ(plain.find("Secure"), std::string::npos) << "Secure over plain HTTP would never be sent back";
  EXPECT_NE(session_cookie("abc", true).find("; Secure"), std::string::npos);
  EXPECT_NE(cleared_session_cookie(false).find("Max-Age=0"), std::string::npos);
}

}  // namespace
}  // namespace fleetmap::web
