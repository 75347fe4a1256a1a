#include "server/cli/list_json.h"

namespace fleetmap {

nlohmann::json maps_json(const std::vector<MapInfo>& maps) {
  nlohmann::json out = nlohmann::json::array();
  for (const MapInfo& i : maps) {
    nlohmann::json georef;  // null: not georeferenced
    if (i.georef)
      georef = {{"crs", i.georef->crs}, {"tx", i.georef->tx}, {"ty", i.georef->ty},
                {"rotation", i.georef->rotation}, {"scale", i.georef->scale}};
    out.push_back({{"name", i.name}, {"id", i.id}, {"obstacles", i.obstacles}, {"segments", i.segments},
                   {"border", {i.border.mx1, i.border.my1, i.border.mx4, i.border.my4}}, {"source", i.source},
                   {"imported_at", i.imported_at}, {"georef", georef}});
  }
  return out;
}

}  // namespace fleetmap
