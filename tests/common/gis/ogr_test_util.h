#pragma once
// Reading exports back for the tests of common/gis: OGR's own reading of a file, and
// PROJ called directly (not through GeoTransform) for the expected coordinates.
#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#include <proj.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/geometry/geometry.h"

namespace fleetmap::test {

inline std::string source_file(const std::string& rel) { return std::string(FLEETMAP_SOURCE_DIR) + "/" + rel; }

inline std::string text_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string scratch(const std::string& name) { return ::testing::TempDir() + "fleetmap_gis_" + name; }

struct GdalCloser {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, GdalCloser>;

inline Dataset open_vector(const std::string& path) {
  GDALAllRegister();
  return Dataset(static_cast<GDALDataset*>(GDALOpenEx(path.c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr)));
}

// source CRS (x, y) -> WGS 84 (lon, lat), PROJ in GIS axis order.
class ProjToWgs84 {
 public:
  explicit ProjToWgs84(const std::string& source) {
    ctx_ = proj_context_create();
    PJ* raw = proj_create_crs_to_crs(ctx_, source.c_str(), "EPSG:4326", nullptr);
    pj_ = proj_normalize_for_visualization(ctx_, raw);
    proj_destroy(raw);
  }
  ~ProjToWgs84() {
    proj_destroy(pj_);
    proj_context_destroy(ctx_);
  }
  ProjToWgs84(const ProjToWgs84&) = delete;
  ProjToWgs84& operator=(const ProjToWgs84&) = delete;
  Point operator()(Point p) const {
    const PJ_COORD c = proj_trans(pj_, PJ_FWD, proj_coord(p.x, p.y, 0, 0));
    return {c.xy.x, c.xy.y};
  }
  bool ok() const { return pj_ != nullptr; }

 private:
  PJ_CONTEXT* ctx_ = nullptr;
  PJ* pj_ = nullptr;
};

// Ground distance between two nearby lon/lat points (m), good to 1e-3 relative at these
// few-metre differences: enough to bound an error of a millimetre.
inline double ground_metres(Point a, Point b) {
  const double k = 6378137.0 * M_PI / 180;
  return std::hypot((a.x - b.x) * k * std::cos(a.y * M_PI / 180), (a.y - b.y) * k);
}

}  // namespace fleetmap::test
