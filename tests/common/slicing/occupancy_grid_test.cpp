// Occupancy grids (common/slicing/occupancy_grid.h): hand-computed cells of axis-aligned, diagonal
// and steep segments and of filled polygons; a sampled oracle for random segments; the
// PGM and YAML that Nav2's map_server reads, parsed back here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "common/slicing/map_slice.h"
#include "common/slicing/occupancy_grid.h"
#include "common/io/seed_format.h"

namespace fleetmap {
namespace {

using Cell = std::pair<int, int>;  // (col, row)
using Cells = std::set<Cell>;

Cells occupied(const OccupancyGrid& g) {
  Cells s;
  for (int r = 0; r < g.height; ++r)
    for (int c = 0; c < g.width; ++c)
      if (g.at(c, r) == OccupancyGrid::kOccupied) s.insert({c, r});
  return s;
}

// A 10 m x 10 m grid of 1 m cells from (0, 0): 11 x 11 cells (the last holds x = 10).
OccupancyGrid unit_grid() { return make_grid({0, 0, 10, 10}, 1.0); }

Cells segment_cells(Point a, Point b) {
  OccupancyGrid g = unit_grid();
  draw_segment(g, a, b);
  return occupied(g);
}

TEST(OccupancyGrid, Dimensions) {
  const OccupancyGrid g = unit_grid();
  EXPECT_EQ(g.width, 11);
  EXPECT_EQ(g.height, 11);
  EXPECT_EQ(g.origin, (Point{0, 0}));
  EXPECT_EQ(g.cells.size(), 121u);
  EXPECT_TRUE(occupied(g).empty());
  const OccupancyGrid h = make_grid({-2, 1, 3.7, 2.2}, 0.5);  // 5.7 / 0.5 = 11.4, 1.2 / 0.5 = 2.4
  EXPECT_EQ(h.width, 12);
  EXPECT_EQ(h.height, 3);
  EXPECT_EQ(h.origin, (Point{-2, 1}));
}

TEST(OccupancyGrid, AxisAlignedSegments) {
  EXPECT_EQ(segment_cells({0.5, 2.5}, {4.5, 2.5}), (Cells{{0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 2}}));
  // On a grid line: one cell thick, in the row above the line (cells are half-open).
  EXPECT_EQ(segment_cells({1, 3}, {4, 3}), (Cells{{1, 3}, {2, 3}, {3, 3}, {4, 3}}));
  EXPECT_EQ(segment_cells({2, 3.5}, {2, 0.5}), (Cells{{2, 0}, {2, 1}, {2, 2}, {2, 3}}));
  // On the grid's top and right edges: still in the grid.
  EXPECT_EQ(segment_cells({9.5, 10}, {10, 10}), (Cells{{9, 10}, {10, 10}}));
}

TEST(OccupancyGrid, DiagonalSegments) {
  // Slope 1/2 between corners: y = 0.5 + (x - 0.2) / 2 is 0.9 at x = 1, 1.4 at x = 2.
  EXPECT_EQ(segment_cells({0.2, 0.5}, {2.2, 1.5}), (Cells{{0, 0}, {1, 0}, {1, 1}, {2, 1}}));
  // Through the corners (1,1), (2,2), (3,3): the four cells around each (supercover).
  const Cells up{{0, 0}, {0, 1}, {1, 0}, {1, 1}, {1, 2}, {2, 1}, {2, 2}, {2, 3}, {3, 2}, {3, 3}};
  EXPECT_EQ(segment_cells({0.5, 0.5}, {3.5, 3.5}), up);
  EXPECT_EQ(segment_cells({3.5, 3.5}, {0.5, 0.5}), up);  // direction does not matter
  const Cells down{{0, 3}, {0, 2}, {1, 3}, {1, 2}, {1, 1}, {2, 2}, {2, 1}, {2, 0}, {3, 1}, {3, 0}};
  EXPECT_EQ(segment_cells({0.5, 3.5}, {3.5, 0.5}), down);
  // Ending on a corner: no cells beyond the end.
  EXPECT_EQ(segment_cells({0.5, 0.5}, {2, 2}), (Cells{{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 2}}));
}

TEST(OccupancyGrid, SteepSegment) {
  // y = 0.2 + 4.6 (x - 0.5): 2.5 at x = 1.
  EXPECT_EQ(segment_cells({0.5, 0.2}, {1.5, 4.8}), (Cells{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {1, 3}, {1, 4}}));
  EXPECT_EQ(segment_cells({1.5, 4.8}, {0.5, 0.2}), (Cells{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {1, 3}, {1, 4}}));
}

TEST(OccupancyGrid, PartlyOutsideIsClipped) {
  EXPECT_EQ(segment_cells({-3, 0.5}, {1.5, 0.5}), (Cells{{0, 0}, {1, 0}}));
  EXPECT_TRUE(segment_cells({-3, -1}, {-1, -3}).empty());
}

// The closed square of cell (c, r) and segment ab (grid units) share a point.
bool touches(int c, int r, Point a, Point b) {
  double t0 = 0, t1 = 1;
  const Point d = b - a;
  const double p[4] = {-d.x, d.x, -d.y, d.y}, q[4] = {a.x - c, c + 1 - a.x, a.y - r, r + 1 - a.y};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < -1e-9) return false;
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0) t0 = std::max(t0, t - 1e-9);
    else t1 = std::min(t1, t + 1e-9);
  }
  return t0 <= t1;
}

