// read_map_file (common/io/read_map_file.h): the format follows the file's name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "common/io/read_map_file.h"
#include "common/io/seed_format.h"

namespace fleetmap {
namespace {

namespace fs = std::filesystem;

// Two AMRL walls forming one open chain: (0,0)-(4,0)-(4,3).
constexpr const char* kAmrlText = "0, 0, 4, 0\n4, 0, 4, 3\n";

std::string write_temp(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("read_map_file_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

TEST(MapFileFormat, AmrlOnlyWhenTheNameEndsInVectormapTxt) {
  EXPECT_EQ(map_file_format("maps/amrl/GDC1.vectormap.txt"), MapFileFormat::Amrl);
  EXPECT_EQ(map_file_format(".vectormap.txt"), MapFileFormat::Amrl);
  EXPECT_EQ(map_file_format("maps/example-room.map"), MapFileFormat::Seed);
  EXPECT_EQ(map_file_format("GDC1.vectormap.txt.bak"), MapFileFormat::Seed);
  EXPECT_EQ(map_file_format("GDC1.vectormap"), MapFileFormat::Seed);
  EXPECT_EQ(map_file_format("GDC1.txt"), MapFileFormat::Seed);
  EXPECT_EQ(map_file_format("GDC1.VECTORMAP.TXT"), MapFileFormat::Seed);  // case-sensitive
  EXPECT_EQ(map_file_format(""), MapFileFormat::Seed);
}

TEST(ReadMapFile, AmrlFileUsesTheGivenOptions) {
  const std::string path = write_temp("walls.vectormap.txt", kAmrlText);
  AmrlOptions o;
  o.height = 3.5;
  o.margin = 2.0;
  o.semantic = "fence";
  AmrlReport report;
  const Map m = read_map_file(path, o, &report);
  EXPECT_EQ(report.segments, 2u);
  ASSERT_EQ(m.segment_count(), 2u);
  for (const Obstacle& ob : m.obstacles)
    for (const Segment& s : ob.segments) {
      EXPECT_EQ(s.h, 3.5);
      EXPECT_EQ(s.semantic, "fence");
    }
  // Border: the walls' box (0..4 x 0..3) grown by the margin.
  const Rect b = m.border.rect();
  EXPECT_DOUBLE_EQ(b.xmin, -2.0);
  EXPECT_DOUBLE_EQ(b.ymin, -2.0);
  EXPECT_DOUBLE_EQ(b.xmax, 6.0);
  EXPECT_DOUBLE_EQ(b.ymax, 5.0);
}

TEST(ReadMapFile, AmrlDefaultsAreAmrlOptionsDefaults) {
  const Map m = read_map_file(write_temp("default.vectormap.txt", kAmrlText));
  ASSERT_FALSE(m.obstacles.empty());
  EXPECT_EQ(m.obstacles.front().segments.front().h, AmrlOptions{}.height);
}

TEST(ReadMapFile, OtherNamesAreSeedFormat) {
  const std::string example = FLEETMAP_SOURCE_DIR "/maps/example-room.map";
  EXPECT_EQ(read_map_file(example), read_seed_file(example));
  // AMRL text under another name is read as seed format, and refused as such.
  const std::string path = write_temp("walls.txt", kAmrlText);
  try {
    read_map_file(path);
    FAIL() << "AMRL text read as a seed map";
  } catch (const MapFormatError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 1u);
  }
}

TEST(ReadMapFile, MissingFileIsAnError) {
  EXPECT_THROW(read_map_file("/nonexistent/x.vectormap.txt"), std::exception);
  EXPECT_THROW(read_map_file("/nonexistent/x.map"), std::exception);
}

}  // namespace
}  // namespace fleetmap
