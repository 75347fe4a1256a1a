#include "common/map/map_placement.h"

#include <algorithm>
#include <cmath>

#include "common/geometry/number_format.h"

namespace fleetmap {
namespace {

constexpr long kMaxCellsPerSide = 256;

// Twice the signed area: > 0 for a counter-clockwise ring.
double signed_area2(const Polygon& ring) {
  double a = 0;
  for (size_t i = 0; i < ring.size(); ++i) a += cross(ring[i], ring[(i + 1) % ring.size()]);
  return a;
}

bool is_solid(const Obstacle& o) {
  if (o.type != ShapeType::ClosedPolygon && o.type != ShapeType::ClosedCurved) return false;
  if (o.segments.size() < 3) return false;
  return std::any_of(o.segments.begin(), o.segments.end(), [](const Segment& s) { return s.h > 0; });
}

std::string pt(Point p) { return "(" + format_number(p.x) + ", " + format_number(p.y) + ")"; }

}  // namespace

MapPlacement::MapPlacement(const Map& map) : border_(map.border), rect_(map.border.rect()) {
  for (const Obstacle& o : map.obstacles) {
    if (!is_solid(o)) continue;
    Solid s;
    for (const Segment& seg : o.segments) s.ring.push_back(seg.a);  // a closed chain (map_validation.h)
    if (!(signed_area2(s.ring) > 0)) continue;                       // free space inside
    s.box = polygon_bounds(s.ring);
    s.id = o.id;
    s.semantic = o.semantic;
    solids_.push_back(std::move(s));
  }
  const double w = rect_.xmax - rect_.xmin, h = rect_.ymax - rect_.ymin;
  if (solids_.empty() || !(w > 0) || !(h > 0)) return;
  // About one solid per cell, at most kMaxCellsPerSide cells a side.
  cell_ = std::max({std::sqrt(w * h / static_cast<double>(solids_.size())), w / kMaxCellsPerSide,
                    h / kMaxCellsPerSide});
  cols_ = std::clamp(static_cast<long>(std::ceil(w / cell_)), 1L, kMaxCellsPerSide);
  rows_ = std::clamp(static_cast<long>(std::ceil(h / cell_)), 1L, kMaxCellsPerSide);
  cells_.resize(static_cast<size_t>(cols_ * rows_));
  auto col = [&](double x) { return std::clamp(static_cast<long>(std::floor((x - rect_.xmin) / cell_)), 0L, cols_ - 1); };
  auto row = [&](double y) { return std::clamp(static_cast<long>(std::floor((y - rect_.ymin) / cell_)), 0L, rows_ - 1); };
  for (size_t i = 0; i < solids_.size(); ++i) {
    const Rect& b = solids_[i].box;
    for (long r = row(b.ymin); r <= row(b.ymax); ++r)
      for (long c = col(b.xmin); c <= col(b.xmax); ++c) cells_[static_cast<size_t>(r * cols_ + c)].push_back(i);
  }
}

std::vector<size_t> MapPlacement::candidates(Point p) const {
  if (cells_.empty() || !rect_.contains(p)) return {};
  const long c = std::clamp(static_cast<long>(std::floor((p.x - rect_.xmin) / cell_)), 0L, cols_ - 1);
  const long r = std::clamp(static_cast<long>(std::floor((p.y - rect_.ymin) / cell_)), 0L, rows_ - 1);
  std::vector<size_t> out;
  for (size_t i : cells_[static_cast<size_t>(r * cols_ + c)])
    if (solids_[i].box.contains(p) && point_in_polygon(p, solids_[i].ring)) out.push_back(i);
  return out;
}

std::string MapPlacement::border_text() const {
  return "outside the border " + pt({border_.mx1, border_.my1}) + "-" + pt({border_.mx4, border_.my4});
}

std::optional<std::string> MapPlacement::point_problem(Point p) const {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !rect_.contains(p)) return border_text();
  const std::vector<size_t> in = candidates(p);
  if (in.empty()) return std::nullopt;
  const Solid& s = solids_[in.front()];
  return "inside obstacle " + std::to_string(s.id) + (s.semantic.empty() ? "" : " '" + s.semantic + "'");
}

std::optional<std::string> MapPlacement::polygon_problem(const Polygon& ring, bool solid_inside) const {
  for (Point p : ring)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !rect_.contains(p)) return "vertex " + pt(p) + " " + border_text();
  if (!solid_inside || ring.empty()) return std::nullopt;
  for (size_t i : candidates(ring.front())) {
    const Solid& s = solids_[i];
    if (std::all_of(ring.begin(), ring.end(), [&](Point p) { return s.box.contains(p) && point_in_polygon(p, s.ring); }))
      return "inside obstacle " + std::to_string(s.id) + (s.semantic.empty() ? "" : " '" + s.semantic + "'");
  }
  return std::nullopt;
}

}  // namespace fleetmap
