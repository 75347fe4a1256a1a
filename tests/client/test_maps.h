#pragma once
// Small maps built in code for the localization tests.
#include <utility>
#include <vector>

#include "common/map/map.h"

namespace fleetmap::localization::test {

inline Segment wall(Point a, Point b, double h = 2.0) { return {a, b, h, 0, "wall", ""}; }

// One open chain of walls inside a border: the smallest map a test can ask for.
inline Map chain_map(const Rect& border, std::vector<Segment> walls) {
  Map m;
  m.border = Border::from_rect(border);
  Obstacle o;
  o.id = 1;
  o.type = ShapeType::OpenPolygon;
  o.segments = std::move(walls);
  m.obstacles = {o};
  m.compute_bounds();
  return m;
}

// A 20 m x 10 m room (the border is its walls), its walls one open chain, with an L-shaped wall, a short wall and a
// closed 1 m x 1 m pillar (the only enclosed obstacle) so that no two places look alike.
inline Map room_map() {
  Map m;
  m.border = Border::from_rect({0, 0, 20, 10});
  Obstacle outer;
  outer.id = 1;
  outer.type = ShapeType::OpenPolygon;
  outer.segments = {wall({0, 0}, {20, 0}), wall({20, 0}, {20, 10}), wall({20, 10}, {0, 10}), wall({0, 10}, {0, 0})};
  Obstacle l;
  l.id = 2;
  l.type = ShapeType::OpenPolygon;
  l.segments = {wall({4, 2}, {4, 6}), wall({4, 6}, {8, 6})};
  Obstacle s;
  s.id = 3;
  s.type = ShapeType::OpenPolygon;
  s.segments = {wall({11, 8}, {13, 10})};
  Obstacle pillar;
  pillar.id = 4;
  pillar.type = ShapeType::ClosedPolygon;
  pillar.segments = {wall({14, 4}, {15, 4}), wall({15, 4}, {15, 5}), wall({15, 5}, {14, 5}), wall({14, 5}, {14, 4})};
  m.obstacles = {outer, l, s, pillar};
  m.compute_bounds();
  return m;
}

// Two closed 8 m x 6 m rooms, 4 m apart along x; each holds an L-shaped wall and a short
// one. `same`: room B is room A moved by 12 m (a perfect look-alike); otherwise B's short
// wall is elsewhere.
inline Map two_rooms(bool same) {
  Map m;
  m.border = Border::from_rect({0, 0, 20, 6});
  int id = 1;
  auto chain = [&](std::vector<Point> pts, double ox) {
    Obstacle o;
    o.id = id++;
    o.type = ShapeType::OpenPolygon;
    for (size_t i = 1; i < pts.size(); ++i)
      o.segments.push_back(wall({pts[i - 1].x + ox, pts[i - 1].y}, {pts[i].x + ox, pts[i].y}));
    m.obstacles.push_back(o);
  };
  for (double ox : {0.0, 12.0}) {
    chain({{0, 0}, {8, 0}, {8, 6}, {0, 6}, {0, 0}}, ox);
    chain({{2, 1}, {2, 3}, {4, 3}}, ox);
    if (same || ox == 0) chain({{6, 4}, {7, 6}}, ox);
    else chain({{1, 4}, {2, 6}}, ox);
  }
  m.compute_bounds();
  return m;
}

}  // namespace fleetmap::localization::test
