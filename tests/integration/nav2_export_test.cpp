// fleetmap map nav2: the real program on the example room (map + objects imported with
// the real program); the PGMs are read back here. The keep-out mask is black exactly on
// the avoided areas (hand-checked cells, and every cell against the polygons), the grid
// differs between two laser heights where the table's legs and top are, and --robot
// reads the robot's laser height from its profile.
#include <cmath>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "common/geometry/polygon.h"
#include "common/io/scene_geojson.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

const std::string kRoom = "nav2_room";
constexpr double kRes = 0.1;

void import_room() {
  RunResult r = run("fleetmap", "map import " + source_path("maps/example-room.map") + " --name " + kRoom + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("fleetmap", "objects import " + kRoom + " " + source_path("maps/example-room.geojson") + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

// A P5 image read back: pixel(x, y) of the cell holding map point (x, y); the border
// -0.5..15.5 gives the origin (-0.5, -0.5).
struct Pgm {
  int width = 0, height = 0;
  std::string pixels;
  explicit Pgm(const std::string& text) {
    std::istringstream in(text);
    std::string magic;
    int maxval = 0;
    in >> magic >> width >> height >> maxval;
    in.get();  // the single whitespace before the raster
    EXPECT_EQ(magic, "P5");
    EXPECT_EQ(maxval, 255);
    pixels = text.substr(static_cast<size_t>(in.tellg()));
    EXPECT_EQ(pixels.size(), static_cast<size_t>(width) * height);
  }
  int cell(int col, int row) const {  // row 0 at the bottom (min y), the image's last line
    return static_cast<unsigned char>(pixels[static_cast<size_t>(height - 1 - row) * width + col]);
  }
  int at(double x, double y) const {
    return cell(static_cast<int>(std::floor((x + 0.5) / kRes)), static_cast<int>(std::floor((y + 0.5) / kRes)));
  }
};

RunResult nav2(const std::string& args) { return run("fleetmap", "map nav2 " + kRoom + " " + args); }

TEST(Nav2Export, KeepoutMaskIsTheAvoidedAreas) {
  import_room();
  const std::string base = temp_path("nav2-room");
  RunResult r = nav2("--laser-height 0.38 --resolution 0.1 -o " + base);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto grid_yaml = yaml_fields(read_file(base + ".yaml"));
  const auto mask_yaml = yaml_fields(read_file(base + "_keepout.yaml"));
  EXPECT_EQ(grid_yaml.at("image"), "\"nav2-room.pgm\"");
  EXPECT_EQ(grid_yaml.at("mode"), "trinary");
  EXPECT_EQ(mask_yaml.at("image"), "\"nav2-room_keepout.pgm\"");
  EXPECT_EQ(mask_yaml.at("mode"), "scale");  // as Nav2's keepout tutorial loads its mask
  EXPECT_EQ(mask_yaml.at("negate"), "0");
  // The mask lies on the grid's cells: same origin, resolution and size.
  EXPECT_EQ(mask_yaml.at("origin"), grid_yaml.at("origin"));
  EXPECT_EQ(mask_yaml.at("resolution"), grid_yaml.at("resolution"));
  EXPECT_EQ(grid_yaml.at("origin"), "[-0.5, -0.5, 0.0]");
  const Pgm grid(read_file(base + ".pgm")), mask(read_file(base + "_keepout.pgm"));
  EXPECT_EQ(mask.width, grid.width);
  EXPECT_EQ(mask.height, grid.height);
  EXPECT_EQ(grid.width, 161);  // 16 m at 0.1 m: floor(160) + 1
  // Hand-checked cells. The L-shaped keep-out zone (2,9) (4,9) (4,10) (3,10) (3,12) (2,12):
  EXPECT_EQ(mask.at(2.55, 9.55), 0);
  EXPECT_EQ(mask.at(3.55, 9.55), 0);
  EXPECT_EQ(mask.at(2.55, 11.55), 0);
  EXPECT_EQ(mask.at(3.55, 10.55), 254);  // the L's notch
  EXPECT_EQ(mask.at(1.85, 10.55), 254);  // west of it
  EXPECT_EQ(mask.at(5.05, 5.05), 0);     // column-1 4.8..5.2
  EXPECT_EQ(mask.at(6.55, -0.15), 0);    // south wall, west part 0..7
  EXPECT_EQ(mask.at(7.45, -0.15), 254);  // the door's opening 7..8: no avoided area
  EXPECT_EQ(mask.at(15.05, 7.55), 0);    // east wall 15..15.2
  EXPECT_EQ(mask.at(7.45, 7.45), 254);   // under the big table: an obstacle, not avoided
  EXPECT_EQ(mask.at(15.35, 7.55), 254);  // outside the walls, within the border
  // In the grid the keep-out zone is free (a keep-out zone is not a wall) and the
  // columns are their outlines.
  EXPECT_EQ(grid.at(2.55, 9.55), 254);
  // Column-1's west edge x = 4.8 is a grid line up to rounding: (4.8 + 0.5) / 0.1 is
  // 52.99999999999999, so its cell is column 52; either side, it is one cell thick.
  EXPECT_TRUE(grid.at(4.75, 5.05) == 0 || grid.at(4.85, 5.05) == 0);
  EXPECT_EQ(grid.at(5.05, 5.05), 254);  // inside the column: its outline only
  // Every cell: black where its centre is inside an avoided area; white where the whole
  // cell is off every area (centre farther than half a diagonal); only 0 or 254.
  const Scene scene = read_scene_geojson(read_file(source_path("maps/example-room.geojson")));
  size_t black = 0, checked = 0;
  for (int row = 0; row < mask.height; ++row)
    for (int col = 0; col < mask.width; ++col) {
      const Point c{-0.5 + (col + 0.5) * kRes, -0.5 + (row + 0.5) * kRes};
      double d = 1e9;
      bool inside = false;
      for (const AvoidedArea& a : scene.avoided) {
        inside = inside || point_in_polygon(c, a.area);
        d = std::min(d, distance_to_polygon(c, a.area));
      }
      const int v = mask.cell(col, row);
      ASSERT_TRUE(v == 0 || v == 254) << col << "," << row;
      black += v == 0;
      if (inside) {
        EXPECT_EQ(v, 0) << "inside at " << c.x << "," << c.y;
        ++checked;
      } else if (d > kRes * 0.7072) {
        EXPECT_EQ(v, 254) << "outside at " << c.x << "," << c.y;
        ++checked;
      }
    }
  EXPECT_GT(checked, 161u * 161 * 9 / 10);
  EXPECT_GT(black, 0u);
  EXPECT_NE(r.err.find("10 avoided areas"), std::string::npos) << r.err;
}

TEST(Nav2Export, GridFollowsTheLaserHeightAndTheRobotsProfile) {
  import_room();
  const std::string low = temp_path("nav2-low"), high = temp_path("nav2-high");
  ASSERT_EQ(nav2("--laser-height 0.38 --resolution 0.1 -o " + low).exit_code, 0);
  ASSERT_EQ(nav2("--laser-height 0.74 --resolution 0.1 -o " + high).exit_code, 0);
  const Pgm lo(read_file(low + ".pgm")), hi(read_file(high + ".pgm"));
  // The big table's north-east leg x 8.39..8.45, y 7.89..7.95 (0..0.72 m): inside the
  // top's outline x 6.5..8.5, y 7..8 (0.72..0.76 m), which is drawn as its outline only.
  EXPECT_EQ(lo.at(8.35, 7.85), 0);
  EXPECT_EQ(hi.at(8.35, 7.85), 254);
  // The top's south edge y = 7 away from the legs: only at 0.74 m.
  EXPECT_EQ(lo.at(7.55, 7.05), 254);
  EXPECT_EQ(hi.at(7.55, 7.05), 0);
  // Box-1 (0..0.5 m), x 1..1.6, y 1..1.4: its west edge only at 0.38 m.
  EXPECT_EQ(lo.at(1.05, 1.15), 0);
  EXPECT_EQ(hi.at(1.05, 1.15), 254);
  // The walls and the cupboard (0..2 m) at both heights.
  EXPECT_EQ(lo.at(15.05, 7.55), 0);
  EXPECT_EQ(hi.at(15.05, 7.55), 0);
  EXPECT_EQ(lo.at(1.55, 14.55), 0);
  EXPECT_EQ(hi.at(1.55, 14.55), 0);
  // The masks do not depend on the height.
  EXPECT_EQ(read_file(low + "_keepout.pgm"), read_file(high + "_keepout.pgm"));
  // --robot: the profile's laser height, or 0.3 m when it has none.
  add_robot("nav2_bot", kRoom);
  const std::string by_robot = temp_path("nav2-robot"), by_height = temp_path("nav2-03");
  ASSERT_EQ(nav2("--robot nav2_bot --resolution 0.1 -o " + by_robot).exit_code, 0);
  ASSERT_EQ(nav2("--laser-height 0.3 --resolution 0.1 -o " + by_height).exit_code, 0);
  EXPECT_EQ(read_file(by_robot + ".pgm"), read_file(by_height + ".pgm"));
  admin()->query("UPDATE robots SET laser_height = 0.74 WHERE db_user = 'nav2_bot'").execute();
  RunResult r = nav2("--robot nav2_bot --resolution 0.1 -o " + by_robot);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("hL 0.74 m (robot nav2_bot)"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(by_robot + ".pgm"), read_file(high + ".pgm"));
  EXPECT_EQ(read_file(by_robot + ".yaml"), read_file(high + ".yaml").replace(read_file(high + ".yaml").find("nav2-high"), 9, "nav2-robot"));
}

TEST(Nav2Export, Errors) {
  import_room();
  const std::string out = temp_path("nav2-err");
  EXPECT_EQ(nav2("--robot no_such_robot_xyz -o " + out).exit_code, 4);
  EXPECT_EQ(run("fleetmap", "map nav2 no_such_map_xyz --laser-height 0.3 -o " + out).exit_code, 4);
  EXPECT_EQ(nav2("-o " + out).exit_code, 2);                                      // neither
  EXPECT_EQ(nav2("--robot a --laser-height 0.3 -o " + out).exit_code, 64);        // both
  EXPECT_EQ(nav2("--laser-height 0.3").exit_code, 64);                            // no -o
  EXPECT_EQ(nav2("--laser-height 0.3 --resolution 0.00001 -o " + out).exit_code, 2);  // too many cells
  EXPECT_EQ(run("fleetmap", "map nav2 --help").exit_code, 0);
}

}  // namespace
}  // namespace fleetmap::test
