#include "common/raycast/ray_rules.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/geometry/segment_distance.h"

namespace fleetmap {
namespace {

Rect grow(const Rect& r, const Rect& by) {
  return {std::min(r.xmin, by.xmin), std::min(r.ymin, by.ymin), std::max(r.xmax, by.xmax), std::max(r.ymax, by.ymax)};
}

}  // namespace

// ---- stairs (seed 000 Fig. 6) -----------------------------------------------------

StairsRule::StairsRule(const Obstacle& stairs, double laser_height) {
  parts_.reserve(stairs.segments.size());
  for (const Segment& s : stairs.segments)
    parts_.push_back({prepare_segment(s.a, s.b), is_stairs_closing(s), stairs_step_stops_laser(s, laser_height)});
}

bool StairsRule::can_stop() const {
  return std::any_of(parts_.begin(), parts_.end(), [](const Part& p) { return p.stops; });
}

double StairsRule::distance(Point o, Point d) const {
  double first_closing = kNoHit, first_step = kNoHit, stop = kNoHit;
  for (const Part& p : parts_) {
    const double t = ray_segment_distance(p.seg, o, d);
    if (p.closing) {
      first_closing = std::min(first_closing, t);
    } else {
      first_step = std::min(first_step, t);
      if (p.stops) stop = std::min(stop, t);
    }
  }
  // Upstairs: the closing segment comes first (a tie too: the ray is on the top edge).
  if (first_closing <= first_step) return kNoHit;
  return stop;
}

// ---- ramps (SPEC 3, common/map/ramp.h) ------------------------------------------------

RampRule::RampRule(const Obstacle& ramp, double laser_height)
    : surface_(ramp_surface(ramp)), laser_height_(laser_height), max_height_(-kNoHit) {
  const auto& segs = ramp.segments;
  for (size_t i = 0; i < segs.size(); ++i) {
    ring_.emplace_back(segs[i].a, segs[i].b);
    const Point next = segs[(i + 1) % segs.size()].a;
    // A ramp cut by a window (SPEC 5.4) is open: bridge its gaps along the cut.
    if (!(segs[i].b == next)) ring_.emplace_back(segs[i].b, next);
    // The surface is a plane: over the polygon it is highest at a vertex.
    max_height_ = std::max(max_height_, surface_.height_at(segs[i].a));
    max_height_ = std::max(max_height_, surface_.height_at(segs[i].b));
  }
}

bool RampRule::contains(Point p) const {
  bool inside = false;
  for (const auto& [a, b] : ring_) {
    if (point_segment_distance2(p, a, b) <= kRayTolerance * kRayTolerance) return true;
    // Crossing number along +x, half-open in y.
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
      if (x > p.x) inside = !inside;
    }
  }
  return inside;
}

double RampRule::distance(Point o, Point d) const {
  if (contains(o)) return kNoHit;  // a robot on the ramp (see the header)
  // Where the ray's line crosses the outline, half-open on the line's side so that a
  // vertex on the line or an edge along it is counted consistently: the crossings
  // pair up into the intervals of the line inside the polygon.
  thread_local std::vector<double> ts;
  ts.clear();
  for (const auto& [p, q] : ring_) {
    const double sp = cross(d, p - o), sq = cross(d, q - o);
    if ((sp > 0) != (sq > 0)) ts.push_back(dot(p + (sp / (sp - sq)) * (q - p) - o, d));
  }
  std::sort(ts.begin(), ts.end());
  const double slope = dot(surface_.gradient, d);  // rise per metre along the ray
  for (size_t k = 0; k + 1 < ts.size(); k += 2) {
    if (ts[k + 1] < 0) continue;  // behind the origin
    const double enter = std::max(ts[k], 0.0);
    const double z = surface_.height_at(o + enter * d);
    if (ramp_stops_laser(z, laser_height_)) return enter;  // the ramp's side
    if (slope > 0) {
      const double t = enter + (laser_height_ - z) / slope;  // the surface reaches hL
      if (t <= ts[k + 1]) return t;
    }
  }
  return kNoHit;
}

// ---- a whole map ------------------------------------------------------------------

namespace {

std::variant<StairsRule, RampRule> special_rule(const Obstacle& o, double laser_height) {
  if (o.type == ShapeType::Stairs) return StairsRule(o, laser_height);
  try {
    return RampRule(o, laser_height);
  } catch (const std::invalid_argument& err) {
    throw std::invalid_argument("obstacle " + std::to_string(o.id) + ": " + err.what());
  }
}

}  // namespace

LaserObstacles prepare_laser_obstacles(const Map& map, double laser_height) {
  LaserObstacles out;
  out.bounds = {kNoHit, kNoHit, -kNoHit, -kNoHit};
  for (const Obstacle& o : map.obstacles) {
    if (o.segments.empty()) continue;
    LaserObstacles::Entry e;
    if (o.type == ShapeType::Stairs || o.type == ShapeType::Ramp) {
      SpecialObstacle sp{special_rule(o, laser_height), o.box()};
      const bool stops = std::visit([](const auto& r) { return r.can_stop(); }, sp.rule);
      if (!stops) continue;
      e.special = static_cast<int>(out.specials.size());
      out.specials.push_back(std::move(sp));
    } else {
      e.walls_begin = static_cast<uint32_t>(out.walls.size());
      for (const Segment& s : o.segments)
        if (stops_laser(s.h, laser_height)) out.walls.push_back(prepare_segment(s.a, s.b));
      e.walls_end = static_cast<uint32_t>(out.walls.size());
      if (e.walls_begin == e.walls_end) continue;
    }
    std::vector<Point> pts;
    for (const Segment& s : o.segments) {
      pts.push_back(s.a);
      pts.push_back(s.b);
    }
    e.bound = minimum_bounding_circle(std::move(pts));
    out.bounds = grow(out.bounds, o.box());
    out.obstacles.push_back(e);
  }
  return out;
}

}  // namespace fleetmap
