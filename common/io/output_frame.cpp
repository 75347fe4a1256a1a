#include "common/io/output_frame.h"

#include <cmath>
#include <stdexcept>

namespace fleetmap {

Point OutputFrame::apply(Point map) const {
  if (!from_map) return map;
  Point p = from_map(map);
  if (decimals >= 0) {
    const double k = std::pow(10.0, decimals);
    p = {std::round(p.x * k) / k, std::round(p.y * k) / k};
  }
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
    throw std::invalid_argument("expected the " + name + " frame to map every point, got a NaN or infinity");
  return p;
}

}  // namespace fleetmap
