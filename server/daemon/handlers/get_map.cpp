// GetMap (SPEC 5.2, 5.4): the w x h window centred on (x, y), sides capped by
// configuration, clipped to the map's border. "mode" (seed 002 section 3.4, docs/wire-format.md):
// "2d" (the default) is the map the robot's laser sees (answer_map); "2.5d" is the
// window of the stored segments, unsliced, with the scene's objects in params "scene".
#include <algorithm>

#include "common/io/scene_geojson.h"
#include "protocol/map_codec.h"
#include "server/daemon/handlers/handler.h"
#include "server/daemon/robot_map_source.h"  // scene_in_window

namespace fleetmap {
namespace {

void answer_map_with_scene(HandlerContext& ctx, const Rect& window, MapEncoding encoding) {
  const MapInfo info = robot_map_info(ctx);
  const Rect r = intersection(window, info.border.rect());
  if (r.empty()) throw ProtocolError(ErrorCode::BadParams, "params: expected a window that overlaps the map's border");
  const Map m = ctx.maps.robot_map(info, r, std::nullopt);
  const auto scene = ctx.maps.scene(info.id);
  SetMapParams p = set_map_params(m, encoding);
  p.mode = MapMode::TwoAndHalfD;
  Json params = encode(p);
  params["scene"] = Json::parse(write_scene_geojson(scene_in_window(*scene, r)));
  ctx.answer(AnswerOp::SetMap, std::move(params), encode_map(m, encoding));
}

}  // namespace

void handle_get_map(HandlerContext& ctx) {
  const GetMapParams p = decode_get_map(ctx.params);
  const double cap = ctx.config.max_window_m;
  const Rect w = Rect::centred({p.x, p.y}, std::min(p.w, cap), std::min(p.h, cap));
  const MapEncoding e = p.encoding.value_or(MapEncoding::Seed);
  if (p.mode.value_or(MapMode::TwoD) == MapMode::TwoAndHalfD) answer_map_with_scene(ctx, w, e);
  else answer_map(ctx, &w, e);
}

}  // namespace fleetmap
