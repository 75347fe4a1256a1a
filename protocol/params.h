#pragma once
// Typed JSON parameters of every op (SPEC 5.2), with validation: a missing field, a
// wrong type, a non-finite or out-of-range number gives ProtocolError(bad_params) naming
// the field; params that are not a JSON object give ProtocolError(bad_json).
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/geometry/geometry.h"
#include "common/core/error.h"
#include "common/planning/tour_event.h"
#include "protocol/ops.h"

namespace fleetmap {

using Json = nlohmann::json;

class ProtocolError : public BadInput {
 public:
  ProtocolError(ErrorCode code, const std::string& message) : BadInput(message), code_(code) {}
  ErrorCode code() const { return code_; }

 private:
  ErrorCode code_;
};

// How a map travels in SetMap (SPEC 5.4).
enum class MapEncoding { Seed, SeedCompress };
std::string_view name(MapEncoding e);
std::optional<MapEncoding> parse_map_encoding(std::string_view s);

// What GetMap's SetMap holds (seed 002 section 3.4, docs/wire-format.md):
//   TwoD         "2d" (the default): the map the robot's laser sees, i.e. the segment map
//                sliced at its profile's laser height plus the objects seen there.
//   TwoAndHalfD  "2.5d": the segments unsliced, with their heights, plus the objects
//                with their height ranges (params "scene", GeoJSON), for robots that
//                slice for themselves.
enum class MapMode { TwoD, TwoAndHalfD };
std::string_view name(MapMode m);
std::optional<MapMode> parse_map_mode(std::string_view s);

// Robot -> server.
struct ReadyParams { long long magic = 0; std::optional<MapEncoding> encoding; };
struct OpAckParams { unsigned long long answer_id = 0; };
// "status": "lost" (optional; default "localized"): the robot's localization says it
// no longer knows where it is (client/localization/lost_detector.h). Its pose fields
// may then be left out, and are not stored (docs/protocol.md).
struct SendPosParams {
  double x = 0, y = 0, theta = 0, v = 0;
  std::optional<double> w;
  bool lost = false;
};
struct SendGpsParams { double lat = 0, lon = 0; };
struct SendImageParams { double x = 0, y = 0; std::optional<long long> object_id; std::string format; };
struct GetMapParams {
  double x = 0, y = 0, w = 0, h = 0;
  std::optional<MapEncoding> encoding;
  std::optional<MapMode> mode;  // nullopt: "2d"
};
struct SetObjectParams { double x = 0, y = 0; std::string object; };
// TourEvent (docs/protocol.md): what the guide said (seed 003 §III); the pose is the
// robot's last SendPos unless all of x, y, theta are given.
struct TourEventParams {
  TourEventKind kind = TourEventKind::EnterCorridor;
  std::string name;  // "" when absent; a place needs one
  std::string tour;  // "" when absent: the robot's default tour
  std::optional<double> x, y, theta;
};

// The params column as a JSON object; throws ProtocolError(bad_json).
Json parse_params(std::string_view text);

ReadyParams decode_ready(const Json& j);
OpAckParams decode_op_ack(const Json& j);
SendPosParams decode_send_pos(const Json& j);
SendGpsParams decode_send_gps(const Json& j);
SendImageParams decode_send_image(const Json& j);
GetMapParams decode_get_map(const Json& j);
SetObjectParams decode_set_object(const Json& j);
TourEventParams decode_tour_event(const Json& j);
void decode_empty(const Json& j);  // Alive, Stopped, GetPath, GetPosIni, GetPosEnd: {} (extra fields ignored)

// Server -> robot.
struct StartParams { long long magic = 0; unsigned robot_id = 0; double alive_period_s = 0; };
struct SetMapParams {
  double border[4] = {0, 0, 0, 0};
  size_t obstacles = 0, segments = 0;
  MapEncoding encoding = MapEncoding::Seed;
  // Written only when set, so that a robot without a profile gets the plain SetMap of
  // SPEC 5.4: the laser height the map is sliced at, and "2.5d" (GetMap mode).
  std::optional<double> laser_height;
  std::optional<MapMode> mode;
};
// SetPath (SPEC 5.2) with the topological route it follows, when GetPath planned through
// the map's graph (docs/protocol.md, "SetPath: nodes and edges"): the graph nodes in
// route order and the edges between them, edges[i] joining nodes[i] and nodes[i + 1].
// Both absent (empty) for a whole-map RRT path; written only when set, and a robot that
// does not know them ignores them (decoders skip unknown keys). The edge type is kept as
// text ("corridor", "room", "door", "stairs", "elevator", common/planning/topo_graph.h)
// so that a type added later does not make an older robot refuse the whole path.
struct PathNode {
  int id = 0;
  std::string name;  // "" when the node has none
  double x = 0, y = 0;
  friend bool operator==(const PathNode&, const PathNode&) = default;
};
struct PathEdge {
  int from = 0, to = 0;
  std::string type;
  friend bool operator==(const PathEdge&, const PathEdge&) = default;
};
struct SetPathParams {
  std::vector<Point> waypoints;
  double length = 0;
  std::vector<PathNode> nodes;
  std::vector<PathEdge> edges;
};
struct SetPoseParams { double x = 0, y = 0; std::optional<double> theta; };
struct ErrorParams { std::optional<unsigned long long> request_id; ErrorCode code = ErrorCode::Internal; std::string message; };

Json encode(const StartParams& p);
Json encode(const SetMapParams& p);
Json encode(const SetPathParams& p);
Json encode(const SetPoseParams& p);  // SetPosIni (theta optional) and SetPosEnd
Json encode(const ErrorParams& p);
Json encode_op_ack(unsigned long long request_id);
Json encode_abort(const std::string& reason);

StartParams decode_start(const Json& j);
SetMapParams decode_set_map(const Json& j);
SetPathParams decode_set_path(const Json& j);
SetPoseParams decode_set_pose(const Json& j);
ErrorParams decode_error(const Json& j);

}  // namespace fleetmap
