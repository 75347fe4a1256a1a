// fleetmap robot add|set|list with a profile (SPEC 6, seed 004): laser height, radius, body
// height, stairs and ramps, through the real program; values land in robots' columns,
// bad values are refused with exit code 2 and change nothing.
#include <gtest/gtest.h>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

class RobotProfileCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    ensure_example_map("rp_map");
    pw_file_ = temp_path("rp.pw");
    write_file(pw_file_, "pw-rp-0123456789\n");
    for (const char* r : {"rp_r1", "rp_r2"}) run("fleetmap", std::string("robot remove ") + r);
  }
  static RunResult add(const std::string& name, const std::string& options) {
    return run("fleetmap", "robot add " + name + " --map rp_map --password-file " + temp_path("rp.pw") + " " + options);
  }
  // The robot's profile columns as text: "laser radius body stairs ramps" (NULL for defaults).
  static std::string columns(const std::string& name) {
    auto c = admin();
    mysqlpp::Query q = c->query(
        "SELECT CONCAT_WS(' ', COALESCE(laser_height, 'NULL'), COALESCE(radius, 'NULL'), COALESCE(body_height, 'NULL'),"
        " can_stairs, can_ramps) FROM robots WHERE db_user = '" + name + "' AND removed_at IS NULL");
    auto r = q.store();
    return r.empty() ? "none" : std::string(r[0][0]);
  }
  std::string pw_file_;
};

TEST_F(RobotProfileCommand, AddWithAProfileStoresItAndListShowsIt) {
  RunResult r = add("rp_r1", "--laser-height 0.38 --radius 0.25 --height 1.2 --stairs --no-ramps");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(columns("rp_r1"), "0.38 0.25 1.2 1 0");
  r = add("rp_r2", "");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(columns("rp_r2"), "NULL NULL NULL 0 1");  // every default

  r = run("fleetmap", "robot list");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("LASER"), std::string::npos) << r.out;
  auto line_of = [&](const std::string& name) {
    const size_t at = r.out.find(" " + name + " ");
    return at == std::string::npos ? std::string() : r.out.substr(at, r.out.find('\n', at) - at);
  };
  const std::string l1 = line_of("rp_r1"), l2 = line_of("rp_r2");
  EXPECT_NE(l1.find("0.38"), std::string::npos) << l1;
  EXPECT_NE(l1.find("0.25"), std::string::npos) << l1;
  EXPECT_NE(l1.find("1.2"), std::string::npos) << l1;
  EXPECT_NE(l1.find("yes"), std::string::npos) << l1;  // stairs
  EXPECT_NE(l2.find("default"), std::string::npos) << l2;

  // Removed and added again: the same row and id, the profile of the new add.
  const long long id = scalar("SELECT id FROM robots WHERE db_user = 'rp_r1'");
  ASSERT_EQ(run("fleetmap", "robot remove rp_r1").exit_code, 0);
  r = add("rp_r1", "--radius 0.5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(scalar("SELECT id FROM robots WHERE db_user = 'rp_r1'"), id);
  EXPECT_EQ(columns("rp_r1"), "NULL 0.5 NULL 0 1");
}

TEST_F(RobotProfileCommand, SetChangesOnlyWhatItIsGiven) {
  ASSERT_EQ(add("rp_r1", "--laser-height 0.3").exit_code, 0);
  RunResult r = run("fleetmap", "robot set rp_r1 --radius 0.4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("laser height 0.3"), std::string::npos) << r.out;
  EXPECT_EQ(columns("rp_r1"), "0.3 0.4 NULL 0 1");
  r = run("fleetmap", "robot set rp_r1 --laser-height 0.9 --height 1.5 --stairs --no-ramps");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(columns("rp_r1"), "0.9 0.4 1.5 1 0");
  r = run("fleetmap", "robot set rp_r1 --laser-height default --radius default --no-stairs --ramps");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(columns("rp_r1"), "NULL NULL 1.5 0 1");
  r = run("fleetmap", "robot set rp_r1 --laser-height 0");  // a laser on the floor is a height
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(columns("rp_r1"), "0 NULL 1.5 0 1");
}

TEST_F(RobotProfileCommand, BadValuesAreRefusedAndChangeNothing) {
  ASSERT_EQ(add("rp_r1", "--laser-height 0.3 --radius 0.3").exit_code, 0);
  struct Case {
    std::string options, message;
  };
  for (const Case& c : std::vector<Case>{
           {"--laser-height -0.1", "laser_height: expected a number in [0, 1000] m, got -0.1"},
           {"--laser-height 1000.5", "laser_height: expected a number in [0, 1000] m"},
           {"--laser-height abc", "--laser-height: expected a number of metres or 'default', got 'abc'"},
           {"--laser-height 0.3m", "--laser-height: expected a number of metres or 'default', got '0.3m'"},
           {"--laser-height nan", "laser_height: expected a number"},
           {"--laser-height inf", "laser_height: expected a number"},
           {"--radius 0", "radius: expected a number in (0, 100] m, got 0"},
           {"--radius 101", "radius: expected a number in (0, 100] m, got 101"},
           {"--height -1", "body_height: expected a number in (0, 1000] m, got -1"},
       }) {
    const RunResult r = run("fleetmap", "robot set rp_r1 " + c.options);
    EXPECT_EQ(r.exit_code, 2) << c.options << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.options << ": " << r.err;
    EXPECT_EQ(columns("rp_r1"), "0.3 0.3 NULL 0 1") << c.options;
  }
  // robot add refuses the value before it creates the account.
  RunResult r = add("rp_r2", "--radius -2");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(columns("rp_r2"), "none");
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM mysql.user WHERE user = 'rp_r2'"), 0);
}

TEST_F(RobotProfileCommand, CommandLineErrorsAndUnknownRobots) {
  ASSERT_EQ(add("rp_r1", "").exit_code, 0);
  RunResult r = run("fleetmap", "robot set rp_r1");  // nothing to change
  EXPECT_EQ(r.exit_code, 64) << r.err;
  EXPECT_NE(r.err.find("expected at least one of"), std::string::npos) << r.err;
  r = run("fleetmap", "robot set rp_r1 --stairs --no-stairs");
  EXPECT_EQ(r.exit_code, 64) << r.err;
  r = run("fleetmap", "robot set rp_r1 --ramps --no-ramps");
  EXPECT_EQ(r.exit_code, 64) << r.err;
  r = run("fleetmap", "robot set rp_r1 --laser-height");
  EXPECT_EQ(r.exit_code, 64) << r.err;
  r = run("fleetmap", "robot set rp_nobody --radius 0.3");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("no robot named 'rp_nobody'"), std::string::npos) << r.err;
  r = run("fleetmap", "robot set --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("--laser-height"), std::string::npos) << r.out;
  EXPECT_EQ(columns("rp_r1"), "NULL NULL NULL 0 1");
}

}  // namespace
}  // namespace fleetmap::test
