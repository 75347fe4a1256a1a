#pragma once
// A map's georeference computed with PROJ: WGS 84 longitude/latitude <-> the map frame,
// through the base CRS of common/map/map_georef.h. Every SendGPS fix, WGS 84 export and
// GIS import goes through this one class.
#include <memory>
#include <mutex>
#include <string>

#include "common/geometry/geometry.h"
#include "common/map/map_georef.h"

namespace fleetmap {

struct LonLat {
  double lon = 0, lat = 0;  // degrees, WGS 84 (EPSG:4326 in GIS axis order)
};

class GeoTransform {
 public:
  // Throws BadInput naming the CRS when PROJ cannot read it, or when it is not a
  // projected CRS in metres, or when the similarity is not finite with scale > 0.
  explicit GeoTransform(const MapGeoref& georef);
  ~GeoTransform();
  GeoTransform(GeoTransform&&) noexcept;
  GeoTransform& operator=(GeoTransform&&) noexcept;

  // Throws BadInput when PROJ cannot transform the point (outside the CRS's domain).
  Point to_map(LonLat ll) const;
  LonLat to_wgs84(Point map) const;

  Point map_to_base(Point map) const;
  Point base_to_map(Point base) const;

  const MapGeoref& georef() const { return georef_; }
  // The base CRS as OGC WKT (WKT1 as GDAL writes it when the CRS has one, else WKT2),
  // for spatial_ref_sys and OGR writers.
  std::string base_wkt() const;

 private:
  struct Proj;
  MapGeoref georef_;
  std::unique_ptr<Proj> proj_;  // PROJ objects are not reentrant: calls lock proj_->mutex
};

// The local Transverse Mercator at (lat0, lon0) on the WGS 84 ellipsoid, k0 = 1, no
// false origin: a conformal metric plane whose scale error is 1.2e-6 at 10 km from the
// origin. A PROJ string that PROJ reads as a CRS.
std::string local_tm_crs(double lat0, double lon0);

// A georeference by the map origin's position and the heading of the map x axis
// (radians, counter-clockwise from east): the local TM at the origin, rotated.
MapGeoref georef_from_origin(double lat0, double lon0, double heading);

}  // namespace fleetmap
