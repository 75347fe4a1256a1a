#include "common/map/map_window.h"

namespace fleetmap {

Rect window_rect(const Border& border, Point centre, double w, double h) {
  return intersection(Rect::centred(centre, w, h), border.rect());
}

std::optional<Obstacle> clip_obstacle(const Obstacle& o, const Rect& r) {
  Obstacle out;
  out.id = o.id;
  out.type = o.type;
  out.semantic = o.semantic;
  for (const Segment& s : o.segments) {
    if (auto c = clip_segment(s.a, s.b, r)) {
      Segment cut = s;
      cut.a = c->a;
      cut.b = c->b;
      out.segments.push_back(std::move(cut));
    }
  }
  if (out.segments.empty()) return std::nullopt;
  out.compute_bound();
  return out;
}

Map clip_map(const Map& m, const Rect& r) {
  Map out;
  out.border = Border::from_rect(r);
  if (r.empty()) return out;
  for (const Obstacle& o : m.obstacles)
    if (auto c = clip_obstacle(o, r)) out.obstacles.push_back(std::move(*c));
  return out;
}

}  // namespace fleetmap
