// A robot's account can do only what SPEC 4 and 5.1 allow: INSERT into rr, and SELECT and
// DELETE of its own answers through sa_mine. Everything else is tried here, as a robot
// over TCP with plain SQL, and each attempt must fail with an SQL error or be answered
// with an Error that changed nothing (checked as administrator).
#include <algorithm>
#include <cctype>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

using nlohmann::json;
using namespace std::chrono_literals;

constexpr const char* kMap = "sec_map";

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool is_query(const std::string& sql) {
  const std::string u = upper(sql.substr(0, 8));
  return u.rfind("SELECT", 0) == 0 || u.rfind("SHOW", 0) == 0 || u.rfind("EXPLAIN", 0) == 0 ||
         u.rfind("CALL", 0) == 0 || u.rfind("WITH", 0) == 0;
}

// Runs sql; 0 when it ran, else the server's error number (or 1 for a client-side error).
unsigned sql_error(mysqlpp::Connection& c, const std::string& sql) {
  try {
    mysqlpp::Query q = c.query(sql);
    if (is_query(sql)) {
      q.store();
      while (q.more_results()) q.store_next();
    } else {
      q.execute();
    }
    return 0;
  } catch (const mysqlpp::BadQuery& e) {
    return e.errnum() ? e.errnum() : 1;
  } catch (const mysqlpp::Exception&) {
    return 1;
  }
}

// Rows of a query as strings (NULL -> "<NULL>").
std::vector<std::vector<std::string>> rows(mysqlpp::Connection& c, const std::string& sql) {
  mysqlpp::Query q = c.query(sql);
  std::vector<std::vector<std::string>> out;
  for (const mysqlpp::Row& r : q.store()) {
    std::vector<std::string> v;
    for (size_t i = 0; i < r.size(); ++i) v.push_back(r[i].is_null() ? "<NULL>" : std::string(r[i].data(), r[i].length()));
    out.push_back(std::move(v));
  }
  return out;
}

std::string one(mysqlpp::Connection& c, const std::string& sql) {
  auto r = rows(c, sql);
  return r.empty() || r[0].empty() ? "<no row>" : r[0][0];
}

std::string quoted(const std::string& s) {
  auto c = admin();
  mysqlpp::Query q = c->query();
  q << mysqlpp::quote << s;
  return q.str();
}

std::string to_hex(const std::string& s) {
  static const char* d = "0123456789ABCDEF";
  std::string h;
  for (unsigned char ch : s) {
    h += d[ch >> 4];
    h += d[ch & 15];
  }
  return h;
}

// True when name/password logs in.
bool can_login(const std::string& name, const std::string& password) {
  try {
    SqlRobot r(name, password);
    return true;
  } catch (const mysqlpp::Exception&) {
    return false;
  }
}

// A snapshot of what a robot must never be able to change.
struct Snapshot {
  long long tables, views, triggers, routines, maps, segments, robots, users, robot_grants;
  std::string sec_a_limit, globals;
  static Snapshot take() {
    Snapshot s;
    s.tables = scalar("SELECT COUNT(*) FROM information_schema.TABLES WHERE TABLE_SCHEMA = DATABASE()");
    s.views = scalar("SELECT COUNT(*) FROM information_schema.VIEWS WHERE TABLE_SCHEMA = DATABASE()");
    s.triggers = scalar("SELECT COUNT(*) FROM information_schema.TRIGGERS WHERE TRIGGER_SCHEMA = DATABASE()");
    s.routines = scalar("SELECT COUNT(*) FROM information_schema.ROUTINES WHERE ROUTINE_SCHEMA = DATABASE()");
    s.maps = scalar("SELECT COUNT(*) FROM maps");
    s.segments = scalar("SELECT COUNT(*) FROM segments");
    s.robots = scalar("SELECT COUNT(*) FROM robots WHERE removed_at IS NULL");
    s.users = scalar("SELECT COUNT(*) FROM mysql.user");
    s.robot_grants = scalar("SELECT COUNT(*) FROM mysql.roles_mapping");
    auto c = admin();
    s.sec_a_limit = one(*c, "SELECT max_user_connections FROM mysql.user WHERE user = 'sec_a'");
    s.globals = one(*c, "SELECT CONCAT_WS(' ', @@GLOBAL.max_user_connections, @@GLOBAL.max_connections,"
                        " @@GLOBAL.event_scheduler, @@GLOBAL.sql_mode, @@GLOBAL.read_only)");
    return s;
  }
  void expect_same_as(const Snapshot& o) const {
    EXPECT_EQ(tables, o.tables);
    EXPECT_EQ(views, o.views);
    EXPECT_EQ(triggers, o.triggers);
    EXPECT_EQ(routines, o.routines);
    EXPECT_EQ(maps, o.maps);
    EXPECT_EQ(segments, o.segments);
    EXPECT_EQ(robots, o.robots);
    EXPECT_EQ(users, o.users);
    EXPECT_EQ(robot_grants, o.robot_grants);
    EXPECT_EQ(sec_a_limit, o.sec_a_limit);
    EXPECT_EQ(globals, o.globals);
  }
};

// Two robot accounts on one map, no server: rows a robot inserts stay in rr to be looked at.
class RobotSecurityAccount : public ::testing::Test {
 protected:
  void SetUp() override {
    ensure_example_map(kMap);
    pw_a_ = add_robot("sec_a", kMap);
    pw_b_ = add_robot("sec_b", kMap);
    id_a_ = static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = 'sec_a'"));
    id_b_ = static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = 'sec_b'"));
    a_ = std::make_unique<SqlRobot>("sec_a", pw_a_);
    b_ = std::make_unique<SqlRobot>("sec_b", pw_b_);
    db_ = one(a_->connection(), "SELECT DATABASE()");
  }
  void TearDown() override {
    a_.reset();
    b_.reset();
    auto c = admin();
    c->query("DELETE FROM rr WHERE db_user IN ('sec_a', 'sec_b')").execute();
  }
  mysqlpp::Connection& a() { return a_->connection(); }
  unsigned long long last_insert_id(mysqlpp::Connection& c) { return std::stoull(one(c, "SELECT LAST_INSERT_ID()")); }

  std::string pw_a_, pw_b_, db_;
  unsigned id_a_ = 0, id_b_ = 0;
  std::unique_ptr<SqlRobot> a_, b_;
};