// Random segments at 0.05 m: every sampled point's cell is occupied (no cell missed),
// every occupied cell touches the segment (none too many), and the cells are
// 4-connected (nothing slips between diagonal cells).
TEST(OccupancyGrid, RandomSegmentsAgainstASampledOracle) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.1, 4.9);
  for (int n = 0; n < 300; ++n) {
    OccupancyGrid g = make_grid({0, 0, 5, 5}, 0.05);
    const Point a{u(rng), u(rng)}, b{u(rng), u(rng)};
    draw_segment(g, a, b);
    const Cells cells = occupied(g);
    for (int k = 0; k <= 20000; ++k) {
      const Point p = a + (k / 20000.0) * (b - a);
      const Cell c{static_cast<int>(std::floor(p.x / 0.05)), static_cast<int>(std::floor(p.y / 0.05))};
      ASSERT_TRUE(cells.count(c)) << n << ": missed cell " << c.first << "," << c.second;
    }
    const Point ga{a.x / 0.05, a.y / 0.05}, gb{b.x / 0.05, b.y / 0.05};
    for (const Cell& c : cells) ASSERT_TRUE(touches(c.first, c.second, ga, gb)) << n;
    // 4-connected: a flood fill from one cell reaches all.
    Cells seen{*cells.begin()};
    std::vector<Cell> todo{*cells.begin()};
    while (!todo.empty()) {
      const auto [c, r] = todo.back();
      todo.pop_back();
      for (Cell nb : {Cell{c + 1, r}, Cell{c - 1, r}, Cell{c, r + 1}, Cell{c, r - 1}})
        if (cells.count(nb) && seen.insert(nb).second) todo.push_back(nb);
    }
    ASSERT_EQ(seen.size(), cells.size()) << n << ": not 4-connected";
  }
}

