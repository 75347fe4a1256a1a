// The example map maps/example-campus.map: it reads, it uses every shape type of
// seed 000 eq. (2), and it is written in canonical form (docs/map-format.md).
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "common/map/map_validation.h"
#include "common/io/seed_format.h"

namespace fleetmap {
namespace {

const std::string kExample = FLEETMAP_SOURCE_DIR "/maps/example-campus.map";

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << path;
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(ExampleMap, Reads) {
  const Map m = read_seed_file(kExample);
  EXPECT_EQ(m.border, (Border{0, 40, 60, 0}));
  EXPECT_EQ(m.obstacles.size(), 7u);
  EXPECT_EQ(m.segment_count(), 41u);
  EXPECT_NO_THROW(validate_map(m));
}

TEST(ExampleMap, UsesEveryShapeType) {
  const Map m = read_seed_file(kExample);
  std::set<int> types;
  for (const Obstacle& o : m.obstacles) types.insert(static_cast<int>(o.type));
  EXPECT_EQ(types, (std::set<int>{1, 2, 3, 4, 5, 6}));
  for (const Obstacle& o : m.obstacles) {
    if (o.type == ShapeType::ClosedCurved || o.type == ShapeType::OpenCurved) {
      EXPECT_GE(o.segments.size(), 6u) << "obstacle " << o.id;
      for (const Segment& s : o.segments) EXPECT_LT(s.length(), 2.5) << "obstacle " << o.id;
    }
  }
}

TEST(ExampleMap, HasBuildingsWithSemanticsAndOneNote) {
  const Map m = read_seed_file(kExample);
  ASSERT_GE(m.obstacles.size(), 2u);
  EXPECT_EQ(m.obstacles[0].semantic, "building,library");
  EXPECT_EQ(m.obstacles[0].segments[0].semantic, "wall,brick");
  size_t notes = 0;
  for (const Obstacle& o : m.obstacles)
    for (const Segment& s : o.segments)
      if (!s.note.empty()) {
        ++notes;
        EXPECT_EQ(s.note, "main entrance, automatic doors");
        EXPECT_EQ(s.semantic, "door,glass");
      }
  EXPECT_EQ(notes, 1u);
}

TEST(ExampleMap, IsCanonical) {
  const std::string bytes = slurp(kExample);
  ASSERT_FALSE(bytes.empty());
  EXPECT_EQ(bytes.find('\r'), std::string::npos);
  EXPECT_EQ(bytes.back(), '\n');
  const Map m = read_seed(bytes, kExample);
  EXPECT_EQ(write_seed(m), bytes);
  EXPECT_EQ(read_seed(write_seed(m)), m);
}

TEST(ExampleMap, ReadsWithCrlfAndBlankLines) {
  const std::string bytes = slurp(kExample);
  std::string crlf;
  for (char c : bytes) {
    if (c == '\n') crlf += "\r\n\r\n";
    else crlf += c;
  }
  EXPECT_EQ(read_seed(crlf), read_seed(bytes));
  EXPECT_EQ(write_seed(read_seed(crlf)), bytes);
}

}  // namespace
}  // namespace fleetmap
