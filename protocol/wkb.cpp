#include "protocol/wkb.h"

#include <cstdint>
#include <cstring>

#include "protocol/connection.h"

namespace fleetmap {

// ST_AsBinary(polygon): byte order, type 3, rings, then per ring its points as doubles.
Polygon polygon_from_wkb(const mysqlpp::String& s) {
  const char* b = s.data();
  const size_t len = s.length();
  size_t at = 0;
  auto u32 = [&] {
    if (at + 4 > len) throw DbError("truncated polygon from the database");
    uint32_t v;
    std::memcpy(&v, b + at, 4);
    at += 4;
    return v;
  };
  auto f64 = [&] {
    if (at + 8 > len) throw DbError("truncated polygon from the database");
    double v;
    std::memcpy(&v, b + at, 8);
    at += 8;
    return v;
  };
  if (len < 1 || b[0] != 1) throw DbError("expected a little-endian WKB polygon from the database");
  at = 1;
  if (u32() != 3 || u32() < 1) throw DbError("expected a WKB polygon from the database");
  const uint32_t points = u32();
  Polygon ring;
  for (uint32_t i = 0; i < points; ++i) {
    const double x = f64();
    ring.push_back({x, f64()});
  }
  if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
  return ring;
}

}  // namespace fleetmap
