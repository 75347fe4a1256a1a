#include "client/localization/free_space.h"

#include <algorithm>
#include <cmath>

namespace fleetmap::localization {

namespace {

// Segments chained end to start, the last back to the first.
bool is_closed_chain(const Obstacle& o) {
  const auto& s = o.segments;
  if (s.size() < 3) return false;
  for (size_t i = 0; i < s.size(); ++i)
    if (!(s[i].b == s[(i + 1) % s.size()].a)) return false;
  return true;
}

}  // namespace

FreeSpace::FreeSpace(const Map& map) : rect_(map.border.rect()) {
  area_ = std::max(0.0, rect_.xmax - rect_.xmin) * std::max(0.0, rect_.ymax - rect_.ymin);
  for (const Obstacle& o : map.obstacles) {
    if (o.type != ShapeType::ClosedPolygon && o.type != ShapeType::ClosedCurved) continue;
    if (!is_closed_chain(o)) continue;
    const bool solid = std::any_of(o.segments.begin(), o.segments.end(), [](const Segment& s) { return s.h > 0; });
    if (!solid) continue;
    Solid q;
    std::vector<Point> pts;
    double twice_area = 0;  // shoelace
    for (const Segment& s : o.segments) {
      q.a.push_back(s.a);
      q.b.push_back(s.b);
      pts.push_back(s.a);
      twice_area += cross(s.a, s.b);
    }
    area_ = std::max(0.0, area_ - std::fabs(twice_area) / 2);
    q.bound = minimum_bounding_circle(pts);
    solids_.push_back(std::move(q));
  }
}

bool FreeSpace::contains(Point p) const {
  if (!rect_.contains(p)) return false;
  for (const Solid& q : solids_) {
    if (!q.bound.contains(p)) continue;
    // Even-odd rule: count the edges crossed by the ray from p towards +x.
    bool inside = false;
    for (size_t i = 0; i < q.a.size(); ++i) {
      const Point a = q.a[i], b = q.b[i];
      if ((a.y > p.y) != (b.y > p.y)) {
        const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (x > p.x) inside = !inside;
      }
    }
    if (inside) return false;
  }
  return true;
}

Point FreeSpace::sample(std::mt19937_64& rng, int max_tries) const {
  std::uniform_real_distribution<double> ux(rect_.xmin, rect_.xmax), uy(rect_.ymin, rect_.ymax);
  Point p;
  for (int k = 0; k < std::max(1, max_tries); ++k) {
    p = {ux(rng), uy(rng)};
    if (contains(p)) return p;
  }
  return p;
}

}  // namespace fleetmap::localization
