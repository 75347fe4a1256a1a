// fleetmap scan and fleetmap map slice include the map's objects (docs/semantic-layer.md): the example
// room (maps/example-room.map + example-room.geojson) imported with the real program, a
// scan through the big table at two laser heights (legs vs top) against ranges worked
// out by hand, and slices at two heights that differ by exactly the expected outlines.
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "common/io/seed_format.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

const std::string kRoom = "scan_objects_room";

void import_room() {
  RunResult r = run("fleetmap", "map import " + source_path("maps/example-room.map") + " --name " + kRoom + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("fleetmap", "objects import " + kRoom + " " + source_path("maps/example-room.geojson") + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

// The range of a single beam (--beams 1 --fov 0) from the command's output.
double one_range(const RunResult& r) {
  std::istringstream in(r.out);
  double angle = 0, range = -1;
  in >> angle >> range;
  return range;
}

double scan_east(const std::string& where, double y, double height, const std::string& extra = "") {
  std::ostringstream args;
  args << "scan " << where << " 3 " << y << " 0 --beams 1 --fov 0 --height " << height << " " << extra;
  RunResult r = run("fleetmap", args.str());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return one_range(r);
}

TEST(ScanObjects, TableLegsAndTopAtTwoHeights) {
  import_room();
  const std::string file = "--file " + source_path("maps/example-room.map");
  const std::string objects = " --objects " + source_path("maps/example-room.geojson");
  // East from (3, 7.08): the big table's south-west leg is x = 6.55..6.61, y = 7.05..7.11
  // (0..0.72 m); its top x = 6.5..8.5, y = 7..8 (0.72..0.76 m); the east wall's inner
  // face x = 15. No column or chair lies on y = 7.08.
  for (const std::string& where : {kRoom, file + objects}) {
    SCOPED_TRACE(where);
    EXPECT_NEAR(scan_east(where, 7.08, 0.38), 3.55, 1e-9);  // the leg
    EXPECT_NEAR(scan_east(where, 7.08, 0.74), 3.50, 1e-9);  // the top's west edge
    EXPECT_NEAR(scan_east(where, 7.08, 0.90), 12.0, 1e-9);  // over both: the wall
    // y = 7.5 passes between the legs (y 7.05..7.11 and 7.89..7.95) under the top.
    EXPECT_NEAR(scan_east(where, 7.5, 0.38), 12.0, 1e-9);
    EXPECT_NEAR(scan_east(where, 7.5, 0.74), 3.50, 1e-9);
  }
  // The bare segments: --no-objects, or a file without --objects.
  EXPECT_NEAR(scan_east(kRoom, 7.08, 0.38, "--no-objects"), 12.0, 1e-9);
  EXPECT_NEAR(scan_east(kRoom, 7.5, 0.74, "--no-objects"), 12.0, 1e-9);
  EXPECT_NEAR(scan_east(file, 7.08, 0.38), 12.0, 1e-9);
  // The seed's bounding-circle caster sees the objects too.
  EXPECT_NEAR(scan_east(kRoom, 7.08, 0.38, "--method seed"), 3.55, 1e-9);
  // Usage errors: --objects with a stored map, --objects with --no-objects.
  EXPECT_EQ(run("fleetmap", "scan " + kRoom + " 3 7 0" + objects).exit_code, 2);
  EXPECT_EQ(run("fleetmap", "scan " + file + " 3 7 0 --no-objects" + objects).exit_code, 2);
}

// Obstacles whose semantic starts with "object:", counted by semantic.
std::map<std::string, int> object_outlines(const Map& slice) {
  std::map<std::string, int> n;
  for (const Obstacle& o : slice.obstacles)
    if (o.semantic.rfind("object:", 0) == 0) ++n[o.semantic];
  return n;
}

Map slice(const std::string& args) {
  RunResult r = run("fleetmap", "map slice " + args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_seed(r.out, "slice", MapKind::Window);
}

TEST(ScanObjects, SlicesAtTwoHeightsDifferByTheObjects) {
  import_room();
  const Map low = slice(kRoom + " --height 0.38"), high = slice(kRoom + " --height 0.74");
  auto lo = object_outlines(low), hi = object_outlines(high);
  // Seen at both heights: the door (0..2.1), the small table (0..0.75), the cupboards
  // (0..2), the shelves' two side panels (0..1.8) each, the trolley (0..0.9), the plant (2D).
  for (const auto& [semantic, n] :
       std::map<std::string, int>{{"object:door:door-1", 1},       {"object:table:small-table", 1},
                                  {"object:cupboard:cupboard-1", 1}, {"object:cupboard:cupboard-2", 1},
                                  {"object:shelf:shelf-1", 2},       {"object:shelf:shelf-2", 2},
                                  {"object:trolley:trolley-1", 1},   {"object:plant:plant-1", 1}}) {
    EXPECT_EQ(lo[semantic], n) << semantic;
    EXPECT_EQ(hi[semantic], n) << semantic;
  }
  // At 0.38 m only: the big table's four legs, each chair's four legs, the three boxes
  // (0.5, 0.4 and 0.6 m tall); the charging station (0..0.3) is under both lasers.
  EXPECT_EQ(lo["object:table:big-table"], 4);
  for (const char* chair : {"object:chair:chair-1", "object:chair:chair-2", "object:chair:chair-3", "object:chair:chair-4"}) {
    EXPECT_EQ(lo[chair], 4) << chair;
    EXPECT_EQ(hi[chair], 1) << chair;  // at 0.74 m: the backrest (0.47..0.9) only
  }
  for (const char* box : {"object:box:box-1", "object:box:box-2", "object:box:box-3"}) {
    EXPECT_EQ(lo[box], 1) << box;
    EXPECT_EQ(hi.count(box), 0u) << box;
  }
  EXPECT_EQ(lo.count("object:charging_station:charger-1"), 0u);
  EXPECT_EQ(hi.count("object:charging_station:charger-1"), 0u);
  // At 0.74 m: the big table is its top, the rectangle x 6.5..8.5, y 7..8, as high as 0.76 m.
  EXPECT_EQ(hi["object:table:big-table"], 1);
  for (const Obstacle& o : high.obstacles) {
    if (o.semantic != "object:table:big-table") continue;
    ASSERT_EQ(o.segments.size(), 4u);
    for (const Segment& g : o.segments) {
      EXPECT_EQ(g.h, 0.76);
      EXPECT_TRUE(g.a.x == 6.5 || g.a.x == 8.5) << g.a.x;
      EXPECT_TRUE(g.a.y == 7 || g.a.y == 8) << g.a.y;
    }
  }
  size_t lo_total = 0, hi_total = 0;
  for (const auto& [s, n] : lo) lo_total += n;
  for (const auto& [s, n] : hi) hi_total += n;
  EXPECT_EQ(lo_total, 10u + 4 + 16 + 3);  // 33 elements seen at 0.38 m
  EXPECT_EQ(hi_total, 10u + 1 + 4);       // 15 at 0.74 m
  // The walls and columns are the same in both slices (all 2.5 m high).
  EXPECT_EQ(low.obstacles.size() - lo_total, 9u);
  EXPECT_EQ(high.obstacles.size() - hi_total, 9u);
  // --no-objects: the bare slice; the file with --objects gives the stored map's slice.
  EXPECT_TRUE(object_outlines(slice(kRoom + " --height 0.38 --no-objects")).empty());
  RunResult stored = run("fleetmap", "map slice " + kRoom + " --height 0.74");
  RunResult file = run("fleetmap", "map slice --file " + source_path("maps/example-room.map") + " --objects " +
                                       source_path("maps/example-room.geojson") + " --height 0.74");
  ASSERT_EQ(file.exit_code, 0) << file.err;
  EXPECT_EQ(file.out, stored.out);
}

}  // namespace
}  // namespace fleetmap::test
