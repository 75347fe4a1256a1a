#include "common/map/ramp.h"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "common/geometry/number_format.h"

namespace fleetmap {
namespace {

constexpr double kBelowFloorTolerance = 1e-6;  // metres

// The ':'-separated numbers after "name=" in one comma-separated token, or nullopt when
// no token has that name.
std::optional<std::vector<double>> token_numbers(std::string_view semantic, std::string_view name,
                                                 size_t count, std::string_view layout) {
  const std::string key = std::string(name) + "=";
  size_t start = 0;
  while (start <= semantic.size()) {
    size_t comma = semantic.find(',', start);
    if (comma == std::string_view::npos) comma = semantic.size();
    const std::string_view tok = semantic.substr(start, comma - start);
    start = comma + 1;
    if (tok.substr(0, key.size()) != key) continue;
    std::vector<double> out;
    std::string_view rest = tok.substr(key.size());
    for (;;) {
      const size_t colon = rest.find(':');
      const std::string_view f = rest.substr(0, colon);
      double v = 0;
      auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
      if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v))
        throw std::invalid_argument("expected ramp token '" + std::string(layout) + "' with finite numbers, got '" +
                                    std::string(tok) + "'");
      out.push_back(v);
      if (colon == std::string_view::npos) break;
      rest = rest.substr(colon + 1);
    }
    if (out.size() != count)
      throw std::invalid_argument("expected ramp token '" + std::string(layout) + "' (" + std::to_string(count) +
                                  " numbers), got '" + std::string(tok) + "'");
    return out;
  }
  return std::nullopt;
}

}  // namespace

RampSurface parse_ramp_surface(std::string_view semantic) {
  auto n = token_numbers(semantic, "normal", 3, "normal=NX:NY:NZ");
  if (!n) throw std::invalid_argument("expected 'normal=NX:NY:NZ' in the ramp's semantic string, got '" +
                                      std::string(semantic) + "'");
  if (!((*n)[2] > 0))
    throw std::invalid_argument("expected a ramp normal pointing up (NZ > 0), got NZ = " + format_number((*n)[2]));
  auto f = token_numbers(semantic, "foot", 2, "foot=X:Y");
  if (!f) throw std::invalid_argument("expected 'foot=X:Y' in the ramp's semantic string, got '" +
                                      std::string(semantic) + "'");
  return {{-(*n)[0] / (*n)[2], -(*n)[1] / (*n)[2]}, {(*f)[0], (*f)[1]}};
}

RampSurface ramp_surface(const Obstacle& ramp) {
  RampSurface s = parse_ramp_surface(ramp.semantic);
  for (const Segment& seg : ramp.segments)
    for (Point p : {seg.a, seg.b})
      if (s.height_at(p) < -kBelowFloorTolerance)
        throw std::invalid_argument("expected the ramp surface on or above the floor at every vertex, got " +
                                    format_number(s.height_at(p)) + " m at (" + format_number(p.x) + ";" +
                                    format_number(p.y) + ")");
  return s;
}

std::string ramp_tokens(double nx, double ny, double nz, Point foot) {
  return "normal=" + format_number(nx) + ":" + format_number(ny) + ":" + format_number(nz) +
         ",foot=" + format_number(foot.x) + ":" + format_number(foot.y);
}

}  // namespace fleetmap
