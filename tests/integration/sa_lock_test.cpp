// Robots lock only their own answers (SPEC 5.3: no robot can stall another), with plain
// SQL as robots written by others would send it:
//   * robot A holds a DELETE of its newest answer, or SELECT * FROM sa_mine FOR UPDATE, open
//     in a transaction; robot B's DELETE FROM sa_mine WHERE id <= N (N: B's newest answer,
//     after A's) completes at once, with A's name sorting before B's and right after it;
//   * the sentinel row that makes this so (sql/10_schema.sql, sa.sentinel) is one per
//     robot: made by robot_add and by the migration, gone with robot_remove, invisible
//     through sa_mine and v_answers, and no robot can delete it.
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kMap = "salock_map";
constexpr const char* kB = "salock_b";

// One answer for name, inserted as the server would; returns its id.
unsigned long long push_answer(mysqlpp::Connection& db, const std::string& name) {
  mysqlpp::Query q = db.query();
  q << "INSERT INTO sa (robot_id, db_user, request_id, op, params) SELECT id, db_user, NULL, 'OpAck', "
       "'{\"request_id\": 0}' FROM robots WHERE db_user = "
    << mysqlpp::quote << name;
  return q.execute().insert_id();
}

long long answers_of(const std::string& name) {
  return scalar("SELECT COUNT(*) FROM sa WHERE sentinel = 0 AND db_user = '" + name + "'");
}
long long sentinels_of(const std::string& name) {
  return scalar("SELECT COUNT(*) FROM sa WHERE sentinel = 1 AND db_user = '" + name + "'");
}