// The same with the real server answering.
class RobotSecurity : public RobotSecurityAccount {
 protected:
  void SetUp() override {
    RobotSecurityAccount::SetUp();
    server_ = std::make_unique<ServerProcess>("--alive-period 10", "sec_server.log");
  }
  void TearDown() override {
    server_.reset();
    if (HasFailure()) std::cerr << "server log:\n" << read_file(temp_path("sec_server.log")).substr(0, 20000);
    RobotSecurityAccount::TearDown();
  }
  std::vector<SqlAnswer> ask(SqlRobot& r, const std::string& op, const std::string& params, size_t n,
                             std::optional<unsigned> robot_id = std::nullopt,
                             const std::optional<std::string>& payload = std::nullopt) {
    const auto id = r.send(op, params, payload, robot_id);
    auto got = r.receive(n);
    EXPECT_EQ(got.size(), n) << op << " " << params;
    for (const auto& g : got) EXPECT_EQ(g.request_id, id) << op;
    return got;
  }
  void ready(SqlRobot& r, long long magic) {
    auto got = ask(r, "Ready", json{{"magic", magic}}.dump(), 2);
    ASSERT_EQ(got.size(), 2u);
    ASSERT_EQ(got[0].op, "Start");
  }
  // The one answer to a request inserted by hand (raw SQL); must be an Error with code.
  std::string expect_error_answer(SqlRobot& r, const std::string& code, const std::string& what) {
    auto got = r.receive(1);
    if (got.size() != 1) {
      ADD_FAILURE() << what << ": no answer";
      return "";
    }
    EXPECT_EQ(got[0].op, "Error") << what;
    EXPECT_EQ(got[0].params["code"], code) << what << " -> " << got[0].params.dump();
    const unsigned long long req = last_insert_id(r.connection());
    EXPECT_EQ(got[0].request_id, req) << what;
    return got[0].params.value("message", "");
  }
  std::unique_ptr<ServerProcess> server_;
};

// ---- reading ------------------------------------------------------------------------

TEST_F(RobotSecurityAccount, ReadsNoTableNorViewButItsOwnAnswers) {
  std::vector<std::string> targets = {"rr", "sa", "maps", "obstacles", "segments", "robots", "tasks", "trajectories",
                                      "gps_fixes", "images", "observed_objects", "mysql.user", "mysql.global_priv",
                                      "mysql.proc", "mysql.roles_mapping", "mysql.db", "mysql.tables_priv"};
  auto adm = admin();
  std::vector<std::string> views;
  for (const auto& r : rows(*adm, "SELECT TABLE_NAME FROM information_schema.VIEWS WHERE TABLE_SCHEMA = DATABASE()"
                                  " AND TABLE_NAME NOT IN ('sa_mine', 'rr_mine') ORDER BY TABLE_NAME"))
    views.push_back(r[0]);
  ASSERT_GE(views.size(), 8u);
  EXPECT_NE(std::find(views.begin(), views.end(), "v_requests"), views.end());
  EXPECT_NE(std::find(views.begin(), views.end(), "v_answers"), views.end());
  targets.insert(targets.end(), views.begin(), views.end());
  for (const std::string& t : targets) {
    EXPECT_NE(sql_error(a(), "SELECT * FROM " + t + " LIMIT 1"), 0u) << t;
    EXPECT_NE(sql_error(a(), "SELECT COUNT(*) FROM " + t), 0u) << t;
  }
  // Indirect reads.
  for (const char* sql : {
           "SELECT * FROM sa_mine WHERE id IN (SELECT id FROM sa)",
           "SELECT (SELECT COUNT(*) FROM rr)",
           "SELECT * FROM sa_mine s JOIN robots r ON r.id = s.robot_id",
           "WITH x AS (SELECT * FROM sa) SELECT * FROM x",
           "EXPLAIN SELECT * FROM sa",
           "SHOW COLUMNS FROM sa",
           "SHOW INDEX FROM sa",
           "HANDLER sa OPEN",
           "HANDLER rr OPEN",
           "INSERT INTO rr (op, params) SELECT op, params FROM sa",
           "INSERT INTO rr (op, params) SELECT 'Alive', JSON_OBJECT('n', COUNT(*)) FROM rr",
           "SELECT * FROM information_schema.INNODB_TRX",
           "SELECT * FROM information_schema.INNODB_LOCK_WAITS",
           "SELECT * FROM information_schema.INNODB_LOCKS",
           "SHOW ENGINE INNODB STATUS",
           "SHOW BINLOG EVENTS",
           "SELECT 1 INTO OUTFILE '/tmp/fleetmap_sec_evil_out'",
       })
    EXPECT_NE(sql_error(a(), sql), 0u) << sql;
  // What the robot may read: its own answers, and the ids and ops of its own waiting requests.
  EXPECT_EQ(sql_error(a(), "SELECT * FROM sa_mine"), 0u);
  EXPECT_EQ(sql_error(a(), "SELECT id, op, created_at FROM rr_mine"), 0u);
  // Files stay closed: LOAD_FILE gives NULL without the FILE privilege.
  EXPECT_EQ(one(a(), "SELECT LOAD_FILE('/etc/passwd') IS NULL"), "1");
  // The catalogue shows the robot only its two objects.
  std::set<std::string> shown;
  for (const auto& r : rows(a(), "SHOW TABLES")) shown.insert(r[0]);
  EXPECT_EQ(shown, (std::set<std::string>{"rr", "rr_mine", "sa_mine"}));
  shown.clear();
  for (const auto& r : rows(a(), "SELECT TABLE_NAME FROM information_schema.TABLES WHERE TABLE_SCHEMA = DATABASE()"))
    shown.insert(r[0]);
  EXPECT_EQ(shown, (std::set<std::string>{"rr", "rr_mine", "sa_mine"}));
  // Other sessions (the administrator's, the other robot's) are invisible, and so are their queries.
  rows(*adm, "SELECT 1");
  for (const char* sql : {"SHOW FULL PROCESSLIST", "SELECT ID, USER, INFO FROM information_schema.PROCESSLIST"})
    for (const auto& r : rows(a(), sql)) EXPECT_EQ(r[1], "sec_a") << sql;
}

