#include "common/map/map_placement.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace fleetmap {
namespace {

// A closed obstacle through the corners, in the order given.
Obstacle ring_obstacle(int id, ShapeType type, const std::vector<Point>& corners, double h = 2.0) {
  Obstacle o;
  o.id = id;
  o.type = type;
  o.semantic = "block";
  for (size_t i = 0; i < corners.size(); ++i) o.segments.push_back({corners[i], corners[(i + 1) % corners.size()], h, 0, "", ""});
  o.compute_bound();
  return o;
}

std::vector<Point> box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }
std::vector<Point> reversed(std::vector<Point> v) { return {v.rbegin(), v.rend()}; }

Map room() {
  Map m;
  m.border = Border::from_rect({0, 0, 20, 10});
  return m;
}

TEST(MapPlacement, BorderIsClosedAndOutsideIsNamed) {
  const MapPlacement p(room());
  EXPECT_FALSE(p.point_problem({0, 0}));
  EXPECT_FALSE(p.point_problem({20, 10}));
  EXPECT_FALSE(p.point_problem({10, 5}));
  auto out = p.point_problem({20.001, 5});
  ASSERT_TRUE(out);
  EXPECT_EQ(*out, "outside the border (0, 10)-(20, 0)");
  EXPECT_TRUE(p.point_problem({5, -0.5}));
  EXPECT_TRUE(p.point_problem({std::nan(""), 5}));
}

TEST(MapPlacement, OnlyCounterClockwiseClosedObstaclesWithHeightAreSolid) {
  Map m = room();
  m.obstacles.push_back(ring_obstacle(1, ShapeType::ClosedPolygon, box(1, 1, 3, 3)));             // solid
  m.obstacles.push_back(ring_obstacle(2, ShapeType::ClosedPolygon, reversed(box(5, 1, 7, 3))));   // free inside
  m.obstacles.push_back(ring_obstacle(3, ShapeType::ClosedPolygon, box(9, 1, 11, 3), 0.0));       // flat
  m.obstacles.push_back(ring_obstacle(4, ShapeType::Ramp, box(13, 1, 15, 3)));                    // driven on
  m.obstacles.push_back(ring_obstacle(5, ShapeType::ClosedCurved, box(1, 5, 3, 7)));              // solid
  Obstacle open = ring_obstacle(6, ShapeType::OpenPolygon, box(5, 5, 7, 7));
  open.segments.pop_back();
  m.obstacles.push_back(open);
  const MapPlacement p(m);
  EXPECT_EQ(p.solid_obstacles(), 2u);
  EXPECT_EQ(p.point_problem({2, 2}).value_or(""), "inside obstacle 1 'block'");
  EXPECT_EQ(p.point_problem({3, 2}).value_or(""), "inside obstacle 1 'block'");  // on the wall
  EXPECT_EQ(p.point_problem({2, 6}).value_or(""), "inside obstacle 5 'block'");
  for (Point q : {Point{6, 2}, Point{10, 2}, Point{14, 2}, Point{6, 6}, Point{4, 2}, Point{3.001, 2}})
    EXPECT_FALSE(p.point_problem(q)) << q.x << " " << q.y;
}

TEST(MapPlacement, PolygonsOutsideTheBorderOrBuriedInASolid) {
  Map m = room();
  m.obstacles.push_back(ring_obstacle(1, ShapeType::ClosedPolygon, box(1, 1, 5, 5)));
  const MapPlacement p(m);
  EXPECT_FALSE(p.polygon_problem(box(6, 6, 8, 8), true));
  EXPECT_EQ(p.polygon_problem(box(18, 8, 21, 9), false).value_or(""),
            "vertex (21, 8) outside the border (0, 10)-(20, 0)");
  // Inside: every vertex in the solid; half in, half out is not buried.
  EXPECT_EQ(p.polygon_problem(box(2, 2, 3, 3), true).value_or(""), "inside obstacle 1 'block'");
  EXPECT_FALSE(p.polygon_problem(box(2, 2, 3, 3), false));
  EXPECT_FALSE(p.polygon_problem(box(4, 4, 6, 6), true));
}

// Many random solids: the grid finds exactly what a scan of every triangle with
// barycentric coordinates finds.
TEST(MapPlacement, GridAgreesWithBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  Map m;
  m.border = Border::from_rect({-50, -20, 150, 80});
  std::vector<std::vector<Point>> tris;
  for (int i = 0; i < 400; ++i) {
    const Point c{-45 + 190 * u(rng), -15 + 90 * u(rng)};
    std::vector<Point> t;
    for (int k = 0; k < 3; ++k) t.push_back({c.x + 8 * (u(rng) - 0.5), c.y + 8 * (u(rng) - 0.5)});
    const double area2 = cross(t[1] - t[0], t[2] - t[0]);
    if (std::abs(area2) < 1e-3) continue;
    if (area2 < 0) std::swap(t[1], t[2]);  // counter-clockwise: solid
    tris.push_back(t);
    m.obstacles.push_back(ring_obstacle(static_cast<int>(tris.size()), ShapeType::ClosedPolygon, t));
  }
  const MapPlacement p(m);
  ASSERT_EQ(p.solid_obstacles(), tris.size());
  auto inside = [](const std::vector<Point>& t, Point q) {
    const double d = cross(t[1] - t[0], t[2] - t[0]);
    const double a = cross(t[1] - q, t[2] - q) / d, b = cross(t[2] - q, t[0] - q) / d, c = 1 - a - b;
    return a > 1e-9 && b > 1e-9 && c > 1e-9;  // strictly inside: no boundary case to argue about
  };
  auto near_edge = [](const std::vector<Point>& t, Point q) {
    const double d = cross(t[1] - t[0], t[2] - t[0]);
    const double a = cross(t[1] - q, t[2] - q) / d, b = cross(t[2] - q, t[0] - q) / d, c = 1 - a - b;
    return std::abs(a) <= 1e-9 || std::abs(b) <= 1e-9 || std::abs(c) <= 1e-9;
  };
  int in = 0;
  for (int i = 0; i < 8000; ++i) {
    const Point q{-50 + 200 * u(rng), -20 + 100 * u(rng)};
    bool brute = false, edge = false;
    for (const auto& t : tris) {
      brute = brute || inside(t, q);
      edge = edge || near_edge(t, q);
    }
    if (edge) continue;
    in += brute;
    EXPECT_EQ(p.point_problem(q).has_value(), brute) << q.x << " " << q.y;
  }
  EXPECT_GT(in, 400);   // the test saw both answers
}

}  // namespace
}  // namespace fleetmap
