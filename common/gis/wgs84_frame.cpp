#include "common/gis/wgs84_frame.h"

#include <memory>

#include "common/gis/geo_transform.h"

namespace fleetmap {

OutputFrame wgs84_frame(const MapGeoref& georef) {
  auto t = std::make_shared<const GeoTransform>(georef);
  OutputFrame f;
  f.name = "wgs84";
  f.units = "degree";
  f.decimals = 9;
  f.from_map = [t](Point p) {
    const LonLat ll = t->to_wgs84(p);
    return Point{ll.lon, ll.lat};
  };
  return f;
}

}  // namespace fleetmap