TEST_F(RobotSecurity, SeesAndDeletesOnlyItsOwnAnswers) {
  ready(*a_, 1);
  // B's answers wait in sa, unread.
  b_->send("Ready", R"({"magic": 2})");
  ASSERT_TRUE(wait_until([] { return scalar("SELECT COUNT(*) FROM sa WHERE sentinel = 0 AND db_user = 'sec_b'") == 2; }));
  auto adm = admin();
  std::vector<std::string> b_ids;
  for (const auto& r : rows(*adm, "SELECT id FROM sa WHERE sentinel = 0 AND db_user = 'sec_b' ORDER BY id")) b_ids.push_back(r[0]);
  ASSERT_EQ(b_ids.size(), 2u);
  const std::string b_rows = "SELECT COUNT(*) FROM sa WHERE db_user = 'sec_b' AND robot_id = " + std::to_string(id_b_) +
                             " AND op IN ('Start', 'SetMap')";

  EXPECT_TRUE(a_->peek().empty());
  EXPECT_EQ(one(a(), "SELECT COUNT(*) FROM sa_mine"), "0");
  EXPECT_EQ(one(a(), "SELECT COUNT(*) FROM sa_mine WHERE db_user = 'sec_b' OR robot_id = " + std::to_string(id_b_) +
                         " OR id = " + b_ids[0]),
            "0");
  // Session settings do not change whose rows the view shows.
  for (const char* s : {"SET NAMES utf8mb4 COLLATE utf8mb4_general_ci", "SET collation_connection = utf8mb4_unicode_ci",
                        "SET NAMES latin1", "SET SESSION sql_mode = 'PAD_CHAR_TO_FULL_LENGTH'"}) {
    EXPECT_EQ(sql_error(a(), s), 0u) << s;
    EXPECT_EQ(one(a(), "SELECT COUNT(*) FROM sa_mine"), "0") << s;
  }
  EXPECT_EQ(sql_error(a(), "SET NAMES utf8mb4"), 0u);

  // Deleting B's rows through the view deletes nothing.
  for (const std::string& sql : {"DELETE FROM sa_mine WHERE id = " + b_ids[0], "DELETE FROM sa_mine WHERE id = " + b_ids[1],
                                 std::string("DELETE FROM sa_mine WHERE db_user = 'sec_b'"), std::string("DELETE FROM sa_mine")}) {
    mysqlpp::Query q = a().query(sql);
    EXPECT_EQ(q.execute().rows(), 0u) << sql;
  }
  EXPECT_EQ(scalar(b_rows), 2);
  // Writing through the view is refused, also for its own rows.
  for (const std::string& sql : {
           "UPDATE sa_mine SET db_user = 'sec_a' WHERE id = " + b_ids[0],
           std::string("UPDATE sa_mine SET op = 'Abort'"),
           "INSERT INTO sa_mine (robot_id, db_user, op, params) VALUES (" + std::to_string(id_b_) +
               ", 'sec_b', 'Abort', '{\"reason\": \"forged\"}')",
           "INSERT INTO sa_mine (robot_id, db_user, op, params) VALUES (" + std::to_string(id_a_) +
               ", 'sec_a', 'SetPosEnd', '{\"x\": 1, \"y\": 1}')",
           "REPLACE INTO sa_mine (id, robot_id, db_user, op, params) VALUES (" + b_ids[0] + ", " +
               std::to_string(id_b_) + ", 'sec_b', 'Abort', '{}')",
           "INSERT INTO sa (robot_id, db_user, op, params) VALUES (" + std::to_string(id_b_) + ", 'sec_b', 'Abort', '{}')",
           std::string("UPDATE sa SET op = 'Abort'"),
           std::string("DELETE FROM sa"),
       })
    EXPECT_NE(sql_error(a(), sql), 0u) << sql;
  EXPECT_EQ(scalar(b_rows), 2);
  // Only these two robots' rows: an earlier test may leave its own answers in sa.
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM sa WHERE op IN ('Abort', 'SetPosEnd') AND (db_user IN ('sec_a', 'sec_b') OR "
                   "robot_id IN (" + std::to_string(id_a_) + ", " + std::to_string(id_b_) + "))"),
            0);
  // B still reads both, and deletes its own.
  auto got = b_->receive(2);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].op, "Start");
  EXPECT_EQ(got[1].op, "SetMap");
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM sa WHERE sentinel = 0 AND db_user = 'sec_b'"), 0);
}

TEST(RobotSecurityLogin, OnlyTheExactNameWithItsPasswordLogsIn) {
  ensure_example_map(kMap);
  const std::string pw = add_robot("sec_a", kMap);
  EXPECT_TRUE(can_login("sec_a", pw));
  // Names that a case-insensitive or pad-space comparison would take for sec_a.
  for (const char* name : {"SEC_A", "Sec_a", "sec_A", "sec_a ", " sec_a", "sec_a  ", "sec_a\t", "sec_", "sec_a%", "sec_%",
                           "sec_a@localhost", "sec_a@%"}) {
    EXPECT_FALSE(can_login(name, pw)) << "'" << name << "'";
  }
  EXPECT_FALSE(can_login("sec_a", pw + "x"));
  EXPECT_FALSE(can_login("sec_a", ""));
  EXPECT_FALSE(can_login("sec_a", upper(pw)));
  // Unknown users, and no anonymous account to land on.
  EXPECT_FALSE(can_login("sec_nobody", pw));
  EXPECT_FALSE(can_login("sec_nobody", ""));
  EXPECT_FALSE(can_login("", ""));
  EXPECT_FALSE(can_login("", pw));
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM mysql.user WHERE user = ''"), 0);
  // Roles cannot log in.
  EXPECT_FALSE(can_login("fleetmap_robot_role", ""));
  EXPECT_FALSE(can_login("fleetmap_server_role", ""));
  // The account's name as the database sees it is exactly the robot's.
  SqlRobot ok("sec_a", pw);
  EXPECT_EQ(one(ok.connection(), "SELECT SUBSTRING_INDEX(USER(), '@', 1)"), "sec_a");
}

// ---- writing rr -----------------------------------------------------------------------

