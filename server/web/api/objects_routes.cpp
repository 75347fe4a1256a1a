// GET /api/maps/{map}/objects and GET /api/maps/{map}/avoided: the semantic layer
// (seed 002 section 3) as GeoJSON, in the format `fleetmap objects export` writes
// (common/io/scene_geojson.h). Objects are the live ones the server plans with:
// imported, and robots' observations not yet expired (protocol/live_scene.h).
#include "common/io/scene_geojson.h"
#include "protocol/live_scene.h"
#include "protocol/map_store.h"
#include "server/web/api/map_frame.h"
#include "server/web/api/route_groups.h"

namespace fleetmap::web {
namespace {

enum class Layer { Objects, Avoided };

ApiResponse scene_layer(const ApiRequest& req, ApiContext& ctx, Layer layer) {
  const std::string& name = req.args.at(0);
  const MapInfo info = MapStore(ctx.reader()).info(name);  // MapNotFound: 404
  const OutputFrame frame = requested_frame(req, name, info.georef);
  Scene scene = read_scene(ctx.reader(), info.id, SceneObjects::Live);
  scene.bounds.reset();
  if (layer == Layer::Objects) scene.avoided.clear();
  else scene.objects.clear();
  return geojson_response(write_scene_geojson(scene, frame));
}

}  // namespace

std::vector<Route> objects_routes() {
  return {
      {"GET", "/api/maps/{map}/objects", false,
       "a map's live objects (imported and observed) as GeoJSON (map frame; ?crs=wgs84)",
       [](const ApiRequest& req, ApiContext& ctx) { return scene_layer(req, ctx, Layer::Objects); }},
      {"GET", "/api/maps/{map}/avoided", false, "a map's avoided areas as GeoJSON (map frame; ?crs=wgs84)",
       [](const ApiRequest& req, ApiContext& ctx) { return scene_layer(req, ctx, Layer::Avoided); }},
  };
}

}  // namespace fleetmap::web
