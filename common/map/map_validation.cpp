#include "common/map/map_validation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>
#include <set>
#include <stdexcept>

#include "common/geometry/number_format.h"
#include "common/map/ramp.h"

namespace fleetmap {
namespace {

constexpr double kJoinTolerance = 1e-6;  // metres: chain ends closer than this are joined

std::string pt(Point p) { return format_number(p.x) + ";" + format_number(p.y); }

bool joined(Point a, Point b) { return distance(a, b) <= kJoinTolerance; }

// Length in bytes of the UTF-8 sequence starting at s[i], or 0 when invalid.
size_t utf8_sequence(std::string_view s, size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  size_t n;
  uint32_t cp;
  if (c < 0x80) return 1;
  if ((c & 0xE0) == 0xC0) { n = 2; cp = c & 0x1F; }
  else if ((c & 0xF0) == 0xE0) { n = 3; cp = c & 0x0F; }
  else if ((c & 0xF8) == 0xF0) { n = 4; cp = c & 0x07; }
  else return 0;
  if (i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    const auto cc = static_cast<unsigned char>(s[i + k]);
    if ((cc & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (cc & 0x3F);
  }
  // Reject overlong forms, surrogates and code points past U+10FFFF.
  static constexpr uint32_t kMin[5] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < kMin[n] || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF) return 0;
  return n;
}

std::optional<std::string> check_number(double v, double limit, std::string_view what) {
  if (!std::isfinite(v)) return "expected a finite number for " + std::string(what) + ", got " + format_number(v);
  if (std::abs(v) > limit)
    return "expected |" + std::string(what) + "| <= " + format_number(limit) + ", got " + format_number(v);
  return std::nullopt;
}

}  // namespace

std::optional<std::string> check_text(std::string_view text, std::string_view what, bool free_form,
                                      size_t max_bytes) {
  if (text.size() > max_bytes)
    return "expected " + std::string(what) + " of at most " + std::to_string(max_bytes) + " bytes, got " +
           std::to_string(text.size());
  // The reader trims blanks around fields, so a semantic string with blanks at its ends
  // would not read back equal.
  if (!free_form && !text.empty() && (text.front() == ' ' || text.back() == ' ' || text.front() == '\t' || text.back() == '\t'))
    return "expected " + std::string(what) + " without blanks at its ends, got '" + std::string(text) + "'";
  for (size_t i = 0; i < text.size();) {
    const size_t n = utf8_sequence(text, i);
    if (n == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(text[i]));
      return "expected UTF-8 text in " + std::string(what) + ", got byte " + hex + " at offset " + std::to_string(i);
    }
    const char c = text[i];
    if (n == 1 && (static_cast<unsigned char>(c) < 0x20 || c == 0x7F))
      return "expected printable text in " + std::string(what) + ", got a control character at offset " +
             std::to_string(i);
    if (!free_form && (c == ';' || c == '#' || c == '%'))
      return "expected " + std::string(what) + " without ';', '#' or '%' (they delimit the format), got '" +
             std::string(text) + "'";
    i += n;
  }
  return std::nullopt;
}

std::optional<std::string> check_border(const Border& b) {
  for (auto [v, name] : {std::pair{b.mx1, "mx1"}, {b.my1, "my1"}, {b.mx4, "mx4"}, {b.my4, "my4"}})
    if (auto e = check_number(v, kMaxCoordinate, name)) return e;
  if (!(b.mx1 < b.mx4 && b.my1 > b.my4))
    return "expected border upper-left then lower-right (mx1 < mx4 and my1 > my4), got (" + format_number(b.mx1) +
           ";" + format_number(b.my1) + ") and (" + format_number(b.mx4) + ";" + format_number(b.my4) + ")";
  return std::nullopt;
}

std::optional<std::string> check_segment(const Segment& s) {
  for (auto [v, name] : {std::pair{s.a.x, "ax"}, {s.a.y, "ay"}, {s.b.x, "bx"}, {s.b.y, "by"}})
    if (auto e = check_number(v, kMaxCoordinate, name)) return e;
  if (auto e = check_number(s.h, kMaxHeight, "h")) return e;
  if (s.h < 0) return "expected height h >= 0, got " + format_number(s.h);
  if (s.in_out != 0 && s.in_out != 1) return "expected inOut 0 or 1, got " + std::to_string(s.in_out);
  if (s.a == s.b) return "expected a segment of non-zero length, got a = b = (" + pt(s.a) + ")";
  if (auto e = check_text(s.semantic, "segment semantic")) return e;
  if (auto e = check_text(s.note, "segment note", true)) return e;
  return std::nullopt;
}

std::optional<std::string> check_shape(const Obstacle& o, MapKind kind) {
  const auto& segs = o.segments;
  const std::string shape = "shape type " + std::to_string(static_cast<int>(o.type)) + " (" +
                           std::string(to_string(o.type)) + ")";
  if (segs.empty()) return "expected at least one segment in obstacle " + std::to_string(o.id) + ", got none";
  if (auto e = check_text(o.semantic, "obstacle semantic", false, kMaxObstacleTextBytes)) return e;

  if (o.type == ShapeType::Ramp) {
    for (size_t i = 0; i < segs.size(); ++i)
      if (segs[i].h != 0)
        return "expected null height on ramp segment " + std::to_string(i + 1) + ", got " + format_number(segs[i].h);
    try {
      ramp_surface(o);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
  }
  if (kind == MapKind::Window) return std::nullopt;

  if (o.type == ShapeType::Stairs) {
    // seed 000 section 3.1 / Fig. 1: steps parallel to each other, heights growing towards
    // the top; one closing segment with h = 0, oriented the other way, at the top.
    int closing = -1;
    for (size_t i = 0; i < segs.size(); ++i) {
      if (segs[i].h == 0) {
        if (closing >= 0)
          return "expected one closing segment with h = 0 in stairs, got segments " + std::to_string(closing + 1) +
                 " and " + std::to_string(i + 1);
        closing = static_cast<int>(i);
      }
    }
    if (closing < 0) return "expected a closing segment with h = 0 in stairs, got none";
    if (segs.size() < 2) return "expected at least one step (h > 0) besides the closing segment, got none";
    const Segment& top = segs[closing];
    const Point dir = top.b - top.a;
    // Segments are oriented left to right seen from free space, so free space (the top
    // landing) is right of the closing segment and the steps are on its left.
    const Point inward{-dir.y, dir.x};
    double last_dist = -1;
    double last_h = std::numeric_limits<double>::infinity();
    std::vector<std::pair<double, double>> steps;  // (distance from the top, height)
    for (size_t i = 0; i < segs.size(); ++i) {
      if (static_cast<int>(i) == closing) continue;
      const Point d = segs[i].b - segs[i].a;
      if (std::abs(cross(d, dir)) > 1e-6 * norm(d) * norm(dir) || dot(d, dir) >= 0)
        return "expected step " + std::to_string(i + 1) + " antiparallel to the closing segment " +
               std::to_string(closing + 1) + ", got direction (" + pt(d) + ")";
      const double dist = dot(segs[i].a - top.a, inward) / norm(inward);
      if (!(dist > 0))
        return "expected step " + std::to_string(i + 1) + " on the steps' side of the closing segment, got distance " +
               format_number(dist);
      steps.emplace_back(dist, segs[i].h);
    }
    std::sort(steps.begin(), steps.end());
    for (auto [dist, h] : steps) {
      if (dist == last_dist) return "expected steps at distinct distances from the closing segment, got two at " +
                                    format_number(dist);
      if (!(h < last_h))
        return "expected step heights to grow towards the closing segment, got " + format_number(h) +
               " m at " + format_number(dist) + " m after " + format_number(last_h) + " m nearer";
      last_dist = dist;
      last_h = h;
    }
    return std::nullopt;
  }

  for (size_t i = 1; i < segs.size(); ++i)
    if (!joined(segs[i - 1].b, segs[i].a))
      return "expected " + shape + " segment " + std::to_string(i + 1) + " to start where segment " +
             std::to_string(i) + " ends (" + pt(segs[i - 1].b) + "), got (" + pt(segs[i].a) + ")";
  if (is_closed(o.type)) {
    if (segs.size() < 3) return "expected at least 3 segments in a " + shape + ", got " + std::to_string(segs.size());
    if (!joined(segs.back().b, segs.front().a))
      return "expected " + shape + " to close: last segment should end at (" + pt(segs.front().a) + "), got (" +
             pt(segs.back().b) + ")";
  }
  return std::nullopt;
}

void validate_map(const Map& m, MapKind kind) {
  if (auto e = check_border(m.border)) throw std::invalid_argument("border: " + *e);
  const Rect r = m.border.rect();
  std::set<int> ids;
  for (size_t k = 0; k < m.obstacles.size(); ++k) {
    const Obstacle& o = m.obstacles[k];
    const std::string where = "obstacle " + std::to_string(o.id) + " (#" + std::to_string(k + 1) + ")";
    if (!ids.insert(o.id).second)
      throw std::invalid_argument(where + ": expected a unique obstacle id, got " + std::to_string(o.id) + " again");
    for (size_t i = 0; i < o.segments.size(); ++i) {
      const Segment& s = o.segments[i];
      if (auto e = check_segment(s))
        throw std::invalid_argument(where + " segment " + std::to_string(i + 1) + ": " + *e);
      if (!r.contains(s.a) || !r.contains(s.b))
        throw std::invalid_argument(where + " segment " + std::to_string(i + 1) +
                                    ": expected a segment inside the border, got (" + pt(s.a) + ") to (" + pt(s.b) +
                                    ")");
    }
    if (auto e = check_shape(o, kind)) throw std::invalid_argument(where + ": " + *e);
  }
}

}  // namespace fleetmap
