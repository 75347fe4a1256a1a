#pragma once
// A map's georeference with the control points it was fitted to (sql/55_georef.sql;
// the georeference itself is maps.geo_*, protocol/map_store.h). Plain data both ways:
// the fit is common/gis/control_point_fit.h, the operator's command server/cli.
//
//   GeorefStore store(conn);
//   store.set_fitted("floor", fit.georef, points);   // one transaction
//   for (const StoredControlPoint& p : store.control_points("floor")) ...
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "common/map/map_georef.h"

namespace fleetmap {

struct StoredControlPoint {
  double x = 0, y = 0;      // map frame, metres
  double lat = 0, lon = 0;  // WGS 84, degrees
  double residual_m = 0;    // ground distance between the fitted and the given position
  friend bool operator==(const StoredControlPoint&, const StoredControlPoint&) = default;
};

class GeorefStore {
 public:
  explicit GeorefStore(mysqlpp::Connection& c) : c_(c) {}

  // Stores georef as the map's georeference and points as its control points, replacing
  // any before, in one transaction. Throws MapNotFound.
  void set_fitted(const std::string& map, const MapGeoref& georef, const std::vector<StoredControlPoint>& points);

  // The map's control points in the order given to the fit; empty when its georeference
  // came another way (origin, CRS, import) or it has none. Throws MapNotFound.
  std::vector<StoredControlPoint> control_points(const std::string& map);

 private:
  mysqlpp::Connection& c_;
};

}  // namespace fleetmap