struct Case {
  const char* name;
  const char* a;          // A's account: sorts before kB, or right after it
  const char* isolation;  // of both robots' sessions
  bool a_deletes;         // A holds DELETE ... WHERE id = <its newest>; else SELECT ... FOR UPDATE
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class SaLock : public ::testing::TestWithParam<Case> {};

TEST_P(SaLock, RangeDeleteOfOneRobotWaitsOnNoOther) {
  const Case c = GetParam();
  ensure_example_map(kMap);
  const RemoveRobotsAtEnd cleanup{{c.a, kB}};
  const std::string a_pw = add_robot(c.a, kMap), b_pw = add_robot(kB, kMap);

  // Interleaved answers A1 B1 A2 B2: A's newest lies inside B's range id <= B2 on sa's
  // primary key, and A's rows sit right before or right after B's in a (db_user, id) index.
  auto db = admin();
  std::vector<unsigned long long> b_ids;
  push_answer(*db, c.a);
  b_ids.push_back(push_answer(*db, kB));
  const unsigned long long a_newest = push_answer(*db, c.a);
  b_ids.push_back(push_answer(*db, kB));
  const unsigned long long b_newest = b_ids.back();
  b_ids.push_back(push_answer(*db, kB));  // past N: B's range delete must leave it
  ASSERT_LT(a_newest, b_newest);

  SqlRobot a(c.a, a_pw), b(kB, b_pw);
  for (SqlRobot* r : {&a, &b}) {
    r->connection().query(std::string("SET SESSION TRANSACTION ISOLATION LEVEL ") + c.isolation).execute();
    r->connection().query("SET SESSION innodb_lock_wait_timeout = 3").execute();
  }
  a.connection().query("START TRANSACTION").execute();
  if (c.a_deletes) {
    EXPECT_EQ(a.connection().query("DELETE FROM sa_mine WHERE id = " + std::to_string(a_newest)).execute().rows(), 1u);
  } else {
    EXPECT_EQ(a.connection().query("SELECT * FROM sa_mine FOR UPDATE").store().size(), 2u);
  }

  const auto t0 = Clock::now();
  unsigned long long deleted = 0;
  int err = 0;
  std::string what;
  try {
    deleted = b.connection().query("DELETE FROM sa_mine WHERE id <= " + std::to_string(b_newest)).execute().rows();
  } catch (const mysqlpp::BadQuery& e) {
    err = e.errnum();
    what = e.what();
  }
  const double wait_s = std::chrono::duration<double>(Clock::now() - t0).count();
  std::cout << "[ info ] " << c.name << ": B's DELETE FROM sa_mine WHERE id <= N took " << wait_s << " s"
            << (err ? " and failed: " + what : std::string()) << "\n";
  EXPECT_NE(err, 1205) << "B waited on A's locks (lock wait timeout after " << wait_s << " s)";
  EXPECT_EQ(err, 0) << what;
  EXPECT_LT(wait_s, 1.0);
  EXPECT_EQ(deleted, 2u);

  a.connection().query("ROLLBACK").execute();
  // B's two rows up to N are gone, its third is there; A's rolled-back work left A's two.
  EXPECT_EQ(answers_of(kB), 1);
  EXPECT_EQ(scalar("SELECT MIN(id) FROM sa WHERE sentinel = 0 AND db_user = '" + std::string(kB) + "'"),
            static_cast<long long>(b_ids.back()));
  EXPECT_EQ(answers_of(c.a), 2);
  EXPECT_EQ(a.peek().size(), 2u);
  EXPECT_EQ(b.peek().size(), 1u);
  // Nobody's sentinel moved.
  EXPECT_EQ(sentinels_of(c.a), 1);
  EXPECT_EQ(sentinels_of(kB), 1);
}

INSTANTIATE_TEST_SUITE_P(
    Holds, SaLock,
    ::testing::Values(Case{"delete_a_before_b", "salock_a", "REPEATABLE READ", true},
                      Case{"delete_a_after_b", "salock_c", "REPEATABLE READ", true},
                      Case{"for_update_a_before_b", "salock_a", "REPEATABLE READ", false},
                      Case{"for_update_a_after_b", "salock_c", "REPEATABLE READ", false},
                      Case{"delete_a_before_b_rc", "salock_a", "READ COMMITTED", true},
                      Case{"delete_a_after_b_rc", "salock_c", "READ COMMITTED", true},
                      Case{"for_update_a_before_b_rc", "salock_a", "READ COMMITTED", false},
                      Case{"for_update_a_after_b_rc", "salock_c", "READ COMMITTED", false}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// One sentinel per robot, whatever the robot or an operator does.
TEST(SaLockSentinel, OnePerRobotInvisibleAndUndeletable) {
  ensure_example_map(kMap);
  const std::string name = "salock_s";
  const RemoveRobotsAtEnd cleanup{{name}};
  const std::string pw = add_robot(name, kMap);
  EXPECT_EQ(sentinels_of(name), 1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM sa s JOIN robots r ON r.id = s.robot_id AND r.db_user = s.db_user "
                   "WHERE s.sentinel = 1 AND s.db_user = '" + name + "'"),
            1)
      << "the sentinel carries the robot's id";

  auto db = admin();
  push_answer(*db, name);
  {
    SqlRobot r(name, pw);
    EXPECT_EQ(r.peek().size(), 1u) << "sa_mine shows the sentinel";
    EXPECT_EQ(r.connection().query("DELETE FROM sa_mine").execute().rows(), 1u);
    EXPECT_EQ(r.connection().query("DELETE FROM sa_mine WHERE op = 'End'").execute().rows(), 0u);
  }
  EXPECT_EQ(sentinels_of(name), 1) << "a robot deleted its sentinel";
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM v_answers WHERE db_user = '" + name + "'"), 0) << "v_answers shows it";

  // Removed: no sentinel (robot_remove empties the mailbox); added again: exactly one.
  ASSERT_EQ(run("fleetmap", "robot remove " + name).exit_code, 0);
  EXPECT_EQ(sentinels_of(name), 0);
  const std::string pw_file = temp_path(name + ".pw");
  for (int i = 0; i < 2; ++i) {
    RunResult r = run("fleetmap", "robot add " + name + " --map " + std::string(kMap) + " --password-file " + pw_file);
    EXPECT_EQ(r.exit_code != 0, i == 1) << r.err;  // the second: "a robot of that name exists"
    EXPECT_EQ(sentinels_of(name), 1) << "after add " << i + 1;
  }
}

// A database from before sentinels: the migration gives every robot not removed its one
// sentinel, and running it again adds none.
TEST(SaLockSentinel, MigrationAddsOneForEveryRobot) {
  ensure_example_map(kMap);
  const std::string name = "salock_m", gone = "salock_g";
  const RemoveRobotsAtEnd cleanup{{name}};
  add_robot(name, kMap);
  add_robot(gone, kMap);
  ASSERT_EQ(run("fleetmap", "robot remove " + gone).exit_code, 0);
  admin()->query("DELETE FROM sa WHERE sentinel = 1 AND db_user = '" + name + "'").execute();
  ASSERT_EQ(sentinels_of(name), 0);
  const std::string load = db_script() + " sql < " + source_path("sql/15_migrations.sql");
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(std::system(load.c_str()), 0);
    EXPECT_EQ(sentinels_of(name), 1) << "after run " << i + 1;
    EXPECT_EQ(sentinels_of(gone), 0) << "a removed robot got a sentinel";
  }
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM robots r WHERE r.removed_at IS NULL AND NOT EXISTS "
                   "(SELECT 1 FROM sa WHERE sa.db_user = r.db_user AND sa.sentinel = 1)"),
            0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM (SELECT db_user FROM sa WHERE sentinel = 1 GROUP BY db_user "
                   "HAVING COUNT(*) > 1) x"),
            0);
}

}  // namespace
}  // namespace fleetmap::test
