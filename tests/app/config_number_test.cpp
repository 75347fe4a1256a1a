// Numbers of the config file's sections (app/config_number.h): the whole value or a
// refusal naming the section, the key, the range and the value.
#include "app/config_number.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fleetmap {
namespace {

std::string refusal_whole(const std::string& v, double least, double most) {
  try {
    config_whole("[web]", "threads", v, least, most);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ConfigNumber, TakesTheWholeValueOnly) {
  EXPECT_DOUBLE_EQ(config_number("[server]", "k", "0.25", false), 0.25);
  EXPECT_DOUBLE_EQ(config_number("[server]", "k", "0", true), 0.0);
  EXPECT_THROW(config_number("[server]", "k", "0", false), std::invalid_argument);
  EXPECT_THROW(config_number("[server]", "k", "20ms", false), std::invalid_argument);
  EXPECT_THROW(config_number("[server]", "k", "", true), std::invalid_argument);
  EXPECT_THROW(config_number("[server]", "k", "-1", true), std::invalid_argument);
  EXPECT_THROW(config_number("[server]", "k", "inf", true), std::invalid_argument);
  EXPECT_THROW(config_number("[server]", "k", "nan", true), std::invalid_argument);
}

TEST(ConfigNumber, RefusesAPartOfANumberWithItsRange) {
  EXPECT_EQ(config_whole("[web]", "threads", "64", 1, 64), 64u);
  EXPECT_EQ(config_whole("[web]", "http_port", "0", 0, 65535), 0u);
  EXPECT_EQ(refusal_whole("1.5", 1, 1e15), "[web] threads: expected a positive whole number, got '1.5'");
  EXPECT_EQ(refusal_whole("65", 1, 64), "[web] threads: expected a positive whole number up to 64, got '65'");
  EXPECT_EQ(refusal_whole("4", 5, 60000), "[web] threads: expected a whole number from 5 to 60000, got '4'");
  EXPECT_EQ(refusal_whole("1e3x", 1, 64), "[web] threads: expected a positive whole number up to 64, got '1e3x'");
}

}  // namespace
}  // namespace fleetmap