TEST_F(RobotSecurityAccount, RrIsInsertOnlyEvenForItsOwnRows) {
  const auto id = a_->send("Alive");
  const std::string sid = std::to_string(id);
  for (const std::string& sql : {
           "UPDATE rr SET op = 'Ready' WHERE id = " + sid,
           "UPDATE rr SET db_user = 'sec_b' WHERE id = " + sid,
           std::string("UPDATE rr SET params = '{}'"),
           "DELETE FROM rr WHERE id = " + sid,
           std::string("DELETE FROM rr WHERE db_user = SUBSTRING_INDEX(USER(), '@', 1)"),
           std::string("DELETE FROM rr"),
           "REPLACE INTO rr (id, op, params) VALUES (" + sid + ", 'Ready', '{\"magic\": 1}')",
           std::string("REPLACE INTO rr (op, params) VALUES ('Alive', '{}')"),
           "INSERT INTO rr (id, op, params) VALUES (" + sid + ", 'Alive', '{}') ON DUPLICATE KEY UPDATE op = 'Ready'",
           std::string("INSERT INTO rr (op, params) VALUES ('Alive', '{}') ON DUPLICATE KEY UPDATE op = 'x'"),
           std::string("TRUNCATE TABLE rr"),
           std::string("LOCK TABLES rr WRITE"),
           std::string("LOAD DATA INFILE '/etc/passwd' INTO TABLE rr"),  // a server-side file: FILE privilege
       })
    EXPECT_NE(sql_error(a(), sql), 0u) << sql;
  auto adm = admin();
  EXPECT_EQ(one(*adm, "SELECT op FROM rr WHERE id = " + sid), "Alive");
  EXPECT_EQ(one(*adm, "SELECT db_user FROM rr WHERE id = " + sid), "sec_a");
  EXPECT_EQ(one(*adm, "SELECT params FROM rr WHERE id = " + sid), "{}");
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'sec_a'"), 1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'sec_b'"), 0);
}

TEST_F(RobotSecurityAccount, RrMineShowsOnlyItsOwnWaitingRequestsAndIsReadOnly) {
  const auto mine = a_->send("Alive");
  const auto theirs = b_->send("GetPosIni");
  EXPECT_EQ(one(a(), "SELECT GROUP_CONCAT(id) FROM rr_mine"), std::to_string(mine));
  EXPECT_EQ(one(a(), "SELECT COUNT(*) FROM rr_mine WHERE id = " + std::to_string(theirs)), "0");
  EXPECT_EQ(one(b_->connection(), "SELECT GROUP_CONCAT(op) FROM rr_mine"), "GetPosIni");
  // No params nor payload: what the request carried stays the server's to read.
  EXPECT_NE(sql_error(a(), "SELECT params FROM rr_mine"), 0u);
  EXPECT_NE(sql_error(a(), "SELECT payload FROM rr_mine"), 0u);
  for (const std::string& sql : {"DELETE FROM rr_mine WHERE id = " + std::to_string(mine),
                                 std::string("UPDATE rr_mine SET op = 'Ready'"),
                                 std::string("INSERT INTO rr_mine (op) VALUES ('Alive')")})
    EXPECT_NE(sql_error(a(), sql), 0u) << sql;
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'sec_a'"), 1);
}

TEST_F(RobotSecurityAccount, TheTriggerStampsAccountTimeAndId) {
  auto adm = admin();
  const auto check_row = [&](unsigned long long id, const std::string& what) {
    // db_user is the account, byte for byte; created_at is the database's clock, now.
    EXPECT_EQ(one(*adm, "SELECT HEX(db_user) FROM rr WHERE id = " + std::to_string(id)), to_hex("sec_a")) << what;
    EXPECT_EQ(one(*adm, "SELECT ABS(TIMESTAMPDIFF(SECOND, created_at, NOW(6))) <= 10 FROM rr WHERE id = " +
                            std::to_string(id)),
              "1")
        << what << ": created_at " << one(*adm, "SELECT created_at FROM rr WHERE id = " + std::to_string(id));
  };
  const auto id0 = a_->send("Alive");
  check_row(id0, "plain insert");

  // Everything forged at once: another account, an old time, the largest id.
  ASSERT_EQ(sql_error(a(), "INSERT INTO rr (id, robot_id, db_user, op, params, created_at) VALUES "
                           "(18446744073709551615, NULL, 'sec_b', 'Alive', '{}', '2001-02-03 04:05:06')"),
            0u);
  const auto id1 = last_insert_id(a());
  EXPECT_EQ(id1, id0 + 1);
  check_row(id1, "forged db_user, created_at, id");
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE id = " + std::to_string(id1) + " AND op = 'Alive'"), 1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE id = 18446744073709551615"), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE db_user <> 'sec_a' AND db_user <> 'sec_b'"), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'sec_b'"), 0);

  // Names that would match sec_b, or nobody, under a sloppy comparison.
  for (const char* forged : {"SEC_B", "sec_b ", "", "sec_b@%", "fleetmap_server"}) {
    ASSERT_EQ(sql_error(a(), "INSERT INTO rr (db_user, op, params) VALUES (" + quoted(forged) + ", 'Alive', '{}')"), 0u);
    check_row(last_insert_id(a()), std::string("db_user '") + forged + "'");
  }
  // An id that exists already: a new row, not an error and not an overwrite.
  ASSERT_EQ(sql_error(a(), "INSERT INTO rr (id, op, params) VALUES (" + std::to_string(id0) + ", 'Stopped', '{}')"), 0u);
  const auto id2 = last_insert_id(a());
  EXPECT_GT(id2, id1);
  EXPECT_EQ(one(*adm, "SELECT op FROM rr WHERE id = " + std::to_string(id0)), "Alive");
  check_row(id2, "duplicate id");

  // A forged session clock: CURRENT_TIMESTAMP would be 1970, SYSDATE(6) is not.
  ASSERT_EQ(sql_error(a(), "SET timestamp = 1"), 0u);
  EXPECT_EQ(one(a(), "SELECT UNIX_TIMESTAMP()"), "1");
  ASSERT_EQ(sql_error(a(), "INSERT INTO rr (op, params) VALUES ('Alive', '{}')"), 0u);
  check_row(last_insert_id(a()), "SET timestamp = 1, default created_at");
  ASSERT_EQ(sql_error(a(), "INSERT INTO rr (op, params, created_at) VALUES ('Alive', '{}', '1970-01-01 00:00:01')"), 0u);
  check_row(last_insert_id(a()), "SET timestamp = 1, forged created_at");
  ASSERT_EQ(sql_error(a(), "INSERT INTO rr (op, params, created_at) VALUES ('Alive', '{}', '2037-12-31 00:00:00')"), 0u);
  check_row(last_insert_id(a()), "SET timestamp = 1, future created_at");

  // The counter goes on normally, for this robot and the next.
  const auto id3 = a_->send("Alive");
  const auto id4 = b_->send("Alive");
  EXPECT_EQ(id4, id3 + 1);
  EXPECT_LT(id4, 1000000000ull);
  EXPECT_EQ(one(*adm, "SELECT db_user FROM rr WHERE id = " + std::to_string(id4)), "sec_b");
}

