// Session ids and CSRF tokens (server/web/http/tokens.h): 256 bits as hex, never repeated,
// compared exactly.
#include "server/web/http/tokens.h"

#include <set>

#include <gtest/gtest.h>

namespace fleetmap::web {
namespace {

TEST(Tokens, Are256BitsOfHex) {
  const std::string t = random_token();
  ASSERT_EQ(t.size(), 64u);
  EXPECT_EQ(t.find_first_not_of("0123456789abcdef"), std::string::npos) << t;
}

TEST(Tokens, DoNotRepeat) {
  std::set<std::string> seen;
  for (int i = 0; i < 1000; ++i) EXPECT_TRUE(seen.insert(random_token()).second);
}

TEST(Tokens, CompareExactly) {
  const std::string t = random_token();
  EXPECT_TRUE(tokens_equal(t, t));
  std::string other = t;
  other.back() = other.back() == 'a' ? 'b' : 'a';
  EXPECT_FALSE(tokens_equal(t, other));
  EXPECT_FALSE(tokens_equal(t, t.substr(0, 63)));  // a prefix is not the token
  EXPECT_FALSE(tokens_equal(t, t + "0"));
  EXPECT_FALSE(tokens_equal("", ""));  // an empty header never matches
}

}  // namespace
}  // namespace fleetmap::web