TEST(OccupancyGrid, FilledPolygons) {
  // The right triangle (0,0) (8,0) (0,8): centres (i+.5, j+.5) inside for i + j <= 7; the
  // hypotenuse crosses the corners (i, 8 - i) and adds the cells i + j = 8: 45 cells.
  OccupancyGrid g = unit_grid();
  fill_polygon(g, {{0, 0}, {8, 0}, {0, 8}});
  Cells want;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; i + j <= 8; ++j) want.insert({i, j});
  EXPECT_EQ(occupied(g), want);
  // A square whose outline runs through the outer ring of cells: the inside comes from
  // the centre rule, 36 cells (the outline alone is 20).
  g = unit_grid();
  fill_polygon(g, {{0.3, 0.3}, {5.7, 0.3}, {5.7, 5.7}, {0.3, 5.7}});
  EXPECT_EQ(occupied(g).size(), 36u);
  EXPECT_EQ(g.at(2, 3), OccupancyGrid::kOccupied);
  EXPECT_EQ(g.at(6, 3), OccupancyGrid::kFree);
  // A small diamond around the centre of cell (2, 2): that cell and the four its corners
  // poke into.
  g = unit_grid();
  fill_polygon(g, {{2.5, 1.9}, {3.1, 2.5}, {2.5, 3.1}, {1.9, 2.5}});
  EXPECT_EQ(occupied(g), (Cells{{2, 2}, {1, 2}, {3, 2}, {2, 1}, {2, 3}}));
  // Clockwise works the same; another value (a later keep-out mask) is written as given.
  g = unit_grid();
  fill_polygon(g, {{0, 8}, {8, 0}, {0, 0}}, 42);
  EXPECT_EQ(g.at(3, 3), 42);
  EXPECT_EQ(g.at(5, 5), OccupancyGrid::kFree);
}

TEST(OccupancyGrid, MemoryGuard) {
  try {
    make_grid({0, 0, 20000, 20000}, 0.001);
    FAIL() << "a 4e14-cell grid was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("coarser resolution"), std::string::npos) << e.what();
  }
  EXPECT_THROW(make_grid({0, 0, 10, 10}, 0), std::invalid_argument);
  EXPECT_THROW(make_grid({0, 0, 10, 10}, NAN), std::invalid_argument);
  EXPECT_EQ(make_grid({0, 0, 20000, 20000}, 2).cells.size(), 10001u * 10001u);  // 1e8 cells: allowed
}

TEST(OccupancyGrid, BoundsFromBorderOrSegments) {
  Map m;
  m.border = {-1, 5, 7, -2};
  EXPECT_EQ(grid_bounds(m), (Rect{-1, -2, 7, 5}));
  m.border = {};
  EXPECT_THROW(grid_bounds(m), std::invalid_argument);
  m.obstacles.push_back({1, ShapeType::OpenPolygon, "", {{{2, 3}, {4, -1}, 1, 0, "", ""}}, {}});
  EXPECT_EQ(grid_bounds(m, 0.5), (Rect{1.5, -1.5, 4.5, 3.5}));
}

// ---- PGM and YAML ------------------------------------------------------------------

struct Pgm {
  int width = 0, height = 0, maxval = 0;
  std::vector<uint8_t> pixels;  // image order: top line first
};

// Netpbm's grammar: "P5", whitespace-separated width, height, maxval (with '#' comments),
// one whitespace byte, then the raster.
Pgm parse_pgm(const std::string& s) {
  Pgm p;
  EXPECT_EQ(s.substr(0, 2), "P5");
  size_t i = 2;
  int* fields[3] = {&p.width, &p.height, &p.maxval};
  for (int* f : fields) {
    while (i < s.size() && (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == '#'))
      if (s[i] == '#') i = s.find('\n', i);
      else ++i;
    size_t end = i;
    while (end < s.size() && std::isdigit(static_cast<unsigned char>(s[end]))) ++end;
    *f = std::stoi(s.substr(i, end - i));
    i = end;
  }
  ++i;  // the single whitespace byte
  p.pixels.assign(s.begin() + static_cast<long>(i), s.end());
  return p;
}

TEST(OccupancyGrid, PgmRowsFromTheTop) {
  OccupancyGrid g = make_grid({10, 20, 11.4, 20.9}, 0.5);  // 3 x 2 cells
  ASSERT_EQ(g.width, 3);
  ASSERT_EQ(g.height, 2);
  g.set(0, 0, OccupancyGrid::kOccupied);  // bottom left
  g.set(2, 1, OccupancyGrid::kUnknown);   // top right
  const std::string pgm = write_pgm(g);
  EXPECT_EQ(pgm.substr(0, 11), "P5\n3 2\n255\n");
  const Pgm p = parse_pgm(pgm);
  EXPECT_EQ(p.width, 3);
  EXPECT_EQ(p.height, 2);
  EXPECT_EQ(p.maxval, 255);
  EXPECT_EQ(p.pixels, (std::vector<uint8_t>{254, 254, 205, 0, 254, 254}));
}