// A robot can force the next AUTO_INCREMENT value of its session with SET insert_id; the
// trigger's NEW.id = NULL does not stop that. Taking the counter to its end would make
// every later INSERT into rr fail for all robots (error 1467), so the database must refuse
// such a row or give it a normal id.
class RobotSecurityCounter : public RobotSecurityAccount {
 protected:
  void TearDown() override {
    // Repair the shared test database whatever happened.
    auto adm = admin();
    adm->query("DELETE FROM rr WHERE id > 1000000000000").execute();
    adm->query("ALTER TABLE rr AUTO_INCREMENT = 1").execute();  // InnoDB: back to MAX(id) + 1
    RobotSecurityAccount::TearDown();
  }
};

TEST_F(RobotSecurityCounter, SetInsertIdCannotExhaustTheCounterForEveryone) {
  const auto before = a_->send("Alive");
  ASSERT_EQ(sql_error(a(), "SET insert_id = 18446744073709551614"), 0u);  // any session may set it
  const unsigned err = sql_error(a(), "INSERT INTO rr (op, params) VALUES ('Alive', '{}')");
  if (err == 0) {
    const auto forced = last_insert_id(a());
    EXPECT_EQ(forced, before + 1) << "the robot chose its row's id";
  }
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE id > 1000000000000"), 0);
  // Whatever the robot did, the others can still send.
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(sql_error(b_->connection(), "INSERT INTO rr (op, params) VALUES ('Alive', '{}')"), 0u)
        << "insert " << i << " of another robot after sec_a's SET insert_id";
  }
  // The robot itself, once it stops forcing ids, can send too.
  ASSERT_EQ(sql_error(a(), "SET insert_id = 0"), 0u);
  EXPECT_EQ(sql_error(a(), "INSERT INTO rr (op, params) VALUES ('Alive', '{}')"), 0u);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE id > 1000000000000"), 0);
  // Nor does the damage outlive the row: once the server has taken (deleted) every
  // request, robots can send again.
  admin()->query("DELETE FROM rr WHERE db_user IN ('sec_a', 'sec_b')").execute();
  EXPECT_EQ(sql_error(b_->connection(), "INSERT INTO rr (op, params) VALUES ('Alive', '{}')"), 0u)
      << "after the server drained rr";
}

// ---- the server's side: ids, strings, ops, params ---------------------------------------

TEST_F(RobotSecurity, AnotherRobotsIdIsRefusedWithoutEffect) {
  ready(*a_, 111);
  ready(*b_, 222);
  ASSERT_TRUE(wait_until([] { return scalar("SELECT COUNT(*) FROM rr WHERE db_user IN ('sec_a', 'sec_b')") == 0; }));
  const std::string ta = "SELECT COUNT(*) FROM trajectories WHERE robot_id = " + std::to_string(id_a_);
  const std::string tb = "SELECT COUNT(*) FROM trajectories WHERE robot_id = " + std::to_string(id_b_);
  const std::string oa = "SELECT COUNT(*) FROM observed_objects WHERE robot_id = " + std::to_string(id_a_);
  const std::string ob = "SELECT COUNT(*) FROM observed_objects WHERE robot_id = " + std::to_string(id_b_);
  const std::string gb = "SELECT COUNT(*) FROM gps_fixes WHERE robot_id = " + std::to_string(id_b_);
  const long long ta0 = scalar(ta), tb0 = scalar(tb), oa0 = scalar(oa), ob0 = scalar(ob), gb0 = scalar(gb);

  const auto not_yours = [&](const std::string& op, const std::string& params, unsigned robot_id) {
    auto got = ask(*a_, op, params, 1, robot_id);
    if (got.size() != 1) return;
    EXPECT_EQ(got[0].op, "Error") << op;
    EXPECT_EQ(got[0].params["code"], "not_your_robot") << op << " " << got[0].params.dump();
    EXPECT_EQ(got[0].robot_id, id_a_) << "the Error goes to the sender";
  };
  not_yours("SendPos", R"({"x": 7, "y": 7, "theta": 0, "v": 1})", id_b_);
  not_yours("SetObject", R"({"x": 7, "y": 7, "object": "forged"})", id_b_);
  not_yours("SendGPS", R"({"lat": 1, "lon": 1})", id_b_);
  not_yours("Ready", R"({"magic": 999})", id_b_);
  not_yours("Stopped", "{}", id_b_);
  not_yours("GetMap", R"({"x": 20, "y": 30, "w": 10, "h": 8})", id_b_);
  not_yours("SendPos", R"({"x": 7, "y": 7, "theta": 0, "v": 1})", id_b_ + 100000);  // nobody's
  not_yours("SendPos", R"({"x": 7, "y": 7, "theta": 0, "v": 1})", 0);
  // Its own id works.
  auto ok = ask(*a_, "SetObject", R"({"x": 3, "y": 4, "object": "mine"})", 1, id_a_);
  ASSERT_EQ(ok.size(), 1u);
  EXPECT_EQ(ok[0].op, "OpAck");

  EXPECT_EQ(scalar(ta), ta0);
  EXPECT_EQ(scalar(tb), tb0);
  EXPECT_EQ(scalar(oa), oa0 + 1);
  EXPECT_EQ(scalar(ob), ob0);
  EXPECT_EQ(scalar(gb), gb0);
  EXPECT_EQ(scalar("SELECT magic FROM robots WHERE id = " + std::to_string(id_b_)), 222);
  EXPECT_EQ(scalar("SELECT magic FROM robots WHERE id = " + std::to_string(id_a_)), 111);
  EXPECT_EQ(scalar("SELECT x IS NULL FROM robots WHERE id = " + std::to_string(id_b_)), 1);
  EXPECT_EQ(scalar("SELECT state = 'ready' FROM robots WHERE id = " + std::to_string(id_b_)), 1);
  EXPECT_TRUE(b_->peek().empty()) << "nothing reached the other robot";
}

