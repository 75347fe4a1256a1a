#include "server/cli/gis_publish.h"

#include <cstdio>
#include <exception>

#include "common/gis/map_frame_crs.h"
#include "protocol/gis_layers.h"
#include "protocol/map_store.h"

namespace fleetmap {

namespace {

template <class F>
void warn_on_failure(const std::string& what, F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "warning: GIS layers %s not refreshed: %s\n", what.c_str(), e.what());
  }
}

}  // namespace

void publish_gis_layers(mysqlpp::Connection& c, const std::string& name) {
  warn_on_failure("of '" + name + "'", [&] {
    const MapInfo info = MapStore(c).info(name);
    GisLayers(c).publish(name, map_frame_crs_wkt(name, info.georef));
  });
}

void withdraw_gis_layers(mysqlpp::Connection& c) {
  warn_on_failure("of deleted maps", [&] { GisLayers(c).withdraw(); });
}

}  // namespace fleetmap
