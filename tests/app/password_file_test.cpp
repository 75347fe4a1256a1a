// app/password_file.h without a database: the mode, the replacement of an old file, the
// refusal of symbolic links, and reading the first line back.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "app/password_file.h"
#include "common/core/error.h"

namespace fleetmap {
namespace {

namespace fs = std::filesystem;

class PasswordFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fleetmap-pw-test-" + std::to_string(getpid()));
    fs::create_directories(dir_);
    old_umask_ = ::umask(022);
  }
  void TearDown() override {
    ::umask(old_umask_);
    fs::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static mode_t mode_of(const std::string& p) {
    struct stat st {};
    EXPECT_EQ(::lstat(p.c_str(), &st), 0) << p;
    return st.st_mode & 07777;
  }
  static std::string content(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  static void put(const std::string& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

  fs::path dir_;
  mode_t old_umask_ = 0;
};

TEST_F(PasswordFile, ANewFileIs0600WithThePasswordAndALineEnd) {
  write_password_file(path("new.pw"), "s3cret");
  EXPECT_EQ(mode_of(path("new.pw")), 0600u);
  EXPECT_EQ(content(path("new.pw")), "s3cret\n");
}

TEST_F(PasswordFile, AnExistingFileBecomes0600AndLosesItsOldContent) {
  put(path("old.pw"), "a much longer old password\nand a second line\n");
  ASSERT_EQ(::chmod(path("old.pw").c_str(), 0644), 0);
  write_password_file(path("old.pw"), "new");
  EXPECT_EQ(mode_of(path("old.pw")), 0600u);
  EXPECT_EQ(content(path("old.pw")), "new\n");
}

TEST_F(PasswordFile, ItsModeIsSetBeforeTheWrite) {
  // Opened (the state while the robot account is created): already 0600, still empty.
  put(path("open.pw"), "old\n");
  ASSERT_EQ(::chmod(path("open.pw").c_str(), 0644), 0);
  {
    PasswordFileOut out(path("open.pw"));
    EXPECT_EQ(mode_of(path("open.pw")), 0600u);
    EXPECT_EQ(content(path("open.pw")), "old\n") << "nothing replaced before write()";
    out.write("pw");
  }
  EXPECT_EQ(content(path("open.pw")), "pw\n");
}

TEST_F(PasswordFile, ASymbolicLinkIsRefusedAndItsTargetUntouched) {
  put(path("target"), "keep\n");
  fs::create_symlink(path("target"), path("link.pw"));
  try {
    write_password_file(path("link.pw"), "pw");
    FAIL() << "expected IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("symbolic link"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path("link.pw")), std::string::npos) << e.what();
  }
  EXPECT_EQ(content(path("target")), "keep\n");
  fs::create_symlink(path("nowhere"), path("dangling.pw"));
  EXPECT_THROW(write_password_file(path("dangling.pw"), "pw"), IoError);
  EXPECT_FALSE(fs::exists(path("nowhere")));
}

TEST_F(PasswordFile, ADirectoryOrAMissingFolderIsAnIoError) {
  EXPECT_THROW(write_password_file(dir_.string(), "pw"), IoError);
  EXPECT_THROW(write_password_file(path("no/such/folder.pw"), "pw"), IoError);
}

TEST_F(PasswordFile, ACreatedFileNeverWrittenIsRemoved) {
  { PasswordFileOut out(path("unused.pw")); }
  EXPECT_FALSE(fs::exists(path("unused.pw")));
  put(path("kept.pw"), "old\n");
  { PasswordFileOut out(path("kept.pw")); }
  EXPECT_EQ(content(path("kept.pw")), "old\n");
}

TEST_F(PasswordFile, ReadingTakesTheFirstLineWithoutItsLineEnd) {
  put(path("crlf.pw"), "abc\r\nsecond\n");
  EXPECT_EQ(read_password_file(path("crlf.pw")), "abc");
  put(path("bare.pw"), "xyz");
  EXPECT_EQ(read_password_file(path("bare.pw")), "xyz");
  EXPECT_THROW(read_password_file(path("missing.pw")), IoError);
}

}  // namespace
}  // namespace fleetmap
