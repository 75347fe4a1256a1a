// Ready (SPEC 5.2): a new session for the account; Start, then SetMap of the whole map
// or, for a large map, of a window around the robot's best known position.
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_ready(HandlerContext& ctx) {
  const ReadyParams p = decode_ready(ctx.params);
  ctx.answer(AnswerOp::Start, encode(StartParams{p.magic, ctx.robot.id, ctx.config.alive_period_s}));
  const MapEncoding e = p.encoding.value_or(MapEncoding::Seed);
  const std::optional<MapInfo> info = ctx.map_info();
  if (info && info->segments > ctx.config.max_full_map_segments) {
    // Last reported pose, else the operator's initial pose, else the map's centre.
    const Rect b = info->border.rect();
    Point c{(b.xmin + b.xmax) / 2, (b.ymin + b.ymax) / 2};
    if (ctx.robot.x && ctx.robot.y) c = {*ctx.robot.x, *ctx.robot.y};
    else if (ctx.robot.ini_x && ctx.robot.ini_y) c = {*ctx.robot.ini_x, *ctx.robot.ini_y};
    const Rect w = Rect::centred(c, ctx.config.ready_window_m, ctx.config.ready_window_m);
    answer_map(ctx, &w, e);
  } else {
    answer_map(ctx, nullptr, e);
  }
  // Last, after everything that may refuse the request: no direct write before an Error.
  ctx.records.start_session(ctx.robot.id, p.magic);
  ctx.robot.magic = p.magic;
  ctx.robot.state = RobotState::Ready;
}

}  // namespace fleetmap
