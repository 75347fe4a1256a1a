// app/maps_dir.*: the real maps' folder is $FLEETMAP_MAPS_DIR when set and not empty,
// else the folder configured at build time (the CMake cache variable FLEETMAP_MAPS_DIR,
// which the tests also receive as FLEETMAP_REAL_MAPS).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "app/maps_dir.h"

namespace fleetmap {
namespace {

// Sets or unsets FLEETMAP_MAPS_DIR for one test and restores what was there.
class MapsDirEnv {
 public:
  explicit MapsDirEnv(const char* value) {
    if (const char* old = std::getenv("FLEETMAP_MAPS_DIR")) old_ = old;
    if (value) setenv("FLEETMAP_MAPS_DIR", value, 1);
    else unsetenv("FLEETMAP_MAPS_DIR");
  }
  ~MapsDirEnv() {
    if (old_) setenv("FLEETMAP_MAPS_DIR", old_->c_str(), 1);
    else unsetenv("FLEETMAP_MAPS_DIR");
  }

 private:
  std::optional<std::string> old_;
};

TEST(MapsDir, EnvironmentOverridesTheConfiguredFolder) {
  MapsDirEnv env("/srv/maps/amrl");
  EXPECT_EQ(maps_dir(), "/srv/maps/amrl");
  EXPECT_EQ(real_map_path("GDC1.vectormap.txt"), "/srv/maps/amrl/GDC1.vectormap.txt");
}

// The configured folder, the same one as the tests', and the same files there.
std::filesystem::path configured() { return FLEETMAP_REAL_MAPS; }

TEST(MapsDir, UnsetGivesTheConfiguredFolderWithoutDotDot) {
  MapsDirEnv env(nullptr);
  const std::string dir = maps_dir();
  EXPECT_EQ(dir.find(".."), std::string::npos) << dir;
  EXPECT_TRUE(std::filesystem::equivalent(dir, configured())) << dir << " vs " << configured();
  EXPECT_EQ(real_map_path("UT_Campus.navigation.json"), dir + "/UT_Campus.navigation.json");
}

TEST(MapsDir, EmptyCountsAsUnset) {
  MapsDirEnv env("");
  EXPECT_TRUE(std::filesystem::equivalent(maps_dir(), configured())) << maps_dir();
}

TEST(MapsDir, EnvironmentIsTakenAsGiven) {
  MapsDirEnv env("maps/../elsewhere");
  EXPECT_EQ(maps_dir(), "maps/../elsewhere");
}

}  // namespace
}  // namespace fleetmap
