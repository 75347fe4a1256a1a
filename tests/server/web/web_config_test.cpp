// fleetmap-web's settings (server/web/http/web_config.h): defaults, values, refusals.
#include "server/web/http/web_config.h"

#include <gtest/gtest.h>

namespace fleetmap::web {
namespace {

TEST(WebConfig, Defaults) {
  const WebConfig c;
  EXPECT_EQ(c.listen, "127.0.0.1");
  EXPECT_EQ(c.http_port, 8080u);
  EXPECT_EQ(c.threads, 2);
  EXPECT_EQ(c.workers, 4);
  EXPECT_EQ(c.feed_period_ms, 50);
  EXPECT_EQ(c.session_idle_s, 1800);
  EXPECT_EQ(c.max_sessions, 256u);
  EXPECT_EQ(c.max_body_bytes, 65536u);
  EXPECT_FALSE(c.tls());
}

TEST(WebConfig, AppliesValues) {
  WebConfig c;
  c.apply({{"http_port", "0"}, {"workers", "8"}, {"max_body_bytes", "1024"}, {"tls_cert", "c.pem"}, {"tls_key", "k.pem"}});
  EXPECT_EQ(c.http_port, 0u);
  EXPECT_EQ(c.workers, 8);
  EXPECT_EQ(c.max_body_bytes, 1024u);
  EXPECT_TRUE(c.tls());
  EXPECT_NO_THROW(c.check());
}

TEST(WebConfig, RefusesBadValues) {
  auto refused = [](const std::string& k, const std::string& v) {
    WebConfig c;
    try {
      c.apply({{k, v}});
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(k), std::string::npos) << e.what();
      return true;
    }
    return false;
  };
  EXPECT_TRUE(refused("http_port", "65536"));
  EXPECT_TRUE(refused("http_port", "80x"));
  EXPECT_TRUE(refused("workers", "0"));
  EXPECT_TRUE(refused("workers", "1.5"));
  EXPECT_TRUE(refused("log_level", "loud"));
  EXPECT_TRUE(refused("no_such_key", "1"));
  WebConfig half;
  half.apply({{"tls_cert", "c.pem"}});
  EXPECT_THROW(half.check(), std::invalid_argument);
}

}  // namespace
}  // namespace fleetmap::web
