#pragma once
// Small maps built in code for the localization tests.
#include <vector>

#include "common/map/map.h"

namespace fleetmap::localization::test {

inline Segment wall(Point a, Point b, double h = 2.0) { return {a, b, h, 0, "wall", ""}; }

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

}  // namespace fleetmap::localization::test