std::map<std::string, std::string> parse_yaml(const std::string& s) {
  std::map<std::string, std::string> kv;
  std::istringstream in(s);
  std::string line;
  while (std::getline(in, line)) {
    const size_t colon = line.find(": ");
    if (colon != std::string::npos) kv[line.substr(0, colon)] = line.substr(colon + 2);
  }
  return kv;
}

// Nav2 map_server, trinary mode: occ = (255 - pixel) / 255 (negate 0); occupied when
// occ > occupied_thresh, free when occ < free_thresh, unknown otherwise.
int nav2_trinary(uint8_t pixel, double occupied_thresh, double free_thresh) {
  const double occ = (255.0 - pixel) / 255.0;
  if (occupied_thresh < occ) return 100;
  if (occ < free_thresh) return 0;
  return -1;
}

TEST(OccupancyGrid, Nav2Yaml) {
  const OccupancyGrid g = make_grid({-12.5, 3.25, 0, 10}, 0.05);
  const auto kv = parse_yaml(write_nav2_yaml(g, "gdc1-0.3.pgm"));
  EXPECT_EQ(kv.at("image"), "\"gdc1-0.3.pgm\"");
  EXPECT_EQ(kv.at("mode"), "trinary");
  EXPECT_EQ(kv.at("resolution"), "0.05");
  EXPECT_EQ(kv.at("origin"), "[-12.5, 3.25, 0.0]");
  EXPECT_EQ(kv.at("negate"), "0");
  const double occ = std::stod(kv.at("occupied_thresh")), free = std::stod(kv.at("free_thresh"));
  EXPECT_EQ(occ, 0.65);
  // The three pixel values read back as what they mean.
  EXPECT_EQ(nav2_trinary(0, occ, free), 100);
  EXPECT_EQ(nav2_trinary(254, occ, free), 0);
  EXPECT_EQ(nav2_trinary(205, occ, free), -1);
  EXPECT_EQ(kv.size(), 7u);
}

// The example map's slice at 0.3 m at 0.5 m per cell, cells read back from the PGM.
TEST(OccupancyGrid, ExampleSliceThroughPgm) {
  const Map s = slice_at_height(read_seed_file(FLEETMAP_SOURCE_DIR "/maps/example-campus.map"), 0.3);
  const OccupancyGrid g = rasterize_map(s, 0.5);
  ASSERT_EQ(g.width, 121);  // border 60 x 40 m
  ASSERT_EQ(g.height, 81);
  const Pgm p = parse_pgm(write_pgm(g));
  ASSERT_EQ(p.pixels.size(), 121u * 81u);
  auto px = [&](double x, double y) {
    const int col = static_cast<int>(std::floor(x / 0.5)), row = static_cast<int>(std::floor(y / 0.5));
    return p.pixels[static_cast<size_t>(p.height - 1 - row) * p.width + col];
  };
  EXPECT_EQ(px(20.1, 30.2), 0);    // the library's east wall x = 20
  EXPECT_EQ(px(22, 30.2), 254);    // beside it
  EXPECT_EQ(px(47.2, 19.2), 0);    // step 0.45 m at y = 19.1
  EXPECT_EQ(px(47.2, 18.6), 254);  // step 0.15 m at y = 18.5 and 0.3 m at y = 18.8: passed
  EXPECT_EQ(px(47.2, 20.2), 254);  // the closing segment y = 20 is not drawn
  EXPECT_EQ(px(10.45, 11), 0);     // the ramp reaches 0.3 m at x = 10.4
  EXPECT_EQ(px(9.2, 11), 254);     // its low part passes under the laser
  EXPECT_EQ(px(8.2, 10.2), 254);   // its foot edge too
  EXPECT_EQ(px(30.2, 14.1), 0);    // the bench (0.45 m)
}

}  // namespace
}  // namespace fleetmap
