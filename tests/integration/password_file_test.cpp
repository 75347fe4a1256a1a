// fleetmap robot add --password-out F: the generated password lands in F with mode 0600
// from the start, whatever the umask, replacing an old file's content; a symbolic link
// is refused before any account is created. The password in F is the account's.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "protocol/connection.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

class PasswordOut : public ::testing::Test {
 protected:
  void SetUp() override {
    ensure_example_map("pf_map");
    old_umask_ = ::umask(022);  // the usual umask: new files 0644 unless created 0600
    for (const char* r : {"pf_r1", "pf_r2", "pf_r3"}) run("fleetmap", std::string("robot remove ") + r);
  }
  void TearDown() override { ::umask(old_umask_); }

  static mode_t mode_of(const std::string& path) {
    struct stat st {};
    EXPECT_EQ(::lstat(path.c_str(), &st), 0) << path;
    return st.st_mode & 07777;
  }
  // The robot can log in with the password in file.
  static void expect_login(const std::string& robot, const std::string& file) {
    const std::string text = read_file(file);
    ASSERT_EQ(text.size(), 25u) << text;  // 24 characters and a line end
    ASSERT_EQ(text.back(), '\n');
    DbSettings s = tcp_settings(Role::Robot);
    s.user = robot;
    s.password = text.substr(0, 24);
    EXPECT_NO_THROW(connect(s)) << robot;
  }
  static long long accounts(const std::string& robot) {
    return scalar("SELECT COUNT(*) FROM robots WHERE db_user = '" + robot + "' AND removed_at IS NULL");
  }
  mode_t old_umask_ = 0;
};

TEST_F(PasswordOut, ANewFileIsMode0600UnderUmask022) {
  const std::string file = temp_path("pf_r1.pw");
  std::filesystem::remove(file);
  const RunResult r = run("fleetmap", "robot add pf_r1 --map pf_map --password-out " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("password written to " + file), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("password: "), std::string::npos) << "not shown as well: " << r.out;
  EXPECT_EQ(mode_of(file), 0600u);
  expect_login("pf_r1", file);
}

TEST_F(PasswordOut, AnExistingFileIsReplacedAndBecomes0600) {
  const std::string file = temp_path("pf_r2.pw");
  write_file(file, "an old secret, longer than the new password, on two lines\nsecond line\n");
  ASSERT_EQ(::chmod(file.c_str(), 0644), 0);
  const RunResult r = run("fleetmap", "robot add pf_r2 --map pf_map --password-out " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(mode_of(file), 0600u);
  EXPECT_EQ(read_file(file).find("old secret"), std::string::npos);
  expect_login("pf_r2", file);  // exactly one 24-character line
}

TEST_F(PasswordOut, ASymbolicLinkIsRefusedBeforeTheAccountExists) {
  const std::string target = temp_path("pf_target"), link = temp_path("pf_r3.pw");
  write_file(target, "untouched\n");
  std::filesystem::remove(link);
  std::filesystem::create_symlink(target, link);
  const RunResult r = run("fleetmap", "robot add pf_r3 --map pf_map --password-out " + link);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("symbolic link"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(target), "untouched\n");
  EXPECT_EQ(accounts("pf_r3"), 0) << "no account whose password nobody has";
  std::filesystem::remove(link);
}

TEST_F(PasswordOut, AFailedAddLeavesNoEmptyFile) {
  const std::string file = temp_path("pf_nomap.pw");
  std::filesystem::remove(file);
  const RunResult r = run("fleetmap", "robot add pf_r3 --map pf_no_such_map --password-out " + file);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_FALSE(std::filesystem::exists(file)) << r.err;
}

}  // namespace
}  // namespace fleetmap::test
