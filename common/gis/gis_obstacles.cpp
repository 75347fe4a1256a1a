#include "common/gis/gis_obstacles.h"

#include <algorithm>
#include <cmath>

namespace fleetmap {

size_t drop_repeated_vertices(Chain& c) {
  const size_t before = c.size();
  c.erase(std::unique(c.begin(), c.end()), c.end());
  return before - c.size();
}

double signed_area2(const Chain& ring) {
  if (ring.empty()) return 0;
  // Relative to the first vertex: in UTM (y = 5e6 m) absolute cross products cancel out.
  const Point r = ring.front();
  double a = 0;
  for (size_t i = 0; i + 1 < ring.size(); ++i) a += cross(ring[i] - r, ring[i + 1] - r);
  return a;
}

namespace {

Obstacle chain_obstacle(const Chain& c, ShapeType type, const SegmentStyle& style) {
  Obstacle o;
  o.type = type;
  o.segments.reserve(c.size() - 1);
  for (size_t i = 0; i + 1 < c.size(); ++i)
    o.segments.push_back(Segment{c[i], c[i + 1], style.h, style.in_out, style.semantic, {}});
  return o;
}

}  // namespace

std::optional<Obstacle> closed_obstacle(Chain ring, bool free_space_inside, const SegmentStyle& style) {
  drop_repeated_vertices(ring);
  if (ring.size() >= 2 && !(ring.front() == ring.back())) ring.push_back(ring.front());
  if (ring.size() < 4) return std::nullopt;
  const double a = signed_area2(ring);
  if (a == 0) return std::nullopt;  // every vertex on one line: no inside, no outside
  if ((a > 0) == free_space_inside) std::reverse(ring.begin(), ring.end());
  return chain_obstacle(ring, ShapeType::ClosedPolygon, style);
}

std::optional<Obstacle> open_obstacle(Chain chain, const SegmentStyle& style) {
  drop_repeated_vertices(chain);
  if (chain.size() < 2) return std::nullopt;
  return chain_obstacle(chain, ShapeType::OpenPolygon, style);
}

std::optional<Obstacle> stairs_obstacle(const Chain& up, const StairsStyle& style) {
  if (up.size() < 2) return std::nullopt;
  const Point a = up.front(), b = up.back();
  const double len = distance(a, b);
  if (len < 0.01) return std::nullopt;
  const Point u = (1 / len) * (b - a);
  const Point left{-u.y, u.x};  // left of someone walking up
  const Point half = (style.width / 2) * left;
  const int n = std::max(1, static_cast<int>(std::lround(len / style.step_depth)));
  const double depth = len / n;
  Obstacle o;
  o.type = ShapeType::Stairs;
  // Each step seen from below runs left to right; the closing segment at the top is
  // seen from the landing above, so it runs the other way (seed 000 section 3.1).
  for (int i = 0; i < n; ++i) {
    const Point p = a + (i * depth) * u;
    o.segments.push_back(Segment{p + half, p - half, style.step_height * (i + 1), style.in_out, style.semantic, {}});
  }
  o.segments.push_back(Segment{b - half, b + half, 0, style.in_out, style.semantic, {}});
  return o;
}

}  // namespace fleetmap
