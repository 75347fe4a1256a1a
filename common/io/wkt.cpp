#include "common/io/wkt.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "common/geometry/number_format.h"

namespace fleetmap {

Polygon parse_polygon_wkt(const std::string& wkt) {
  auto fail = [&](const std::string& what) -> Polygon {
    throw std::invalid_argument("expected " + what + " in 'POLYGON((x y, x y, ...))', got '" + wkt + "'");
  };
  size_t at = 0;
  auto skip = [&] {
    while (at < wkt.size() && std::isspace(static_cast<unsigned char>(wkt[at]))) ++at;
  };
  auto eat = [&](char c) {
    skip();
    if (at < wkt.size() && wkt[at] == c) return ++at, true;
    return false;
  };
  skip();
  std::string word;
  while (at < wkt.size() && std::isalpha(static_cast<unsigned char>(wkt[at])))
    word += static_cast<char>(std::toupper(static_cast<unsigned char>(wkt[at++])));
  if (word != "POLYGON") return fail("the word POLYGON");
  if (!eat('(') || !eat('(')) return fail("'(('");
  Polygon ring;
  for (;;) {
    double xy[2];
    for (double& v : xy) {
      skip();
      auto [end, ec] = std::from_chars(wkt.data() + at, wkt.data() + wkt.size(), v);
      if (ec != std::errc() || !std::isfinite(v)) return fail("a finite number");
      at = static_cast<size_t>(end - wkt.data());
    }
    ring.push_back({xy[0], xy[1]});
    if (eat(',')) continue;
    if (!eat(')')) return fail("',' or ')'");
    break;
  }
  if (eat(',')) throw std::invalid_argument("expected one ring (holes are not part of the model), got '" + wkt + "'");
  if (!eat(')')) return fail("'))'");
  skip();
  if (at != wkt.size()) return fail("nothing after '))'");
  if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
  if (ring.size() < 3) return fail("at least 3 vertices");
  return ring;
}

std::string polygon_to_wkt(const Polygon& ring) {
  std::string s = "POLYGON((";
  for (size_t i = 0; i <= ring.size() && !ring.empty(); ++i) {
    const Point p = ring[i % ring.size()];
    s += (i ? "," : "") + format_number(p.x) + " " + format_number(p.y);
  }
  return s + "))";
}

}  // namespace fleetmap
