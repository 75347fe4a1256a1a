#include "client/sim/generated_maps.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include "client/localization/pose.h"

namespace fleetmap::localization {

namespace {

constexpr double kWallHeight = 2.5;

// Builds a map from polylines (walls) and closed rectangles (pillars).
class MapBuilder {
 public:
  explicit MapBuilder(const Rect& border) { map_.border = Border::from_rect(border); }

  void wall(std::vector<Point> chain) {
    Obstacle o;
    o.id = next_id_++;
    o.type = ShapeType::OpenPolygon;
    o.semantic = "wall";
    for (size_t i = 1; i < chain.size(); ++i) o.segments.push_back(segment(chain[i - 1], chain[i]));
    map_.obstacles.push_back(std::move(o));
  }
  void pillar(Point centre, double side) {
    const double h = side / 2;
    const Point c[4] = {{centre.x - h, centre.y - h}, {centre.x + h, centre.y - h}, {centre.x + h, centre.y + h},
                        {centre.x - h, centre.y + h}};
    Obstacle o;
    o.id = next_id_++;
    o.type = ShapeType::ClosedPolygon;
    o.semantic = "pillar";
    for (int i = 0; i < 4; ++i) o.segments.push_back(segment(c[i], c[(i + 1) % 4]));
    map_.obstacles.push_back(std::move(o));
  }
  // The border's four walls.
  void outer_walls() {
    const Rect r = map_.border.rect();
    wall({{r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}, {r.xmin, r.ymin}});
  }
  Map done() {
    map_.compute_bounds();
    return std::move(map_);
  }

 private:
  static Segment segment(Point a, Point b) { return {a, b, kWallHeight, 0, "wall", ""}; }
  Map map_;
  int next_id_ = 1;
};

// A row of rooms along y = wall_y, doors opening towards the corridor (side +1: rooms
// above the wall, -1: below). Widths and door offsets drawn from rng.
void room_row(MapBuilder& b, double x0, double x1, double wall_y, double depth, int side, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> width(3.0, 7.0), offset(0.2, 0.8);
  constexpr double door = 0.9;
  const double back = wall_y + side * depth;
  b.wall({{x0, wall_y}, {x0, back}});
  double x = x0;
  while (x < x1 - 1e-9) {
    const double next = std::min(x1, x + width(rng));
    const double d = x + (next - x - door) * offset(rng);
    b.wall({{x, wall_y}, {d, wall_y}});
    b.wall({{d + door, wall_y}, {next, wall_y}});
    if (next < x1) b.wall({{next, wall_y}, {next, back}});
    x = next;
  }
}

Map offices(uint64_t seed) {
  std::mt19937_64 rng(seed);
  MapBuilder b({0, 0, 60, 14});
  b.outer_walls();
  room_row(b, 0, 60, 8, 6, +1, rng);   // north rooms 8-14
  room_row(b, 0, 60, 6, 6, -1, rng);   // south rooms 0-6, corridor 6-8
  return b.done();
}

Map corridor(uint64_t) {
  // Identical by construction: the seed changes nothing.
  MapBuilder b({0, 0, 80, 6.5});
  b.outer_walls();
  constexpr double pitch = 4.0, door = 1.0, wall_y = 2.5;
  for (double x = 0; x < 80 - 1e-9; x += pitch) {
    b.wall({{x, wall_y}, {x + (pitch - door) / 2, wall_y}});
    b.wall({{x + (pitch + door) / 2, wall_y}, {x + pitch, wall_y}});
    if (x + pitch < 80) b.wall({{x + pitch, wall_y}, {x + pitch, 6.5}});
  }
  return b.done();
}

Map hall(uint64_t) {
  MapBuilder b({0, 0, 60, 40});
  b.outer_walls();
  for (double x = 6; x < 60; x += 8)
    for (double y = 4; y < 40; y += 8) b.pillar({x, y}, 0.6);
  return b.done();
}

Map clutter(uint64_t seed) {
  std::mt19937_64 rng(seed);
  MapBuilder b({0, 0, 40, 30});
  b.outer_walls();
  std::uniform_real_distribution<double> x(1, 39), y(1, 29), len(0.3, 1.5), dir(-kPi, kPi);
  for (int i = 0; i < 150; ++i) {
    const Point a{x(rng), y(rng)};
    const double l = len(rng), t = dir(rng);
    b.wall({a, {a.x + l * std::cos(t), a.y + l * std::sin(t)}});
  }
  return b.done();
}

}  // namespace

const std::vector<std::string>& generated_map_kinds() {
  static const std::vector<std::string> kinds{"offices", "corridor", "hall", "clutter"};
  return kinds;
}

std::optional<Map> generate_map(const std::string& kind, uint64_t seed) {
  if (kind == "offices") return offices(seed);
  if (kind == "corridor") return corridor(seed);
  if (kind == "hall") return hall(seed);
  if (kind == "clutter") return clutter(seed);
  return std::nullopt;
}

std::optional<Map> generated_map_from_name(const std::string& name) {
  const std::string prefix = "gen:";
  if (name.rfind(prefix, 0) != 0) return std::nullopt;
  std::string kind = name.substr(prefix.size());
  uint64_t seed = 1;
  if (const size_t colon = kind.find(':'); colon != std::string::npos) {
    const std::string digits = kind.substr(colon + 1);
    kind.resize(colon);
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 18)
      throw std::invalid_argument("map " + name + ": expected gen:KIND:SEED with SEED a non-negative integer");
    seed = std::stoull(digits);
  }
  if (auto map = generate_map(kind, seed)) return map;
  std::string kinds;
  for (const std::string& k : generated_map_kinds()) kinds += (kinds.empty() ? "" : ", ") + k;
  throw std::invalid_argument("map " + name + ": expected gen:KIND[:SEED] with KIND one of " + kinds);
}

}  // namespace fleetmap::localization
