// fleetmap map slice: the real program on a stored map (and the same file without the
// database): hand-checked slices in the seed format, a Nav2 PGM + YAML read back here,
// and the error paths.
#include <cmath>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "common/io/seed_format.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

const Obstacle& by_id(const Map& m, int id) {
  for (const Obstacle& o : m.obstacles)
    if (o.id == id) return o;
  throw std::runtime_error("no obstacle " + std::to_string(id));
}

TEST(MapSliceCommand, SeedSliceOfAStoredMap) {
  ensure_example_map("slice_map");
  RunResult r = run("fleetmap", "map slice slice_map --height 0.5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("slice of 'slice_map' at 0.5 m"), std::string::npos) << r.err;
  const Map s = read_seed(r.out, "slice", MapKind::Window);
  // At 0.5 m: the bench (0.45 m) is gone, the steps of 0.6 and 0.75 m and the closing
  // segment stay, the ramp (0.5 m at its top x = 12) is its top edge.
  EXPECT_EQ(s.obstacles.size(), 6u);
  for (const Obstacle& o : s.obstacles) EXPECT_NE(o.id, 5);
  const Obstacle& stairs = by_id(s, 6);
  ASSERT_EQ(stairs.segments.size(), 3u);
  EXPECT_EQ(stairs.segments[0].h, 0.6);
  EXPECT_EQ(stairs.segments[2].h, 0);
  const Obstacle& ramp = by_id(s, 7);
  EXPECT_EQ(ramp.type, ShapeType::OpenPolygon);
  for (const Segment& g : ramp.segments) {
    EXPECT_EQ(g.a.x, 12);
    EXPECT_EQ(g.b.x, 12);
  }
  // The stored map and the file give the same slice.
  RunResult f = run("fleetmap", "map slice --file " + source_path("maps/example-campus.map") + " --height 0.5");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  EXPECT_EQ(f.out, r.out);
  // -o writes the same text to a file.
  const std::string out = temp_path("slice-0.5.map");
  ASSERT_EQ(run("fleetmap", "map slice slice_map --height 0.5 -o " + out).exit_code, 0);
  EXPECT_EQ(read_file(out), r.out);
}

TEST(MapSliceCommand, Nav2GridOfAStoredMap) {
  ensure_example_map("slice_map");
  const std::string base = temp_path("slice-grid");
  RunResult r = run("fleetmap", "map slice slice_map --height 0.3 --format pgm --resolution 0.25 -o " + base + ".pgm");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  const auto kv = yaml_fields(read_file(base + ".yaml"));
  EXPECT_EQ(kv.at("image"), "\"slice-grid.pgm\"");  // relative to the YAML, which is beside it
  EXPECT_EQ(kv.at("mode"), "trinary");
  EXPECT_EQ(kv.at("resolution"), "0.25");
  EXPECT_EQ(kv.at("origin"), "[0, 0, 0.0]");  // the border's lower-left corner
  // Border 60 x 40 m at 0.25 m: 241 x 161 cells (the last column holds x = 60).
  const std::string pgm = read_file(base + ".pgm");
  const std::string header = "P5\n241 161\n255\n";
  ASSERT_EQ(pgm.substr(0, header.size()), header);
  ASSERT_EQ(pgm.size(), header.size() + 241u * 161u);
  auto px = [&](double x, double y) {
    const size_t col = static_cast<size_t>(std::floor(x / 0.25)), row = static_cast<size_t>(std::floor(y / 0.25));
    return static_cast<unsigned char>(pgm[header.size() + (160 - row) * 241 + col]);  // top line first
  };
  EXPECT_EQ(px(5.1, 30), 0);      // library west wall x = 5
  EXPECT_EQ(px(58.1, 20), 0);     // fence x = 58 (1.8 m)
  EXPECT_EQ(px(30.1, 14.05), 0);  // bench (0.45 m) at (30, 14)
  EXPECT_EQ(px(47.1, 19.15), 0);  // step 0.45 m at y = 19.1
  EXPECT_EQ(px(47.1, 18.55), 254);  // step 0.15 m at y = 18.5 passes under the laser
  EXPECT_EQ(px(47.1, 20.1), 254);   // closing segment y = 20: not an obstacle in 2D
  EXPECT_EQ(px(10.45, 11), 0);      // ramp surface at 0.3 m: x = 10.4
  EXPECT_EQ(px(9, 11), 254);
  EXPECT_EQ(px(25, 8), 254);        // open ground
  // Without the database: the same grid from the file.
  const std::string base2 = temp_path("slice-grid-file");
  ASSERT_EQ(run("fleetmap", "map slice --file " + source_path("maps/example-campus.map") +
                                " --height 0.3 --format pgm --resolution 0.25 -o " + base2)
                .exit_code,
            0);
  EXPECT_EQ(read_file(base2 + ".pgm"), pgm);
}

TEST(MapSliceCommand, Errors) {
  EXPECT_EQ(run("fleetmap", "map slice no_such_map_xyz --height 0.3").exit_code, 4);
  RunResult r = run("fleetmap", "map slice --file " + source_path("maps/example-campus.map") + " --height 0.3 --format pgm");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("expected -o OUTPUT"), std::string::npos) << r.err;
  r = run("fleetmap", "map slice --file " + source_path("maps/example-campus.map") +
                          " --height 0.3 --format pgm --resolution 0.0001 -o " + temp_path("huge"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("coarser resolution"), std::string::npos) << r.err;
  EXPECT_EQ(run("fleetmap", "map slice --file " + source_path("maps/example-campus.map")).exit_code, 64);  // no --height
  EXPECT_EQ(run("fleetmap", "map slice --file " + source_path("maps/example-campus.map") + " --height -1").exit_code, 64);
  EXPECT_EQ(run("fleetmap", "map slice --height 1").exit_code, 2);  // neither NAME nor --file
  EXPECT_EQ(run("fleetmap", "map slice --help").exit_code, 0);
}

}  // namespace
}  // namespace fleetmap::test