TEST_F(RobotSecurity, SqlInStringParametersIsStoredAndAnsweredLiterally) {
  ready(*a_, 5);
  const Snapshot before = Snapshot::take();
  const std::string mine = " WHERE robot_id = " + std::to_string(id_a_) + " ORDER BY id DESC LIMIT 1";
  auto adm = admin();
  for (const std::string& object : {
           std::string("x'); DROP TABLE maps; --"),
           std::string("x\"); DROP TABLE maps; #"),
           std::string("\\'; DELETE FROM robots; -- "),
           std::string("a`b`c\\\\d%e_f"),
           std::string("' OR '1'='1"),
           std::string("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\xa4\x96"),
           std::string("nul\0byte", 8),
           std::string(255, '\''),
           std::string(127, '\\') + "'",
       }) {
    auto got = ask(*a_, "SetObject", json{{"x", 3}, {"y", 4}, {"object", object}}.dump(), 1);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].op, "OpAck") << got[0].params.dump();
    EXPECT_EQ(one(*adm, "SELECT HEX(object) FROM observed_objects" + mine), to_hex(object)) << object;
  }
  // An image format with quotes.
  const std::string format = "png'); DROP TABLE images; --";
  auto got = ask(*a_, "SendImage", json{{"x", 1}, {"y", 2}, {"format", format}}.dump(), 1, std::nullopt,
                 std::string("\x00\x01'\"\\", 5));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].op, "OpAck") << got[0].params.dump();
  EXPECT_EQ(one(*adm, "SELECT HEX(format) FROM images" + mine), to_hex(format));
  EXPECT_EQ(one(*adm, "SELECT HEX(data) FROM images" + mine), "000127225C");

  // A GetMap encoding with quotes: refused, and quoted back as it was.
  for (const std::string& enc : {std::string("seed'); DROP TABLE maps; --"), std::string("seed\", \"x\": \"y"),
                                 std::string("seed' OR '1'='1")}) {
    got = ask(*a_, "GetMap", json{{"x", 20}, {"y", 30}, {"w", 10}, {"h", 8}, {"encoding", enc}}.dump(), 1);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].op, "Error");
    EXPECT_EQ(got[0].params["code"], "bad_params");
    EXPECT_NE(got[0].params["message"].get<std::string>().find(enc), std::string::npos) << got[0].params.dump();
  }
  // An op with SQL in it (rr.op is 16 characters).
  for (const std::string& op : {std::string("';DROP TABLE rr"), std::string("x\\'; --"), std::string("Ready' OR '1")}) {
    got = ask(*a_, op, "{}", 1);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].params["code"], "unknown_op") << op;
    EXPECT_NE(got[0].params["message"].get<std::string>().find(op), std::string::npos) << got[0].params.dump();
  }
  Snapshot::take().expect_same_as(before);
  // And the map still serves.
  got = ask(*a_, "GetMap", R"({"x": 20, "y": 30, "w": 10, "h": 8})", 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].op, "SetMap");
}

TEST_F(RobotSecurity, OverLongOpIsUnknownNotTruncatedIntoAValidOp) {
  ready(*a_, 42);
  const std::string longop = "GetPosIni" + std::string(31, 'X');  // 40 characters
  // Strict mode (the server default): the database refuses it outright.
  EXPECT_EQ(sql_error(a(), "INSERT INTO rr (op, params) VALUES ('" + longop + "', '{}')"), 1406u);
  // Trailing spaces are cut even in strict mode (a note only): "Ready" + 11 spaces is no op.
  ASSERT_EQ(sql_error(a(), "INSERT INTO rr (op, params) VALUES ('Ready" + std::string(35, ' ') + "', '{\"magic\": 7}')"), 0u);
  expect_error_answer(*a_, "unknown_op", "Ready + 35 spaces, strict");
  // A robot turns strict mode off: the op is silently truncated to 16 characters.
  ASSERT_EQ(sql_error(a(), "SET SESSION sql_mode = ''"), 0u);
  ASSERT_EQ(sql_error(a(), "INSERT INTO rr (op, params) VALUES ('" + longop + "', '{}')"), 0u);
  std::string msg = expect_error_answer(*a_, "unknown_op", "40-character op, sql_mode ''");
  EXPECT_NE(msg.find("GetPosIniXXXXXXX"), std::string::npos) << msg;
  for (const std::string& op : {"Ready" + std::string(35, ' '), "Ready" + std::string(35, '\t'),
                                "GetMap" + std::string(34, '.'), "Ready" + std::string(35, '\0')}) {
    mysqlpp::Query q = a().query();
    q << "INSERT INTO rr (op, params) VALUES (" << mysqlpp::quote << op << ", '{\"magic\": 9}')";
    ASSERT_NO_THROW(q.execute()) << op.size();
    expect_error_answer(*a_, "unknown_op", "op of 40 bytes starting " + op.substr(0, 6));
  }
  EXPECT_EQ(scalar("SELECT magic FROM robots WHERE id = " + std::to_string(id_a_)), 42);
  EXPECT_TRUE(a_->peek().empty());
}

TEST_F(RobotSecurity, ParamsThatAreNotJsonAreBadJson) {
  ready(*a_, 42);
  // With the CHECK constraint on, the database refuses them.
  EXPECT_NE(sql_error(a(), "INSERT INTO rr (op, params) VALUES ('Ready', '{not json')"), 0u);
  // A robot switches the constraint off for its session.
  ASSERT_EQ(sql_error(a(), "SET SESSION check_constraint_checks = 0"), 0u);
  for (const std::string& params : {std::string("{not json"), std::string(""), std::string("{\"magic\": 1"),
                                    std::string("magic=1"), std::string("{'magic': 1}"), std::string("{\"magic\": NaN}"),
                                    std::string("\x01\x02\x03")}) {
    for (const char* op : {"Ready", "SendPos", "OpAck", "Alive"}) {
      a_->send(op, params);
      expect_error_answer(*a_, "bad_json", std::string(op) + " '" + params + "'");
    }
  }
  ASSERT_EQ(sql_error(a(), "SET SESSION check_constraint_checks = 1"), 0u);
  // JSON, but no object: bad_json too; a number beyond double range: bad_params.
  for (const char* params : {"[1, 2]", "\"x\"", "null", "7"}) {
    a_->send("Ready", params);
    expect_error_answer(*a_, "bad_json", params);
  }
  a_->send("Ready", R"({"magic": 1e999})");
  expect_error_answer(*a_, "bad_params", "magic 1e999");
  a_->send("GetMap", R"({"x": 1, "y": 1, "w": 1e999, "h": 1})");
  expect_error_answer(*a_, "bad_params", "w 1e999");
  EXPECT_EQ(scalar("SELECT magic FROM robots WHERE id = " + std::to_string(id_a_)), 42);
  auto got = ask(*a_, "GetMap", R"({"x": 20, "y": 30, "w": 10, "h": 8})", 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].op, "SetMap");
}

