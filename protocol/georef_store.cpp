#include "protocol/georef_store.h"

#include <charconv>

#include "common/geometry/number_format.h"
#include "protocol/connection.h"
#include "protocol/sql_util.h"
#include "protocol/map_store.h"

namespace fleetmap {

using sql::to_double;
using sql::to_int;

namespace {

}  // namespace

void GeorefStore::set_fitted(const std::string& map, const MapGeoref& georef,
                             const std::vector<StoredControlPoint>& points) {
  Transaction tx(c_);
  MapStore maps(c_);
  const unsigned id = maps.info(map).id;
  maps.set_georef(map, georef);  // deletes the points of the georeference before
  if (!points.empty()) {
    mysqlpp::Query q = c_.query();
    q << "INSERT INTO georef_control_points (map_id, ord, x, y, lat, lon, residual_m) VALUES ";
    for (size_t i = 0; i < points.size(); ++i) {
      const StoredControlPoint& p = points[i];
      q << (i ? "," : "") << "(" << id << "," << i + 1 << "," << format_number(p.x) << "," << format_number(p.y)
        << "," << format_number(p.lat) << "," << format_number(p.lon) << "," << format_number(p.residual_m) << ")";
    }
    q.execute();
  }
  tx.commit();
}

std::vector<StoredControlPoint> GeorefStore::control_points(const std::string& map) {
  const unsigned id = MapStore(c_).info(map).id;
  mysqlpp::Query q = c_.query();
  q << "SELECT x, y, lat, lon, residual_m FROM georef_control_points WHERE map_id = " << id << " ORDER BY ord";
  std::vector<StoredControlPoint> out;
  for (const mysqlpp::Row& r : q.store())
    out.push_back({to_double(r[0]), to_double(r[1]), to_double(r[2]), to_double(r[3]), to_double(r[4])});
  return out;
}

}  // namespace fleetmap
