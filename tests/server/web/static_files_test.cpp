// Static files (server/web/http/static_files.h): what stays inside its folder and what
// does not, on a scratch tree with a sibling folder, a symlink out and a nested file.
#include "server/web/http/static_files.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <unistd.h>

namespace fleetmap::web {
namespace {
namespace fs = std::filesystem;

class StaticFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    base_ = fs::temp_directory_path() / ("fleetmap_static_test_" + std::to_string(::getpid()));
    fs::remove_all(base_);
    fs::create_directories(base_ / "console" / "js");
    fs::create_directories(base_ / "console2");
    write(base_ / "console" / "index.html");
    write(base_ / "console" / "js" / "app.js");
    write(base_ / "console2" / "secret.txt");
    write(base_ / "secret.txt");
    fs::create_symlink(base_ / "secret.txt", base_ / "console" / "link.txt");
    root_ = (base_ / "console").string();
  }
  void TearDown() override { fs::remove_all(base_); }
  static void write(const fs::path& p) { std::ofstream(p) << "x"; }
  fs::path base_;
  std::string root_;
};

TEST_F(StaticFiles, ServesFilesInside) {
  EXPECT_EQ(safe_file(root_, "index.html"), fs::canonical(base_ / "console" / "index.html").string());
  EXPECT_EQ(safe_file(root_, "js/app.js"), fs::canonical(base_ / "console" / "js" / "app.js").string());
  EXPECT_EQ(safe_file(root_ + "/", "index.html"), fs::canonical(base_ / "console" / "index.html").string());
}

TEST_F(StaticFiles, RefusesEscapes) {
  EXPECT_EQ(safe_file(root_, "../secret.txt"), std::nullopt);
  EXPECT_EQ(safe_file(root_, "js/../../secret.txt"), std::nullopt);
  EXPECT_EQ(safe_file(root_, "js/.."), std::nullopt);
  EXPECT_EQ(safe_file(root_, "../console2/secret.txt"), std::nullopt);  // a sibling sharing the prefix
  EXPECT_EQ(safe_file(root_, "/etc/passwd"), std::nullopt);
  EXPECT_EQ(safe_file(root_, "link.txt"), std::nullopt);  // a symlink out of the folder
  EXPECT_EQ(safe_file(root_, std::string("index.html\0.png", 15)), std::nullopt);
  EXPECT_EQ(safe_file(root_, "..\\secret.txt"), std::nullopt);
}

TEST_F(StaticFiles, RefusesWhatIsNotAFile) {
  EXPECT_EQ(safe_file(root_, "js"), std::nullopt);
  EXPECT_EQ(safe_file(root_, ""), std::nullopt);
  EXPECT_EQ(safe_file(root_, "missing.js"), std::nullopt);
  EXPECT_EQ(safe_file((base_ / "nowhere").string(), "index.html"), std::nullopt);
}

TEST(ContentTypes, ByExtension) {
  EXPECT_EQ(content_type_for("/a/index.html"), "text/html; charset=utf-8");
  EXPECT_EQ(content_type_for("leaflet.js"), "text/javascript; charset=utf-8");
  EXPECT_EQ(content_type_for("leaflet.css"), "text/css; charset=utf-8");
  EXPECT_EQ(content_type_for("images/marker-icon.png"), "image/png");
  EXPECT_EQ(content_type_for("x.svg"), "image/svg+xml");
  EXPECT_EQ(content_type_for("openapi.json"), "application/json");
  EXPECT_EQ(content_type_for("leaflet.js.map"), "application/json");
  EXPECT_EQ(content_type_for("README"), "application/octet-stream");
}

}  // namespace
}  // namespace fleetmap::web