// ---- schema, accounts, procedures -----------------------------------------------------

TEST_F(RobotSecurityAccount, CannotCallProceduresChangeTheSchemaOrAccounts) {
  const Snapshot before = Snapshot::take();
  const std::vector<std::string> denied = {
      "CALL robot_add('sec_evil', 'abcdefghijklmnop', 'sec_map', 100)",
      "CALL robot_add('sec_a', 'abcdefghijklmnop', 'sec_map', 100)",
      "CALL robot_remove('sec_b')",
      "CALL robot_remove('sec_a')",
      "CREATE TABLE sec_evil (x INT)",
      "CREATE TABLE sec_evil2 LIKE rr",
      "CREATE TABLE sec_evil3 AS SELECT * FROM sa_mine",
      "CREATE TEMPORARY TABLE sec_tmp (x INT)",
      "CREATE VIEW sec_v AS SELECT 1",
      "CREATE OR REPLACE VIEW sa_mine AS SELECT * FROM sa",
      "CREATE INDEX ix_evil ON rr (op)",
      "CREATE TRIGGER sec_t BEFORE INSERT ON rr FOR EACH ROW SET NEW.op = 'x'",
      "CREATE OR REPLACE TRIGGER rr_stamp BEFORE INSERT ON rr FOR EACH ROW SET NEW.id = NEW.id",
      "CREATE PROCEDURE sec_p() SELECT 1",
      "CREATE FUNCTION sec_f() RETURNS INT RETURN 1",
      "CREATE SEQUENCE sec_seq",
      "CREATE EVENT sec_e ON SCHEDULE EVERY 1 SECOND DO DELETE FROM sa",
      "CREATE DATABASE sec_evil",
      "CREATE USER 'sec_evil'@'%' IDENTIFIED BY 'abcdefghijklmnop'",
      "CREATE ROLE sec_evil_role",
      "DROP TABLE rr",
      "DROP TABLE sa",
      "DROP TABLE maps",
      "DROP TABLE IF EXISTS segments",
      "DROP VIEW sa_mine",
      "DROP VIEW v_requests",
      "DROP TRIGGER rr_stamp",
      "DROP PROCEDURE robot_add",
      "DROP PROCEDURE robot_remove",
      "DROP DATABASE " + db_,
      "DROP USER 'sec_b'@'%'",
      "DROP USER 'fleetmap_server'@'%'",
      "DROP ROLE fleetmap_robot_role",
      "ALTER TABLE rr ADD COLUMN evil INT",
      "ALTER TABLE rr DROP COLUMN db_user",
      "ALTER TABLE rr AUTO_INCREMENT = 18446744073709551615",
      "ALTER TABLE sa ENGINE = MyISAM",
      "ALTER VIEW sa_mine AS SELECT * FROM sa",
      "ALTER DATABASE " + db_ + " CHARACTER SET latin1",
      "ALTER USER 'sec_a'@'%' WITH MAX_USER_CONNECTIONS 100",
      "ALTER USER CURRENT_USER() WITH MAX_USER_CONNECTIONS 0",
      "ALTER USER 'sec_b'@'%' ACCOUNT LOCK",
      "ALTER USER 'sec_b'@'%' IDENTIFIED BY 'abcdefghijklmnop'",
      "RENAME TABLE rr TO rr_old",
      "RENAME USER 'sec_b'@'%' TO 'sec_x'@'%'",
      "TRUNCATE TABLE sa",
      "OPTIMIZE TABLE rr",
      "GRANT SELECT ON sa TO 'sec_a'@'%'",
      "GRANT SELECT ON *.* TO 'sec_a'@'%'",
      "GRANT ALL ON " + db_ + ".* TO 'sec_a'@'%'",
      "GRANT fleetmap_server_role TO 'sec_a'@'%'",
      "GRANT fleetmap_robot_role TO 'sec_b'@'%'",
      "GRANT INSERT ON rr TO 'sec_b'@'%'",
      "GRANT SELECT, DELETE ON sa_mine TO 'sec_b'@'%'",
      "GRANT EXECUTE ON PROCEDURE robot_add TO 'sec_a'@'%'",
      "REVOKE INSERT ON rr FROM 'sec_b'@'%'",
      "REVOKE fleetmap_robot_role FROM 'sec_b'@'%'",
      "REVOKE ALL PRIVILEGES, GRANT OPTION FROM 'sec_b'@'%'",
      "SET ROLE fleetmap_server_role",
      "SET ROLE fleetmap_operator_role",
      "SET ROLE fleetmap_inspector_role",
      "SET DEFAULT ROLE fleetmap_server_role",
      "SET PASSWORD FOR 'sec_b'@'%' = PASSWORD('abcdefghijklmnop')",
      "SET GLOBAL max_user_connections = 1000",
      "SET GLOBAL max_connections = 5",
      "SET GLOBAL event_scheduler = ON",
      "SET SESSION max_user_connections = 100",
      "FLUSH PRIVILEGES",
      "FLUSH TABLES WITH READ LOCK",
      "INSTALL SONAME 'ha_blackhole'",
      "SHUTDOWN",
  };
  for (const std::string& sql : denied) EXPECT_NE(sql_error(a(), sql), 0u) << sql;
  // The robot's session still works, and nothing changed.
  EXPECT_EQ(sql_error(a(), "SELECT COUNT(*) FROM sa_mine"), 0u);
  Snapshot::take().expect_same_as(before);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM mysql.user WHERE user = 'sec_b' AND host = '%'"), 1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM mysql.user WHERE user LIKE 'sec\\_evil%'"), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM information_schema.TRIGGERS WHERE TRIGGER_SCHEMA = DATABASE()"
                   " AND TRIGGER_NAME = 'rr_stamp'"),
            1);
  EXPECT_EQ(scalar("SELECT max_user_connections FROM mysql.user WHERE user = 'sec_a'"), 4);
  // Its role is the robot role, and only that.
  EXPECT_EQ(one(a(), "SELECT CURRENT_ROLE()"), "fleetmap_robot_role");
  // B still logs in with its password.
  EXPECT_TRUE(can_login("sec_b", pw_b_));
}

