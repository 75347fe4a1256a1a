// Under AddressSanitizer (FLEETMAP_SANITIZE) the programs an integration test runs write
// their ASan/LSan/UBSan reports to files of their own: their stderr mostly goes to
// scratch logs that no assertion reads, and a test expecting a failing exit code would
// pass on a sanitizer abort. At the end of the test process (one test under CTest) any
// such report fails it and is printed. This process's own reports still go to stderr.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#if defined(__SANITIZE_ADDRESS__)
#define FLEETMAP_TESTS_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FLEETMAP_TESTS_UNDER_ASAN 1
#endif
#endif

#ifdef FLEETMAP_TESTS_UNDER_ASAN
namespace fleetmap::test {
namespace {

namespace fs = std::filesystem;

class ChildSanitizerReports : public ::testing::Environment {
 public:
  explicit ChildSanitizerReports(fs::path dir) : dir_(std::move(dir)) {}

  void SetUp() override { fs::create_directories(dir_); }

  void TearDown() override {
    std::error_code ec;
    for (const auto& f : fs::directory_iterator(dir_, ec)) {
      std::ifstream in(f.path());
      std::ostringstream text;
      text << in.rdbuf();
      ADD_FAILURE() << "a program run by this test wrote a sanitizer report (" << f.path().filename().string()
                    << "):\n" << text.str();
    }
    fs::remove_all(dir_, ec);
  }

 private:
  fs::path dir_;
};

// The runtime has read this process's options already; setenv changes only the children's.
void append_option(const char* variable, const std::string& option) {
  const char* old = std::getenv(variable);
  const std::string value = old && *old ? std::string(old) + ":" + option : option;
  setenv(variable, value.c_str(), 1);
}

const bool registered = [] {
  const fs::path dir = fs::path(FLEETMAP_BIN_DIR).parent_path() / "sanitizer-reports" / std::to_string(getpid());
  // log_path=P writes P.<pid>; ASan, LSan and UBSan share the option.
  append_option("ASAN_OPTIONS", "log_path=" + (dir / "report").string());
  append_option("UBSAN_OPTIONS", "log_path=" + (dir / "report").string());
  ::testing::AddGlobalTestEnvironment(new ChildSanitizerReports(dir));
  return true;
}();

}  // namespace
}  // namespace fleetmap::test
#endif
