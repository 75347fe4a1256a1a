#include "common/slicing/map_slice.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/geometry/number_format.h"
#include "common/map/laser_rules.h"
#include "common/map/ramp.h"
#include "common/raycast/ray_rules.h"

namespace fleetmap {
namespace {

// ---- ST 1-5 ---------------------------------------------------------------------

std::optional<Obstacle> slice_walls(const Obstacle& o, double hl) {
  Obstacle out{o.id, o.type, o.semantic, {}, {}};
  for (const Segment& s : o.segments)
    if (stops_laser(s.h, hl)) out.segments.push_back(s);
  if (out.segments.empty()) return std::nullopt;
  return out;
}

// The closing segment stays: it is what tells a ray caster that the robot is upstairs.
std::optional<Obstacle> slice_stairs(const Obstacle& o, double hl) {
  Obstacle out{o.id, o.type, o.semantic, {}, {}};
  bool step = false;
  for (const Segment& s : o.segments) {
    const bool stops = stairs_step_stops_laser(s, hl);
    if (stops || is_stairs_closing(s)) out.segments.push_back(s);
    step = step || stops;
  }
  if (!step) return std::nullopt;
  return out;
}

// ---- ST 6: the part of the ramp at or above hL ----------------------------------

struct Vertex {
  Point p;
  const Segment* from;  // the segment of the edge that starts here; nullptr for a bridge
};

struct PointLess {
  bool operator()(Point a, Point b) const { return a.x < b.x || (a.x == b.x && a.y < b.y); }
};

// Where the surface crosses hL on edge pq, with zp and zq the heights over hL at its
// ends (one >= 0, the other < 0). An end at exactly hL is returned bit for bit, so the
// pieces chain exactly.
Point crossing(Point p, Point q, double zp, double zq) {
  const double t = zp / (zp - zq);
  if (t <= 0) return p;
  if (t >= 1) return q;
  return p + t * (q - p);
}

// The boundary pieces chained into rings (each piece starts where the previous ends);
// true when they form exactly one closed ring.
bool chain(std::vector<Segment>& pieces) {
  std::multimap<Point, size_t, PointLess> by_start;
  for (size_t i = 0; i < pieces.size(); ++i) by_start.emplace(pieces[i].a, i);
  std::vector<Segment> out;
  std::vector<bool> used(pieces.size(), false);
  size_t rings = 0;
  bool closed = true;
  for (size_t first = 0; first < pieces.size(); ++first) {
    if (used[first]) continue;
    ++rings;
    size_t cur = first;
    for (;;) {
      used[cur] = true;
      out.push_back(pieces[cur]);
      if (pieces[cur].b == pieces[first].a) break;
      size_t next = pieces.size();
      auto [lo, hi] = by_start.equal_range(pieces[cur].b);
      for (auto it = lo; it != hi; ++it)
        if (!used[it->second]) next = it->second;
      if (next == pieces.size()) {
        closed = false;
        break;
      }
      cur = next;
    }
  }
  pieces = std::move(out);
  return rings == 1 && closed;
}

std::optional<Obstacle> slice_ramp(const Obstacle& o, double hl) {
  const RampSurface surface = ramp_surface(o);
  // The outline as RampRule sees it: a cut ramp's gaps are bridged.
  std::vector<Vertex> ring;
  const auto& segs = o.segments;
  for (size_t i = 0; i < segs.size(); ++i) {
    ring.push_back({segs[i].a, &segs[i]});
    if (!(segs[i].b == segs[(i + 1) % segs.size()].a)) ring.push_back({segs[i].b, nullptr});
  }
  const size_t n = ring.size();
  std::vector<double> z(n);  // the surface over hL, for the crossings
  std::vector<bool> solid(n);  // the vertex is in R
  double area2 = 0;
  for (size_t k = 0; k < n; ++k) {
    const double height = surface.height_at(ring[k].p);
    z[k] = height - hl;
    solid[k] = ramp_stops_laser(height, hl);
    area2 += cross(ring[k].p, ring[(k + 1) % n].p);
  }

  const int in_out = segs.front().in_out;
  auto piece = [&](Point a, Point b, const Segment* from, std::vector<Segment>& out) {
    if (a == b) return;
    Segment s = from ? *from : Segment{{}, {}, 0, in_out, "", ""};
    s.a = a;
    s.b = b;
    s.h = std::max({hl, surface.height_at(a), surface.height_at(b)});
    out.push_back(std::move(s));
  };

  std::vector<Segment> pieces;
  std::vector<Point> crossings;
  for (size_t k = 0; k < n; ++k) {
    const Vertex& v = ring[k];
    const Point p = v.p, q = ring[(k + 1) % n].p;
    const double zp = z[k], zq = z[(k + 1) % n];
    const bool in_p = solid[k], in_q = solid[(k + 1) % n];
    if (in_p && in_q) {
      piece(p, q, v.from, pieces);
    } else if (in_p || in_q) {
      const Point c = crossing(p, q, zp, zq);
      crossings.push_back(c);
      if (in_p) piece(p, c, v.from, pieces);
      else piece(c, q, v.from, pieces);
    }
  }
  if (pieces.empty() && crossings.empty()) return std::nullopt;

  // The line where the surface is at hL, inside the polygon: the crossings pair up along
  // it. Walked with R on the same side as the polygon's interior (left of a
  // counter-clockwise outline), each interval runs from an exit to an entry.
  const Point g = surface.gradient;
  const Point d = area2 >= 0 ? Point{g.y, -g.x} : Point{-g.y, g.x};
  std::sort(crossings.begin(), crossings.end(), [&](Point a, Point b) { return dot(a, d) < dot(b, d); });
  Segment line{{}, {}, hl, in_out, "ramp-crossing", ""};
  for (size_t k = 0; k + 1 < crossings.size(); k += 2) piece(crossings[k], crossings[k + 1], &line, pieces);
  if (pieces.empty()) return std::nullopt;  // R is a single point

  Obstacle out{o.id, ShapeType::ClosedPolygon, o.semantic, std::move(pieces), {}};
  if (!chain(out.segments) || out.segments.size() < 3) out.type = ShapeType::OpenPolygon;
  return out;
}

}  // namespace

Map slice_at_height(const Map& map, double laser_height) {
  if (!std::isfinite(laser_height) || laser_height < 0)
    throw std::invalid_argument("expected a finite laser height >= 0, got " + format_number(laser_height));
  Map out;
  out.border = map.border;
  for (const Obstacle& o : map.obstacles) {
    std::optional<Obstacle> s;
    switch (o.type) {
      case ShapeType::Stairs: s = slice_stairs(o, laser_height); break;
      case ShapeType::Ramp:
        try {
          s = slice_ramp(o, laser_height);
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument("obstacle " + std::to_string(o.id) + ": " + e.what());
        }
        break;
      default: s = slice_walls(o, laser_height);
    }
    if (!s) continue;
    s->compute_bound();
    out.obstacles.push_back(std::move(*s));
  }
  return out;
}

}  // namespace fleetmap
