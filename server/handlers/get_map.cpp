// GetMap (SPEC 5.2, 5.4): the w x h window centred on (x, y), sides capped by
// configuration, clipped to the map's border.
#include <algorithm>

#include "server/handlers/handler.h"

namespace fleetmap {

void handle_get_map(HandlerContext& ctx) {
  const GetMapParams p = decode_get_map(ctx.params);
  const double cap = ctx.config.max_window_m;
  const Rect w = Rect::centred({p.x, p.y}, std::min(p.w, cap), std::min(p.h, cap));
  answer_map(ctx, &w, p.encoding.value_or(MapEncoding::Seed));
}

}  // namespace fleetmap