TEST_F(RobotSecurityAccount, CannotEndOtherConnections) {
  auto adm = admin();
  const std::string admin_thread = one(*adm, "SELECT CONNECTION_ID()");
  const std::string b_thread = one(b_->connection(), "SELECT CONNECTION_ID()");
  for (const std::string& t : {admin_thread, b_thread}) {
    EXPECT_NE(sql_error(a(), "KILL " + t), 0u) << t;
    EXPECT_NE(sql_error(a(), "KILL CONNECTION " + t), 0u) << t;
    EXPECT_NE(sql_error(a(), "KILL QUERY " + t), 0u) << t;
  }
  // KILL USER of another account is accepted by MariaDB but ends nothing.
  for (const char* sql : {"KILL USER sec_b", "KILL CONNECTION USER 'sec_b'@'%'", "KILL QUERY USER sec_b",
                          "KILL HARD USER sec_b"})
    sql_error(a(), sql);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM information_schema.PROCESSLIST WHERE ID = " + b_thread), 1);
  EXPECT_EQ(one(*adm, "SELECT 1"), "1");
  EXPECT_EQ(one(b_->connection(), "SELECT COUNT(*) FROM sa_mine"), "0");
}

TEST(RobotSecurityConnections, MaxUserConnectionsHolds) {
  ensure_example_map(kMap);
  const std::string pw = add_robot("sec_c", kMap);
  EXPECT_EQ(scalar("SELECT max_user_connections FROM mysql.user WHERE user = 'sec_c'"), 4);  // robot add's default
  std::vector<std::unique_ptr<SqlRobot>> open;
  std::string refusal;
  for (int i = 0; i < 10; ++i) {
    try {
      open.push_back(std::make_unique<SqlRobot>("sec_c", pw));
    } catch (const mysqlpp::Exception& e) {
      refusal = e.what();
      break;
    }
  }
  EXPECT_EQ(open.size(), 4u);
  EXPECT_NE(refusal.find("max_user_connections"), std::string::npos) << refusal;
  // The robot cannot raise its limit.
  ASSERT_FALSE(open.empty());
  mysqlpp::Connection& c = open.front()->connection();
  for (const char* sql : {"SET SESSION max_user_connections = 100", "SET GLOBAL max_user_connections = 0",
                          "ALTER USER CURRENT_USER() WITH MAX_USER_CONNECTIONS 100",
                          "ALTER USER 'sec_c'@'%' WITH MAX_USER_CONNECTIONS 0"})
    EXPECT_NE(sql_error(c, sql), 0u) << sql;
  EXPECT_FALSE(can_login("sec_c", pw));
  // One closed, one more fits.
  open.pop_back();
  EXPECT_TRUE(wait_until([] {
    return scalar("SELECT COUNT(*) FROM information_schema.PROCESSLIST WHERE USER = 'sec_c'") < 4;
  }));
  EXPECT_NO_THROW(open.push_back(std::make_unique<SqlRobot>("sec_c", pw)));
}

TEST(RobotSecurityRemove, DropsTheAccountEndsItsConnectionsKeepsItsTrajectory) {
  ensure_example_map(kMap);
  const std::string pw = add_robot("sec_d", kMap);
  const std::string id = std::to_string(scalar("SELECT id FROM robots WHERE db_user = 'sec_d'"));
  const std::string trajectory = "SELECT COUNT(*) FROM trajectories WHERE robot_id = " + id;
  const long long before = scalar(trajectory);
  {
    ServerProcess server("--alive-period 10", "sec_remove.log");
    SqlRobot d("sec_d", pw);
    SqlRobot d2("sec_d", pw);
    d.send("Ready", R"({"magic": 3})");
    ASSERT_EQ(d.receive(2).size(), 2u);
    for (int i = 0; i < 3; ++i) d.send("SendPos", json{{"x", 10.0 + i}, {"y", 20.0}, {"theta", 0.0}, {"v", 0.5}}.dump());
    ASSERT_TRUE(wait_until([&] { return scalar(trajectory) == before + 3; })) << server.log().substr(0, 5000);
    // An answer waiting, to see the mailbox emptied.
    d.send("GetPosEnd");
    ASSERT_TRUE(wait_until([] { return scalar("SELECT COUNT(*) FROM sa WHERE sentinel = 0 AND db_user = 'sec_d'") == 1; }));
    EXPECT_EQ(scalar("SELECT COUNT(*) FROM information_schema.PROCESSLIST WHERE USER = 'sec_d'"), 2);

    const RunResult r = run("fleetmap", "robot remove sec_d");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // The account is gone and its connections were ended.
    EXPECT_EQ(scalar("SELECT COUNT(*) FROM mysql.user WHERE user = 'sec_d'"), 0);
    EXPECT_TRUE(wait_until([] {
      return scalar("SELECT COUNT(*) FROM information_schema.PROCESSLIST WHERE USER = 'sec_d'") == 0;
    }, 5s));
    EXPECT_NE(sql_error(d.connection(), "SELECT COUNT(*) FROM sa_mine"), 0u);
    EXPECT_NE(sql_error(d2.connection(), "INSERT INTO rr (op, params) VALUES ('Alive', '{}')"), 0u);
    EXPECT_FALSE(can_login("sec_d", pw));
  }
  // Its history stays; its mailbox does not.
  EXPECT_EQ(scalar(trajectory), before + 3);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM v_trajectory_points WHERE robot = 'sec_d'"), before + 3);
  EXPECT_EQ(scalar("SELECT removed_at IS NOT NULL FROM robots WHERE id = " + id), 1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM sa WHERE db_user = 'sec_d'"), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'sec_d'"), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM v_robot_status WHERE name = 'sec_d'"), 0);
  // A second remove is refused (no robot of that name).
  EXPECT_NE(run("fleetmap", "robot remove sec_d").exit_code, 0);
}

}  // namespace
}  // namespace fleetmap::test
