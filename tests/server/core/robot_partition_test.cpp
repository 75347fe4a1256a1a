// RobotPartition (server/core/robot_partition.h): "I/N" parsed, every robot owned by
// exactly one of the N shares, and malformed or out-of-range shares refused by name.
#include "server/core/robot_partition.h"

#include <stdexcept>

#include <gtest/gtest.h>

#include "server/core/server_config.h"

namespace fleetmap {
namespace {

std::string refusal(const std::string& text) {
  try {
    parse_robot_partition(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(RobotPartition, TheDefaultTakesEveryRobot) {
  const RobotPartition p;
  EXPECT_TRUE(p.all());
  for (unsigned id : {0u, 1u, 2u, 7u, 4000000000u}) EXPECT_TRUE(p.owns(id)) << id;
}

TEST(RobotPartition, ParsesIndexAndCount) {
  const RobotPartition p = parse_robot_partition("2/3");
  EXPECT_EQ(p.index, 2u);
  EXPECT_EQ(p.count, 3u);
  EXPECT_FALSE(p.all());
  EXPECT_EQ(p.text(), "2/3");
  EXPECT_TRUE(p.owns(5));
  EXPECT_TRUE(p.owns(8));
  EXPECT_FALSE(p.owns(6));
  EXPECT_FALSE(p.owns(7));
  EXPECT_TRUE(parse_robot_partition("0/1").all());
}

TEST(RobotPartition, EveryRobotHasExactlyOneOwnerAmongTheShares) {
  for (unsigned n : {1u, 2u, 3u, 7u}) {
    for (unsigned id = 1; id <= 50; ++id) {
      unsigned owners = 0;
      for (unsigned i = 0; i < n; ++i) owners += parse_robot_partition(std::to_string(i) + "/" + std::to_string(n)).owns(id);
      EXPECT_EQ(owners, 1u) << "robot " << id << " among " << n << " shares";
    }
  }
}

TEST(RobotPartition, RefusesWhatIsNoShare) {
  for (const char* bad : {"", "1", "/", "1/", "/2", "2/2", "3/2", "0/0", "-1/2", "1/-2", "a/b", "1/2/3", " 1/2",
                          "1 /2", "0x1/2", "1.0/2", "0/1025", "0/99999", "+1/2"}) {
    const std::string why = refusal(bad);
    EXPECT_NE(why, "") << "accepted '" << bad << "'";
    EXPECT_NE(why.find("partition: expected I/N"), std::string::npos) << why;
    EXPECT_NE(why.find(std::string("'") + bad + "'"), std::string::npos) << why;
  }
  EXPECT_NE(refusal("2/2").find("I must be below N"), std::string::npos);
  EXPECT_EQ(parse_robot_partition("1023/1024").index, 1023u);
}

TEST(RobotPartition, IsAServerSetting) {
  ServerConfig c;
  c.apply({{"partition", "1/2"}});
  EXPECT_EQ(c.partition.index, 1u);
  EXPECT_EQ(c.partition.count, 2u);
  EXPECT_THROW(c.apply({{"partition", "2/2"}}), std::invalid_argument);
  EXPECT_EQ(c.partition.text(), "1/2");  // a refused value leaves the setting as it was
}

}  // namespace
}  // namespace fleetmap
