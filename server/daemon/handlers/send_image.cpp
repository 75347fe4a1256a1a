// SendImage (SPEC 5.2): the image is stored with the pose and the object it shows.
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_send_image(HandlerContext& ctx) {
  const SendImageParams p = decode_send_image(ctx.params);
  if (!ctx.request.payload || ctx.request.payload->empty())
    throw ProtocolError(ErrorCode::BadParams, "payload: expected the image bytes, got none");
  if (ctx.request.payload->size() > ctx.config.max_image_bytes)
    throw ProtocolError(ErrorCode::PayloadTooLarge, "payload: expected at most " +
                                                        std::to_string(ctx.config.max_image_bytes) + " bytes, got " +
                                                        std::to_string(ctx.request.payload->size()));
  ctx.records.record_image(ctx.robot.id, p, *ctx.request.payload, ctx.request.created_at);
  ctx.op_ack();
}

}  // namespace fleetmap
