#include "protocol/params.h"

#include <cmath>
#include <limits>

namespace fleetmap {
namespace {

// Largest coordinate a robot may send: the map frame's own limit (10 000 km).
constexpr double kMaxCoordinate = 1e7;
constexpr double kMaxSpeed = 1e3;  // m/s or rad/s: anything above is a unit error
constexpr size_t kMaxTextBytes = 255;
constexpr size_t kMaxImageFormatBytes = 32;  // images.format VARCHAR(32)

[[noreturn]] void bad(const std::string& field, const std::string& what) {
  throw ProtocolError(ErrorCode::BadParams, "params." + field + ": expected " + what);
}

const Json* find(const Json& j, const char* field) {
  auto it = j.find(field);
  return it == j.end() ? nullptr : &*it;
}

double number(const Json& j, const char* field, double limit = kMaxCoordinate) {
  const Json* v = find(j, field);
  if (!v) bad(field, "a number, got nothing");
  if (!v->is_number()) bad(field, "a number, got " + std::string(v->type_name()));
  const double d = v->get<double>();
  if (!std::isfinite(d)) bad(field, "a finite number");
  if (std::abs(d) > limit) bad(field, "a number within ±" + std::to_string(limit).substr(0, 9));
  return d;
}

std::optional<double> optional_number(const Json& j, const char* field, double limit = kMaxCoordinate) {
  const Json* v = find(j, field);
  if (!v || v->is_null()) return std::nullopt;
  return number(j, field, limit);
}

long long integer(const Json& j, const char* field) {
  const Json* v = find(j, field);
  if (!v) bad(field, "an integer, got nothing");
  if (!v->is_number_integer()) bad(field, "an integer, got " + std::string(v->type_name()));
  if (v->is_number_unsigned() && v->get<unsigned long long>() > static_cast<unsigned long long>(std::numeric_limits<long long>::max()))
    bad(field, "an integer within 64-bit range");
  return v->get<long long>();
}

// max_bytes: the column's width (sql/10_schema.sql), so what decodes also stores.
std::string text(const Json& j, const char* field, size_t max_bytes = kMaxTextBytes) {
  const Json* v = find(j, field);
  if (!v) bad(field, "a string, got nothing");
  if (!v->is_string()) bad(field, "a string, got " + std::string(v->type_name()));
  std::string s = v->get<std::string>();
  if (s.empty() || s.size() > max_bytes) bad(field, "a string of 1-" + std::to_string(max_bytes) + " bytes");
  return s;
}

std::optional<MapEncoding> optional_encoding(const Json& j) {
  const Json* v = find(j, "encoding");
  if (!v || v->is_null()) return std::nullopt;
  if (!v->is_string()) bad("encoding", "\"seed\" or \"seed+compress\"");
  auto e = parse_map_encoding(v->get<std::string>());
  if (!e) bad("encoding", "\"seed\" or \"seed+compress\", got \"" + v->get<std::string>() + "\"");
  return e;
}

std::optional<MapMode> optional_mode(const Json& j) {
  const Json* v = find(j, "mode");
  if (!v || v->is_null()) return std::nullopt;
  if (!v->is_string()) bad("mode", "\"2d\" or \"2.5d\", got " + std::string(v->type_name()));
  auto m = parse_map_mode(v->get<std::string>());
  if (!m) bad("mode", "\"2d\" or \"2.5d\", got \"" + v->get<std::string>() + "\"");
  return m;
}

void require_object(const Json& j) {
  if (!j.is_object()) throw ProtocolError(ErrorCode::BadJson, "params: expected a JSON object");
}

}  // namespace

std::string_view name(MapEncoding e) { return e == MapEncoding::Seed ? "seed" : "seed+compress"; }

std::optional<MapEncoding> parse_map_encoding(std::string_view s) {
  if (s == "seed") return MapEncoding::Seed;
  if (s == "seed+compress") return MapEncoding::SeedCompress;
  return std::nullopt;
}

std::string_view name(MapMode m) { return m == MapMode::TwoD ? "2d" : "2.5d"; }

std::optional<MapMode> parse_map_mode(std::string_view s) {
  if (s == "2d") return MapMode::TwoD;
  if (s == "2.5d") return MapMode::TwoAndHalfD;
  return std::nullopt;
}

Json parse_params(std::string_view text) {
  // A robot can SET check_constraint_checks=0 and store anything in the JSON column.
  Json j;
  try {
    j = Json::parse(text.begin(), text.end());
  } catch (const Json::out_of_range&) {
    // Valid JSON whose number does not fit a double (1e999): a field out of range.
    throw ProtocolError(ErrorCode::BadParams, "params: expected finite numbers, got one out of double range");
  } catch (const Json::exception&) {
    throw ProtocolError(ErrorCode::BadJson, "params: expected JSON, got unparsable text");
  }
  require_object(j);
  return j;
}

ReadyParams decode_ready(const Json& j) {
  require_object(j);
  return {integer(j, "magic"), optional_encoding(j)};
}

OpAckParams decode_op_ack(const Json& j) {
  require_object(j);
  const long long id = integer(j, "answer_id");
  if (id <= 0) bad("answer_id", "a positive integer");
  return {static_cast<unsigned long long>(id)};
}

SendPosParams decode_send_pos(const Json& j) {
  require_object(j);
  bool lost = false;
  if (const Json* st = find(j, "status")) {
    const std::string s = st->is_string() ? st->get<std::string>() : std::string();
    if (s != "localized" && s != "lost") bad("status", "\"localized\" or \"lost\"");
    lost = s == "lost";
  }
  if (lost)  // a robot that does not know where it is need not make a pose up
    return {optional_number(j, "x").value_or(0), optional_number(j, "y").value_or(0),
            optional_number(j, "theta", 1e3).value_or(0), optional_number(j, "v", kMaxSpeed).value_or(0),
            optional_number(j, "w", kMaxSpeed), true};
  return {number(j, "x"), number(j, "y"), number(j, "theta", 1e3), number(j, "v", kMaxSpeed),
          optional_number(j, "w", kMaxSpeed), false};
}

SendGpsParams decode_send_gps(const Json& j) {
  require_object(j);
  return {number(j, "lat", 90), number(j, "lon", 180)};
}

SendImageParams decode_send_image(const Json& j) {
  require_object(j);
  SendImageParams p;
  p.x = number(j, "x");
  p.y = number(j, "y");
  if (const Json* v = find(j, "object_id"); v && !v->is_null()) p.object_id = integer(j, "object_id");
  p.format = text(j, "format", kMaxImageFormatBytes);
  return p;
}

GetMapParams decode_get_map(const Json& j) {
  require_object(j);
  GetMapParams p{number(j, "x"), number(j, "y"), number(j, "w"), number(j, "h"), optional_encoding(j), optional_mode(j)};
  if (!(p.w > 0)) bad("w", "a width > 0");
  if (!(p.h > 0)) bad("h", "a height > 0");
  return p;
}

SetObjectParams decode_set_object(const Json& j) {
  require_object(j);
  return {number(j, "x"), number(j, "y"), text(j, "object")};
}

TourEventParams decode_tour_event(const Json& j) {
  require_object(j);
  TourEventParams p;
  const std::string event = text(j, "event");
  const std::optional<TourEventKind> kind = tour_event_kind_from_string(event);
  if (!kind) bad("event", "\"corridor\", \"room\", \"door\", \"crossing\" or \"place\", got \"" + event + "\"");
  p.kind = *kind;
  if (const Json* v = find(j, "name"); v && !v->is_null()) p.name = text(j, "name");
  if (p.kind == TourEventKind::Place && p.name.empty()) bad("name", "a name for a place, got nothing");
  if (const Json* v = find(j, "tour"); v && !v->is_null()) p.tour = text(j, "tour");
  p.x = optional_number(j, "x");
  p.y = optional_number(j, "y");
  p.theta = optional_number(j, "theta", 1e3);
  const int given = p.x.has_value() + p.y.has_value() + p.theta.has_value();
  if (given != 0 && given != 3) bad(p.x ? (p.y ? "theta" : "y") : "x", "x, y and theta together, or none of them");
  return p;
}

void decode_empty(const Json& j) { require_object(j); }

Json encode(const StartParams& p) {
  return {{"magic", p.magic}, {"robot_id", p.robot_id}, {"alive_period_s", p.alive_period_s}};
}

Json encode(const SetMapParams& p) {
  Json j = {{"border", {p.border[0], p.border[1], p.border[2], p.border[3]}},
          {"obstacles", p.obstacles},
          {"segments", p.segments},
          {"encoding", std::string(name(p.encoding))}};
  if (p.laser_height) j["laser_height"] = *p.laser_height;
  if (p.mode) j["mode"] = std::string(name(*p.mode));
  return j;
}

Json encode(const SetPathParams& p) {
  Json w = Json::array();
  for (Point q : p.waypoints) w.push_back({q.x, q.y});
  Json j = {{"waypoints", w}, {"length", p.length}};
  if (!p.nodes.empty()) {
    Json& nodes = j["nodes"] = Json::array();
    for (const PathNode& n : p.nodes) nodes.push_back({{"id", n.id}, {"name", n.name}, {"x", n.x}, {"y", n.y}});
  }
  if (!p.edges.empty()) {
    Json& edges = j["edges"] = Json::array();
    for (const PathEdge& e : p.edges) edges.push_back({{"from", e.from}, {"to", e.to}, {"type", e.type}});
  }
  return j;
}

Json encode(const SetPoseParams& p) {
  Json j = {{"x", p.x}, {"y", p.y}};
  if (p.theta) j["theta"] = *p.theta;
  return j;
}

Json encode(const ErrorParams& p) {
  Json j = {{"code", std::string(name(p.code))}, {"message", p.message}};
  j["request_id"] = p.request_id ? Json(*p.request_id) : Json(nullptr);
  return j;
}

Json encode_op_ack(unsigned long long request_id) { return {{"request_id", request_id}}; }
Json encode_abort(const std::string& reason) { return {{"reason", reason}}; }

StartParams decode_start(const Json& j) {
  require_object(j);
  const long long id = integer(j, "robot_id");
  if (id <= 0 || id > 4294967295LL) bad("robot_id", "a positive 32-bit integer");
  return {integer(j, "magic"), static_cast<unsigned>(id), number(j, "alive_period_s")};
}

SetMapParams decode_set_map(const Json& j) {
  require_object(j);
  SetMapParams p;
  const Json* b = find(j, "border");
  if (!b || !b->is_array() || b->size() != 4) bad("border", "[mx1, my1, mx4, my4]");
  for (int i = 0; i < 4; ++i) {
    if (!(*b)[i].is_number()) bad("border", "four numbers");
    p.border[i] = (*b)[i].get<double>();
  }
  const long long obstacles = integer(j, "obstacles"), segments = integer(j, "segments");
  if (obstacles < 0) bad("obstacles", "a count >= 0");
  if (segments < 0) bad("segments", "a count >= 0");
  p.obstacles = static_cast<size_t>(obstacles);
  p.segments = static_cast<size_t>(segments);
  p.encoding = optional_encoding(j).value_or(MapEncoding::Seed);
  p.laser_height = optional_number(j, "laser_height", 1000);
  p.mode = optional_mode(j);
  return p;
}

SetPathParams decode_set_path(const Json& j) {
  require_object(j);
  SetPathParams p;
  const Json* w = find(j, "waypoints");
  if (!w || !w->is_array()) bad("waypoints", "an array of [x, y]");
  for (const Json& q : *w) {
    if (!q.is_array() || q.size() != 2 || !q[0].is_number() || !q[1].is_number()) bad("waypoints", "[x, y] pairs");
    p.waypoints.push_back({q[0].get<double>(), q[1].get<double>()});
  }
  p.length = number(j, "length");
  // The route (optional): each element is checked with its index in the field's name.
  auto elements = [&](const char* field, const char* what) -> const Json* {
    const Json* v = find(j, field);
    if (!v || v->is_null()) return nullptr;
    if (!v->is_array()) bad(field, what);
    for (const Json& e : *v)
      if (!e.is_object()) bad(field, what);
    return v;
  };
  auto at = [](const char* field, size_t i, const char* key) {
    return std::string(field) + "[" + std::to_string(i) + "]." + key;
  };
  auto id_of = [&](const Json& e, const char* field, size_t i, const char* key) {
    const Json* v = find(e, key);
    if (!v || !v->is_number_integer() || v->get<long long>() < 0 || v->get<long long>() > std::numeric_limits<int>::max())
      bad(at(field, i, key), "a node id (an integer >= 0)");
    return static_cast<int>(v->get<long long>());
  };
  if (const Json* nodes = elements("nodes", "an array of {\"id\", \"name\", \"x\", \"y\"}")) {
    for (size_t i = 0; i < nodes->size(); ++i) {
      const Json& e = (*nodes)[i];
      PathNode n;
      n.id = id_of(e, "nodes", i, "id");
      if (const Json* name = find(e, "name"); name && !name->is_null()) {
        if (!name->is_string()) bad(at("nodes", i, "name"), "a string");
        n.name = name->get<std::string>();
      }
      for (auto [key, out] : {std::pair{"x", &n.x}, std::pair{"y", &n.y}}) {
        const Json* v = find(e, key);
        if (!v || !v->is_number() || !std::isfinite(v->get<double>()) || std::abs(v->get<double>()) > kMaxCoordinate)
          bad(at("nodes", i, key), "a finite coordinate");
        *out = v->get<double>();
      }
      p.nodes.push_back(std::move(n));
    }
  }
  if (const Json* edges = elements("edges", "an array of {\"from\", \"to\", \"type\"}")) {
    for (size_t i = 0; i < edges->size(); ++i) {
      const Json& e = (*edges)[i];
      PathEdge d;
      d.from = id_of(e, "edges", i, "from");
      d.to = id_of(e, "edges", i, "to");
      const Json* type = find(e, "type");
      if (!type || !type->is_string()) bad(at("edges", i, "type"), "a string");
      d.type = type->get<std::string>();
      p.edges.push_back(std::move(d));
    }
  }
  return p;
}

SetPoseParams decode_set_pose(const Json& j) {
  require_object(j);
  return {number(j, "x"), number(j, "y"), optional_number(j, "theta", 1e3)};
}

ErrorParams decode_error(const Json& j) {
  require_object(j);
  ErrorParams p;
  // Request ids are rr's AUTO_INCREMENT ids, so >= 1; a negative one must not wrap.
  if (const Json* r = find(j, "request_id"); r && !r->is_null()) {
    const long long id = integer(j, "request_id");
    if (id <= 0) bad("request_id", "a positive integer");
    p.request_id = static_cast<unsigned long long>(id);
  }
  const Json* c = find(j, "code");
  if (!c || !c->is_string() || !parse_error_code(c->get<std::string>())) bad("code", "an error code");
  p.code = *parse_error_code(c->get<std::string>());
  if (const Json* m = find(j, "message"); m && m->is_string()) p.message = m->get<std::string>();
  return p;
}

}  // namespace fleetmap
