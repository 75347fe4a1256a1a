// Typed params of every op (SPEC 5.2): each decode_* with valid input and with each kind
// of error (missing field, wrong type, out of range, not an object, not JSON), the
// field named in the message; encode/decode round trips of the server's answers; op,
// answer and error-code names exactly as the protocol spells them.
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "protocol/ops.h"
#include "protocol/params.h"

namespace fleetmap {
namespace {

Json J(const char* text) { return Json::parse(text); }

// Runs f, expects ProtocolError with code; returns its message ("" when none was thrown).
template <typename F>
std::string error_of(F&& f, ErrorCode code, const std::string& what) {
  try {
    f();
  } catch (const ProtocolError& e) {
    EXPECT_EQ(name(e.code()), name(code)) << what << ": " << e.what();
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": expected ProtocolError(" << name(code) << "), got another exception: " << e.what();
    return e.what();
  }
  ADD_FAILURE() << what << ": expected ProtocolError(" << name(code) << "), nothing was thrown";
  return "";
}

// decode(j) must be bad_params and its message must name params.<field>.
template <typename D>
void expect_bad_params(D decode, const char* json_text, const std::string& field) {
  const std::string msg = error_of([&] { decode(J(json_text)); }, ErrorCode::BadParams, json_text);
  EXPECT_NE(msg.find("params." + field), std::string::npos) << json_text << " -> " << msg;
}

// Values that are JSON but not an object: every decoder answers bad_json.
const char* const kNotObjects[] = {"[]", "[1, 2]", "null", "42", "1.5", "true", "\"text\""};

template <typename D>
void expect_not_object_is_bad_json(D decode, const char* what) {
  for (const char* t : kNotObjects) {
    const std::string msg = error_of([&] { decode(J(t)); }, ErrorCode::BadJson, std::string(what) + " " + t);
    EXPECT_NE(msg.find("params"), std::string::npos) << msg;
  }
}

// ---- parse_params -----------------------------------------------------------------

TEST(ParseParams, ObjectsAreAccepted) {
  EXPECT_EQ(parse_params("{}"), Json::object());
  EXPECT_EQ(parse_params(R"({"x": 1, "y": [2, 3], "s": "a"})")["y"][1], 3);
  EXPECT_EQ(parse_params("  {\"magic\" : 7}\n"), J(R"({"magic": 7})"));
}

TEST(ParseParams, NonObjectsAreBadJson) {
  for (const char* t : kNotObjects) error_of([&] { parse_params(t); }, ErrorCode::BadJson, t);
}

TEST(ParseParams, UnparsableTextIsBadJson) {
  // What a robot can store after SET check_constraint_checks=0.
  for (const char* t : {"", " ", "{not json", "{", "{\"x\": }", "{\"x\": 1,}", "{} {}", "{} x", "{'x': 1}", "NaN",
                        "{\"x\": NaN}", "{\"x\": Infinity}", "{\"x\": -inf}", "\xff\xfe{}", "{\"s\": \"\xc3\x28\"}"})
    error_of([&] { parse_params(t); }, ErrorCode::BadJson, std::string("'") + t + "'");
}

TEST(ParseParams, NumbersBeyondDoubleRangeAreBadParams) {
  // Valid JSON, but no finite double: a field out of range, not a syntax error.
  for (const char* t : {R"({"x": 1e999})", R"({"x": -1e999})", R"({"w": 1E400, "h": 1})"}) {
    const std::string msg = error_of([&] { parse_params(t); }, ErrorCode::BadParams, t);
    EXPECT_NE(msg.find("params"), std::string::npos) << msg;
  }
  // Underflow to zero or a subnormal is a finite double: accepted.
  EXPECT_EQ(parse_params(R"({"x": 1e-999})")["x"].get<double>(), 0.0);
}

// ---- Ready ------------------------------------------------------------------------

TEST(ParamsReady, Valid) {
  ReadyParams p = decode_ready(J(R"({"magic": 12345})"));
  EXPECT_EQ(p.magic, 12345);
  EXPECT_FALSE(p.encoding);
  p = decode_ready(J(R"({"magic": -7, "encoding": "seed+compress"})"));
  EXPECT_EQ(p.magic, -7);
  EXPECT_EQ(p.encoding, MapEncoding::SeedCompress);
  EXPECT_EQ(decode_ready(J(R"({"magic": 0, "encoding": "seed"})")).encoding, MapEncoding::Seed);
  EXPECT_FALSE(decode_ready(J(R"({"magic": 0, "encoding": null})")).encoding);
  EXPECT_EQ(decode_ready(J(R"({"magic": 9223372036854775807})")).magic, std::numeric_limits<long long>::max());
  EXPECT_EQ(decode_ready(J(R"({"magic": -9223372036854775808})")).magic, std::numeric_limits<long long>::min());
  EXPECT_EQ(decode_ready(J(R"({"magic": 1, "extra": [1]})")).magic, 1);  // unknown fields ignored
}

TEST(ParamsReady, Errors) {
  expect_bad_params(decode_ready, "{}", "magic");
  expect_bad_params(decode_ready, R"({"magic": "7"})", "magic");
  expect_bad_params(decode_ready, R"({"magic": true})", "magic");
  expect_bad_params(decode_ready, R"({"magic": null})", "magic");
  expect_bad_params(decode_ready, R"({"magic": 7.5})", "magic");
  expect_bad_params(decode_ready, R"({"magic": [7]})", "magic");
  expect_bad_params(decode_ready, R"({"magic": 9223372036854775808})", "magic");
  expect_bad_params(decode_ready, R"({"magic": 18446744073709551615})", "magic");
  expect_bad_params(decode_ready, R"({"magic": 1, "encoding": "zip"})", "encoding");
  expect_bad_params(decode_ready, R"({"magic": 1, "encoding": "SEED"})", "encoding");
  expect_bad_params(decode_ready, R"({"magic": 1, "encoding": 1})", "encoding");
  expect_bad_params(decode_ready, R"({"magic": 1, "encoding": true})", "encoding");
  expect_not_object_is_bad_json(decode_ready, "Ready");
  // The rejected encoding is quoted literally in the message.
  const std::string msg = error_of([] { decode_ready(J(R"({"magic": 1, "encoding": "x'); DROP TABLE maps; --"})")); },
                                   ErrorCode::BadParams, "encoding with quotes");
  EXPECT_NE(msg.find("x'); DROP TABLE maps; --"), std::string::npos) << msg;
}

// ---- OpAck ------------------------------------------------------------------------

TEST(ParamsOpAck, Valid) {
  EXPECT_EQ(decode_op_ack(J(R"({"answer_id": 5})")).answer_id, 5u);
  EXPECT_EQ(decode_op_ack(J(R"({"answer_id": 9223372036854775807})")).answer_id, 9223372036854775807ull);
}

TEST(ParamsOpAck, Errors) {
  expect_bad_params(decode_op_ack, "{}", "answer_id");
  expect_bad_params(decode_op_ack, R"({"answer_id": 0})", "answer_id");
  expect_bad_params(decode_op_ack, R"({"answer_id": -1})", "answer_id");
  expect_bad_params(decode_op_ack, R"({"answer_id": "5"})", "answer_id");
  expect_bad_params(decode_op_ack, R"({"answer_id": true})", "answer_id");
  expect_bad_params(decode_op_ack, R"({"answer_id": 5.5})", "answer_id");
  expect_bad_params(decode_op_ack, R"({"answer_id": null})", "answer_id");
  expect_bad_params(decode_op_ack, R"({"answer_id": 18446744073709551615})", "answer_id");
  expect_not_object_is_bad_json(decode_op_ack, "OpAck");
}

// ---- SendPos ----------------------------------------------------------------------

TEST(ParamsSendPos, Valid) {
  SendPosParams p = decode_send_pos(J(R"({"x": 1.5, "y": -2, "theta": 3.14, "v": 0.5})"));
  EXPECT_DOUBLE_EQ(p.x, 1.5);
  EXPECT_DOUBLE_EQ(p.y, -2);
  EXPECT_DOUBLE_EQ(p.theta, 3.14);
  EXPECT_DOUBLE_EQ(p.v, 0.5);
  EXPECT_FALSE(p.w);
  p = decode_send_pos(J(R"({"x": 0, "y": 0, "theta": 0, "v": 0, "w": -0.25})"));
  ASSERT_TRUE(p.w);
  EXPECT_DOUBLE_EQ(*p.w, -0.25);
  EXPECT_FALSE(decode_send_pos(J(R"({"x": 0, "y": 0, "theta": 0, "v": 0, "w": null})")).w);
  // The map frame's limit is inclusive.
  p = decode_send_pos(J(R"({"x": 1e7, "y": -1e7, "theta": 0, "v": 1000})"));
  EXPECT_DOUBLE_EQ(p.x, 1e7);
  EXPECT_DOUBLE_EQ(p.v, 1000);
}

TEST(ParamsSendPos, LostNeedsNoPoseAndOnlyTwoStatusesExist) {
  EXPECT_FALSE(decode_send_pos(J(R"({"x": 1, "y": 2, "theta": 0, "v": 0})")).lost);
  EXPECT_FALSE(decode_send_pos(J(R"({"x": 1, "y": 2, "theta": 0, "v": 0, "status": "localized"})")).lost);
  const SendPosParams p = decode_send_pos(J(R"({"status": "lost"})"));
  EXPECT_TRUE(p.lost);
  EXPECT_DOUBLE_EQ(p.v, 0);
  // A pose given with it is still checked.
  expect_bad_params(decode_send_pos, R"({"status": "lost", "x": "here"})", "x");
  // A localized SendPos still needs its pose.
  expect_bad_params(decode_send_pos, R"({"status": "localized"})", "x");
  for (const char* bad : {R"({"x": 0, "y": 0, "theta": 0, "v": 0, "status": "LOST"})",
                          R"({"x": 0, "y": 0, "theta": 0, "v": 0, "status": true})",
                          R"({"x": 0, "y": 0, "theta": 0, "v": 0, "status": null})"})
    expect_bad_params(decode_send_pos, bad, "status");
}

TEST(ParamsSendPos, Errors) {
  expect_bad_params(decode_send_pos, R"({"y": 0, "theta": 0, "v": 0})", "x");
  expect_bad_params(decode_send_pos, R"({"x": 0, "theta": 0, "v": 0})", "y");
  expect_bad_params(decode_send_pos, R"({"x": 0, "y": 0, "v": 0})", "theta");
  expect_bad_params(decode_send_pos, R"({"x": 0, "y": 0, "theta": 0})", "v");
  expect_bad_params(decode_send_pos, R"({"x": "0", "y": 0, "theta": 0, "v": 0})", "x");
  expect_bad_params(decode_send_pos, R"({"x": 0, "y": true, "theta": 0, "v": 0})", "y");
  expect_bad_params(decode_send_pos, R"({"x": 0, "y": 0, "theta": false, "v": 0})", "theta");
  expect_bad_params(decode_send_pos, R"({"x": 0, "y": 0, "theta": 0, "v": true})", "v");
  expect_bad_params(decode_send_pos, R"({"x": null, "y": 0, "theta": 0, "v": 0})", "x");
  expect_bad_params(decode_send_pos, R"({"x": [0], "y": 0, "theta": 0, "v": 0})", "x");
  expect_bad_params(decode_send_pos, R"({"x": {}, "y": 0, "theta": 0, "v": 0})", "x");
  expect_bad_params(decode_send_pos, R"({"x": 0, "y": 0, "theta": 0, "v": 0, "w": "1"})", "w");
  expect_bad_params(decode_send_pos, R"({"x": 0, "y": 0, "theta": 0, "v": 0, "w": true})", "w");
  // Out of range.
  expect_bad_params(decode_send_pos, R"({"x": 1e300, "y": 0, "theta": 0, "v": 0})", "x");
  expect_bad_params(decode_send_pos, R"({"x": 10000000.5, "y": 0, "theta": 0, "v": 0})", "x");
  expect_bad_params(decode_send_pos, R"({"x": 0, "y": -1e8, "theta": 0, "v": 0})", "y");
  expect_bad_params(decode_send_pos, R"({"x": 0, "y": 0, "theta": 1001, "v": 0})", "theta");
  expect_bad_params(decode_send_pos, R"({"x": 0, "y": 0, "theta": 0, "v": -1000.5})", "v");
  expect_bad_params(decode_send_pos, R"({"x": 0, "y": 0, "theta": 0, "v": 0, "w": 1e4})", "w");
  expect_not_object_is_bad_json(decode_send_pos, "SendPos");
}

// ---- SendGPS ----------------------------------------------------------------------

TEST(ParamsSendGps, Valid) {
  SendGpsParams p = decode_send_gps(J(R"({"lat": 41.389, "lon": 2.113})"));
  EXPECT_DOUBLE_EQ(p.lat, 41.389);
  EXPECT_DOUBLE_EQ(p.lon, 2.113);
  p = decode_send_gps(J(R"({"lat": -90, "lon": 180})"));
  EXPECT_DOUBLE_EQ(p.lat, -90);
  EXPECT_DOUBLE_EQ(p.lon, 180);
  p = decode_send_gps(J(R"({"lat": 90, "lon": -180})"));
  EXPECT_DOUBLE_EQ(p.lat, 90);
  EXPECT_DOUBLE_EQ(p.lon, -180);
}

TEST(ParamsSendGps, Errors) {
  expect_bad_params(decode_send_gps, R"({"lon": 2})", "lat");
  expect_bad_params(decode_send_gps, R"({"lat": 2})", "lon");
  expect_bad_params(decode_send_gps, R"({"lat": 90.0001, "lon": 2})", "lat");
  expect_bad_params(decode_send_gps, R"({"lat": -91, "lon": 2})", "lat");
  expect_bad_params(decode_send_gps, R"({"lat": 1, "lon": 180.5})", "lon");
  expect_bad_params(decode_send_gps, R"({"lat": 1, "lon": -181})", "lon");
  expect_bad_params(decode_send_gps, R"({"lat": true, "lon": 2})", "lat");
  expect_bad_params(decode_send_gps, R"({"lat": 1, "lon": "2"})", "lon");
  expect_not_object_is_bad_json(decode_send_gps, "SendGPS");
}

// ---- SendImage --------------------------------------------------------------------

TEST(ParamsSendImage, Valid) {
  SendImageParams p = decode_send_image(J(R"({"x": 1, "y": 2, "object_id": 5, "format": "png"})"));
  EXPECT_DOUBLE_EQ(p.x, 1);
  EXPECT_DOUBLE_EQ(p.y, 2);
  EXPECT_EQ(p.object_id, 5);
  EXPECT_EQ(p.format, "png");
  p = decode_send_image(J(R"({"x": 1, "y": 2, "format": "jpg"})"));
  EXPECT_FALSE(p.object_id);
  EXPECT_FALSE(decode_send_image(J(R"({"x": 1, "y": 2, "object_id": null, "format": "jpg"})")).object_id);
  EXPECT_EQ(decode_send_image(J(R"({"x": 1, "y": 2, "object_id": -3, "format": "jpg"})")).object_id, -3);
  const std::string f32(32, 'f');  // images.format is VARCHAR(32)
  EXPECT_EQ(decode_send_image(Json{{"x", 0}, {"y", 0}, {"format", f32}}).format, f32);
  const std::string msg = error_of([&] { decode_send_image(Json{{"x", 0}, {"y", 0}, {"format", f32 + "f"}}); },
                                  ErrorCode::BadParams, "33-byte format");
  EXPECT_NE(msg.find("1-32 bytes"), std::string::npos) << msg;
  // Quotes are data.
  EXPECT_EQ(decode_send_image(J(R"({"x": 0, "y": 0, "format": "p'n\"g"})")).format, "p'n\"g");
}

TEST(ParamsSendImage, Errors) {
  expect_bad_params(decode_send_image, R"({"y": 2, "format": "png"})", "x");
  expect_bad_params(decode_send_image, R"({"x": 1, "format": "png"})", "y");
  expect_bad_params(decode_send_image, R"({"x": 1, "y": 2})", "format");
  expect_bad_params(decode_send_image, R"({"x": 1, "y": 2, "format": ""})", "format");
  expect_bad_params(decode_send_image, R"({"x": 1, "y": 2, "format": 5})", "format");
  expect_bad_params(decode_send_image, R"({"x": 1, "y": 2, "format": true})", "format");
  expect_bad_params(decode_send_image, R"({"x": 1, "y": 2, "format": null})", "format");
  expect_bad_params(decode_send_image, R"({"x": 1, "y": 2, "object_id": 1.5, "format": "png"})", "object_id");
  expect_bad_params(decode_send_image, R"({"x": 1, "y": 2, "object_id": "5", "format": "png"})", "object_id");
  expect_bad_params(decode_send_image, R"({"x": 1, "y": 2, "object_id": true, "format": "png"})", "object_id");
  expect_bad_params(decode_send_image, R"({"x": true, "y": 2, "format": "png"})", "x");
  expect_bad_params(decode_send_image, R"({"x": 1e8, "y": 2, "format": "png"})", "x");
  const Json long_format{{"x", 0}, {"y", 0}, {"format", std::string(256, 'f')}};
  const std::string msg = error_of([&] { decode_send_image(long_format); }, ErrorCode::BadParams, "256-byte format");
  EXPECT_NE(msg.find("params.format"), std::string::npos) << msg;
  expect_not_object_is_bad_json(decode_send_image, "SendImage");
}

// ---- GetMap -----------------------------------------------------------------------

TEST(ParamsGetMap, Valid) {
  GetMapParams p = decode_get_map(J(R"({"x": 20, "y": 30, "w": 10, "h": 8})"));
  EXPECT_DOUBLE_EQ(p.x, 20);
  EXPECT_DOUBLE_EQ(p.y, 30);
  EXPECT_DOUBLE_EQ(p.w, 10);
  EXPECT_DOUBLE_EQ(p.h, 8);
  EXPECT_FALSE(p.encoding);
  p = decode_get_map(J(R"({"x": -1, "y": -1, "w": 0.001, "h": 1e7, "encoding": "seed+compress"})"));
  EXPECT_EQ(p.encoding, MapEncoding::SeedCompress);
  EXPECT_DOUBLE_EQ(p.h, 1e7);
  EXPECT_EQ(decode_get_map(J(R"({"x": 0, "y": 0, "w": 1, "h": 1, "encoding": "seed"})")).encoding, MapEncoding::Seed);
}

TEST(ParamsGetMap, Errors) {
  expect_bad_params(decode_get_map, R"({"y": 1, "w": 5, "h": 10})", "x");
  expect_bad_params(decode_get_map, R"({"x": 1, "w": 5, "h": 10})", "y");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "h": 10})", "w");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": 5})", "h");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": 0, "h": 10})", "w");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": -0.0, "h": 10})", "w");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": -5, "h": 10})", "w");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": 5, "h": 0})", "h");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": 5, "h": -1})", "h");
  expect_bad_params(decode_get_map, R"({"x": "1", "y": 1, "w": 5, "h": 10})", "x");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": true, "h": 10})", "w");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": 5, "h": false})", "h");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": 1e300, "h": 10})", "w");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": 5, "h": 10, "encoding": "zip"})", "encoding");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": 5, "h": 10, "encoding": "seed+COMPRESS"})", "encoding");
  expect_bad_params(decode_get_map, R"({"x": 1, "y": 1, "w": 5, "h": 10, "encoding": ["seed"]})", "encoding");
  expect_not_object_is_bad_json(decode_get_map, "GetMap");
  // 1e999 never reaches decode_get_map: parse_params refuses it first.
  error_of([] { decode_get_map(parse_params(R"({"x": 1, "y": 1, "w": 1e999, "h": 10})")); }, ErrorCode::BadParams,
           "w 1e999");
}

// ---- SetObject --------------------------------------------------------------------

TEST(ParamsSetObject, Valid) {
  SetObjectParams p = decode_set_object(J(R"({"x": 3, "y": 4, "object": "door"})"));
  EXPECT_DOUBLE_EQ(p.x, 3);
  EXPECT_DOUBLE_EQ(p.y, 4);
  EXPECT_EQ(p.object, "door");
  // SQL in a string is data, kept byte for byte.
  EXPECT_EQ(decode_set_object(J(R"({"x": 0, "y": 0, "object": "x'); DROP TABLE maps; --"})")).object,
            "x'); DROP TABLE maps; --");
  EXPECT_EQ(decode_set_object(J(R"({"x": 0, "y": 0, "object": "a\\b\"c\u00e9"})")).object, "a\\b\"c\xc3\xa9");
  const std::string o255(255, 'o');
  EXPECT_EQ(decode_set_object(Json{{"x", 0}, {"y", 0}, {"object", o255}}).object, o255);
}

TEST(ParamsSetObject, Errors) {
  expect_bad_params(decode_set_object, R"({"y": 4, "object": "door"})", "x");
  expect_bad_params(decode_set_object, R"({"x": 3, "object": "door"})", "y");
  expect_bad_params(decode_set_object, R"({"x": 3, "y": 4})", "object");
  expect_bad_params(decode_set_object, R"({"x": 3, "y": 4, "object": ""})", "object");
  expect_bad_params(decode_set_object, R"({"x": 3, "y": 4, "object": 7})", "object");
  expect_bad_params(decode_set_object, R"({"x": 3, "y": 4, "object": ["door"]})", "object");
  expect_bad_params(decode_set_object, R"({"x": true, "y": 4, "object": "door"})", "x");
  expect_bad_params(decode_set_object, R"({"x": 3, "y": 1e9, "object": "door"})", "y");
  const Json long_object{{"x", 0}, {"y", 0}, {"object", std::string(256, 'o')}};
  const std::string msg = error_of([&] { decode_set_object(long_object); }, ErrorCode::BadParams, "256-byte object");
  EXPECT_NE(msg.find("params.object"), std::string::npos) << msg;
  expect_not_object_is_bad_json(decode_set_object, "SetObject");
}

// ---- Alive, Stopped, GetPath, GetPosIni, GetPosEnd ---------------------------------

TEST(ParamsEmpty, ObjectsPassExtraFieldsIgnored) {
  EXPECT_NO_THROW(decode_empty(J("{}")));
  EXPECT_NO_THROW(decode_empty(J(R"({"anything": [1, 2], "x": "y"})")));
  expect_not_object_is_bad_json(decode_empty, "empty");
}

// ---- Server -> robot: round trips -------------------------------------------------

TEST(StartParamsCodec, RoundTrip) {
  const StartParams p{-123456789012345LL, 42, 0.5};
  const Json j = encode(p);
  EXPECT_EQ(j, J(R"({"magic": -123456789012345, "robot_id": 42, "alive_period_s": 0.5})"));
  const StartParams q = decode_start(j);
  EXPECT_EQ(q.magic, p.magic);
  EXPECT_EQ(q.robot_id, p.robot_id);
  EXPECT_DOUBLE_EQ(q.alive_period_s, p.alive_period_s);
  // Through text, as it travels in sa.params.
  const StartParams r = decode_start(parse_params(j.dump()));
  EXPECT_EQ(r.robot_id, 42u);
}

TEST(StartParamsCodec, Errors) {
  expect_bad_params(decode_start, R"({"robot_id": 1, "alive_period_s": 1})", "magic");
  expect_bad_params(decode_start, R"({"magic": 1, "alive_period_s": 1})", "robot_id");
  expect_bad_params(decode_start, R"({"magic": 1, "robot_id": 1})", "alive_period_s");
  expect_bad_params(decode_start, R"({"magic": 1, "robot_id": 0, "alive_period_s": 1})", "robot_id");
  expect_bad_params(decode_start, R"({"magic": 1, "robot_id": -4, "alive_period_s": 1})", "robot_id");
  expect_bad_params(decode_start, R"({"magic": 1, "robot_id": "1", "alive_period_s": 1})", "robot_id");
  expect_bad_params(decode_start, R"({"magic": 1, "robot_id": 1, "alive_period_s": true})", "alive_period_s");
  // robots.id is INT UNSIGNED: an id beyond 32 bits is out of range, not silently wrapped.
  expect_bad_params(decode_start, R"({"magic": 1, "robot_id": 4294967297, "alive_period_s": 1})", "robot_id");
  expect_not_object_is_bad_json(decode_start, "Start");
}

TEST(SetMapParamsCodec, RoundTripBothEncodings) {
  for (MapEncoding e : {MapEncoding::Seed, MapEncoding::SeedCompress}) {
    SetMapParams p;
    p.border[0] = -1.5;
    p.border[1] = 40;
    p.border[2] = 60.25;
    p.border[3] = -0.125;
    p.obstacles = 7;
    p.segments = 41;
    p.encoding = e;
    const Json j = encode(p);
    EXPECT_EQ(j["border"], J("[-1.5, 40, 60.25, -0.125]"));
    EXPECT_EQ(j["obstacles"], 7);
    EXPECT_EQ(j["segments"], 41);
    EXPECT_EQ(j["encoding"], std::string(name(e)));
    const SetMapParams q = decode_set_map(parse_params(j.dump()));
    for (int i = 0; i < 4; ++i) EXPECT_EQ(q.border[i], p.border[i]) << i;
    EXPECT_EQ(q.obstacles, 7u);
    EXPECT_EQ(q.segments, 41u);
    EXPECT_EQ(q.encoding, e);
  }
  // No encoding: the default, seed (SPEC 5.4).
  EXPECT_EQ(decode_set_map(J(R"({"border": [0, 1, 1, 0], "obstacles": 0, "segments": 0})")).encoding, MapEncoding::Seed);
}

TEST(SetMapParamsCodec, Errors) {
  expect_bad_params(decode_set_map, R"({"obstacles": 0, "segments": 0})", "border");
  expect_bad_params(decode_set_map, R"({"border": [0, 1, 1], "obstacles": 0, "segments": 0})", "border");
  expect_bad_params(decode_set_map, R"({"border": [0, 1, 1, 0, 5], "obstacles": 0, "segments": 0})", "border");
  expect_bad_params(decode_set_map, R"({"border": [0, 1, "1", 0], "obstacles": 0, "segments": 0})", "border");
  expect_bad_params(decode_set_map, R"({"border": [0, 1, true, 0], "obstacles": 0, "segments": 0})", "border");
  expect_bad_params(decode_set_map, R"({"border": {"mx1": 0}, "obstacles": 0, "segments": 0})", "border");
  expect_bad_params(decode_set_map, R"({"border": [0, 1, 1, 0], "segments": 0})", "obstacles");
  expect_bad_params(decode_set_map, R"({"border": [0, 1, 1, 0], "obstacles": 0})", "segments");
  expect_bad_params(decode_set_map, R"({"border": [0, 1, 1, 0], "obstacles": 1.5, "segments": 0})", "obstacles");
  expect_bad_params(decode_set_map, R"({"border": [0, 1, 1, 0], "obstacles": 0, "segments": "3"})", "segments");
  expect_bad_params(decode_set_map, R"({"border": [0, 1, 1, 0], "obstacles": 0, "segments": 0, "encoding": "gz"})",
                    "encoding");
  // A count is never negative (it would wrap to a huge size_t).
  expect_bad_params(decode_set_map, R"({"border": [0, 1, 1, 0], "obstacles": -1, "segments": 0})", "obstacles");
  expect_bad_params(decode_set_map, R"({"border": [0, 1, 1, 0], "obstacles": 0, "segments": -1})", "segments");
  expect_not_object_is_bad_json(decode_set_map, "SetMap");
}

TEST(SetPathParamsCodec, RoundTrip) {
  SetPathParams p;
  p.waypoints = {{1, 2}, {3.5, -4.25}, {1e6, 0}};
  p.length = 12.75;
  const Json j = encode(p);
  EXPECT_EQ(j, J(R"({"waypoints": [[1, 2], [3.5, -4.25], [1000000, 0]], "length": 12.75})"));
  const SetPathParams q = decode_set_path(parse_params(j.dump()));
  EXPECT_EQ(q.waypoints, p.waypoints);
  EXPECT_DOUBLE_EQ(q.length, p.length);
  // An empty path survives too.
  const SetPathParams e = decode_set_path(encode(SetPathParams{}));
  EXPECT_TRUE(e.waypoints.empty());
  EXPECT_EQ(e.length, 0);
}

TEST(SetPathParamsCodec, Errors) {
  expect_bad_params(decode_set_path, R"({"length": 1})", "waypoints");
  expect_bad_params(decode_set_path, R"({"waypoints": {}, "length": 1})", "waypoints");
  expect_bad_params(decode_set_path, R"({"waypoints": [[1]], "length": 1})", "waypoints");
  expect_bad_params(decode_set_path, R"({"waypoints": [[1, 2, 3]], "length": 1})", "waypoints");
  expect_bad_params(decode_set_path, R"({"waypoints": [[1, "2"]], "length": 1})", "waypoints");
  expect_bad_params(decode_set_path, R"({"waypoints": [1, 2], "length": 1})", "waypoints");
  expect_bad_params(decode_set_path, R"({"waypoints": [[1, true]], "length": 1})", "waypoints");
  expect_bad_params(decode_set_path, R"({"waypoints": [[1, 2]]})", "length");
  expect_bad_params(decode_set_path, R"({"waypoints": [[1, 2]], "length": "1"})", "length");
  expect_not_object_is_bad_json(decode_set_path, "SetPath");
}

// The route GetPath followed through the topological graph (docs/protocol.md, "SetPath:
// nodes and edges"): written only when set, read back, and unknown keys ignored.
TEST(SetPathParamsCodec, NodesAndEdges) {
  SetPathParams p;
  p.waypoints = {{0, 0}, {5, 0}};
  p.length = 5;
  p.nodes = {{3, "room 2.302", 1.5, -2}, {7, "", 4, 0.25}};
  p.edges = {{3, 7, "door"}};
  const Json j = encode(p);
  EXPECT_EQ(j, J(R"({"waypoints": [[0, 0], [5, 0]], "length": 5,
                    "nodes": [{"id": 3, "name": "room 2.302", "x": 1.5, "y": -2},
                              {"id": 7, "name": "", "x": 4, "y": 0.25}],
                    "edges": [{"from": 3, "to": 7, "type": "door"}]})"));
  const SetPathParams q = decode_set_path(parse_params(j.dump()));
  EXPECT_EQ(q.nodes, p.nodes);
  EXPECT_EQ(q.edges, p.edges);
  // A whole-map RRT path has neither key.
  EXPECT_FALSE(encode(SetPathParams{{{0, 0}}, 0, {}, {}}).contains("nodes"));
  EXPECT_FALSE(encode(SetPathParams{{{0, 0}}, 0, {}, {}}).contains("edges"));
  // A newer server's extra keys, and a type this robot does not know, do not refuse the path.
  const SetPathParams n = decode_set_path(J(R"({"waypoints": [[1, 2]], "length": 0, "lanes": 3,
      "nodes": [{"id": 1, "x": 1, "y": 2, "floor": 2}], "edges": [{"from": 1, "to": 2, "type": "ramp", "w": 1}]})"));
  ASSERT_EQ(n.nodes.size(), 1u);
  EXPECT_EQ(n.nodes[0].name, "");
  ASSERT_EQ(n.edges.size(), 1u);
  EXPECT_EQ(n.edges[0].type, "ramp");
}

TEST(SetPathParamsCodec, NodeAndEdgeErrorsNameTheElement) {
  expect_bad_params(decode_set_path, R"({"waypoints": [], "length": 0, "nodes": {}})", "nodes");
  expect_bad_params(decode_set_path, R"({"waypoints": [], "length": 0, "nodes": [1]})", "nodes");
  expect_bad_params(decode_set_path, R"({"waypoints": [], "length": 0, "nodes": [{"id": 1, "x": 1, "y": 1},
      {"id": -1, "x": 1, "y": 1}]})", "nodes[1].id");
  expect_bad_params(decode_set_path, R"({"waypoints": [], "length": 0, "nodes": [{"id": 1, "x": "1", "y": 1}]})",
                    "nodes[0].x");
  expect_bad_params(decode_set_path, R"({"waypoints": [], "length": 0, "nodes": [{"id": 1, "x": 1}]})", "nodes[0].y");
  expect_bad_params(decode_set_path, R"({"waypoints": [], "length": 0, "nodes": [{"id": 1, "name": 2, "x": 1, "y": 1}]})",
                    "nodes[0].name");
  expect_bad_params(decode_set_path, R"({"waypoints": [], "length": 0, "edges": [{"from": 1, "to": 2.5, "type": "door"}]})",
                    "edges[0].to");
  expect_bad_params(decode_set_path, R"({"waypoints": [], "length": 0, "edges": [{"from": 1, "to": 2}]})",
                    "edges[0].type");
}

TEST(SetPoseParamsCodec, RoundTripWithAndWithoutTheta) {
  const SetPoseParams with{3, 4, 1.5};
  Json j = encode(with);
  EXPECT_EQ(j, J(R"({"x": 3, "y": 4, "theta": 1.5})"));
  SetPoseParams q = decode_set_pose(parse_params(j.dump()));
  EXPECT_DOUBLE_EQ(q.x, 3);
  EXPECT_DOUBLE_EQ(q.y, 4);
  ASSERT_TRUE(q.theta);
  EXPECT_DOUBLE_EQ(*q.theta, 1.5);

  const SetPoseParams without{10, -12, std::nullopt};
  j = encode(without);
  EXPECT_EQ(j, J(R"({"x": 10, "y": -12})"));  // SetPosEnd: no theta key at all
  q = decode_set_pose(j);
  EXPECT_DOUBLE_EQ(q.x, 10);
  EXPECT_DOUBLE_EQ(q.y, -12);
  EXPECT_FALSE(q.theta);
  EXPECT_FALSE(decode_set_pose(J(R"({"x": 1, "y": 2, "theta": null})")).theta);
}

TEST(SetPoseParamsCodec, Errors) {
  expect_bad_params(decode_set_pose, R"({"y": 4})", "x");
  expect_bad_params(decode_set_pose, R"({"x": 4})", "y");
  expect_bad_params(decode_set_pose, R"({"x": true, "y": 4})", "x");
  expect_bad_params(decode_set_pose, R"({"x": 1, "y": 4, "theta": "0"})", "theta");
  expect_bad_params(decode_set_pose, R"({"x": 1, "y": 4, "theta": 2000})", "theta");
  expect_not_object_is_bad_json(decode_set_pose, "SetPose");
}

TEST(ErrorParamsCodec, RoundTripEveryCode) {
  for (ErrorCode c : {ErrorCode::UnknownOp, ErrorCode::BadJson, ErrorCode::BadParams, ErrorCode::NotYourRobot,
                      ErrorCode::NotRegistered, ErrorCode::PayloadTooLarge, ErrorCode::UnknownAnswer, ErrorCode::NoGoal,
                      ErrorCode::NoPose, ErrorCode::NoPath, ErrorCode::NoPlanner, ErrorCode::Internal}) {
    const ErrorParams p{77, c, "it's \"wrong\"; DROP TABLE sa; --"};
    const Json j = encode(p);
    EXPECT_EQ(j["code"], std::string(name(c)));
    EXPECT_EQ(j["request_id"], 77);
    const ErrorParams q = decode_error(parse_params(j.dump()));
    EXPECT_EQ(q.request_id, 77u);
    EXPECT_EQ(q.code, c);
    EXPECT_EQ(q.message, p.message);
  }
  // No request (the server acted on its own): request_id is present and null.
  const Json j = encode(ErrorParams{std::nullopt, ErrorCode::Internal, "m"});
  ASSERT_TRUE(j.contains("request_id"));
  EXPECT_TRUE(j["request_id"].is_null());
  EXPECT_FALSE(decode_error(j).request_id);
  EXPECT_FALSE(decode_error(J(R"({"code": "internal"})")).request_id);
  EXPECT_EQ(decode_error(J(R"({"code": "internal"})")).message, "");
}

TEST(ErrorParamsCodec, Errors) {
  expect_bad_params(decode_error, R"({"request_id": 1, "message": "m"})", "code");
  expect_bad_params(decode_error, R"({"code": "nope", "message": "m"})", "code");
  expect_bad_params(decode_error, R"({"code": "BAD_JSON", "message": "m"})", "code");
  expect_bad_params(decode_error, R"({"code": 3, "message": "m"})", "code");
  expect_bad_params(decode_error, R"({"code": "internal", "request_id": "1"})", "request_id");
  expect_bad_params(decode_error, R"({"code": "internal", "request_id": 1.5})", "request_id");
  // Found by fuzz/params_fuzz (decode -> encode -> decode): -1 became 2^64-1, which
  // decode_error then refused as out of range.
  expect_bad_params(decode_error, R"({"code": "internal", "request_id": -1})", "request_id");
  expect_bad_params(decode_error, R"({"code": "internal", "request_id": 0})", "request_id");
  expect_not_object_is_bad_json(decode_error, "Error");
}

TEST(ParamsSmallAnswers, OpAckAndAbortShapes) {
  EXPECT_EQ(encode_op_ack(18446744073709551615ull), J(R"({"request_id": 18446744073709551615})"));
  EXPECT_EQ(encode_op_ack(5), J(R"({"request_id": 5})"));
  EXPECT_EQ(encode_abort("blocked 'corridor'"), J(R"({"reason": "blocked 'corridor'"})"));
  EXPECT_EQ(encode_abort(""), J(R"({"reason": ""})"));
}

// ---- TourEvent (docs/protocol.md) ---------------------------------------------------

TEST(ParamsTourEvent, DecodesTheEventNameTourAndPose) {
  TourEventParams p = decode_tour_event(J(R"({"event": "door"})"));
  EXPECT_EQ(p.kind, TourEventKind::Door);
  EXPECT_EQ(p.name, "");
  EXPECT_EQ(p.tour, "");
  EXPECT_FALSE(p.x);
  p = decode_tour_event(J(R"({"event": "place", "name": "dock", "tour": "floor 1", "x": 1.5, "y": -2, "theta": 3})"));
  EXPECT_EQ(p.kind, TourEventKind::Place);
  EXPECT_EQ(p.name, "dock");
  EXPECT_EQ(p.tour, "floor 1");
  EXPECT_EQ(p.x, 1.5);
  EXPECT_EQ(p.y, -2);
  EXPECT_EQ(p.theta, 3);
  EXPECT_EQ(decode_tour_event(J(R"({"event": "corridor"})")).kind, TourEventKind::EnterCorridor);
  EXPECT_EQ(decode_tour_event(J(R"({"event": "room"})")).kind, TourEventKind::EnterRoom);
  EXPECT_EQ(decode_tour_event(J(R"({"event": "crossing", "name": null})")).kind, TourEventKind::Crossing);
}

TEST(ParamsTourEvent, MalformedParamsNameTheField) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({})", "params.event"},
      {R"({"event": "hall"})", "params.event"},
      {R"({"event": 3})", "params.event"},
      {R"({"event": "place"})", "params.name"},
      {R"({"event": "door", "name": ""})", "params.name"},
      {R"({"event": "door", "tour": 7})", "params.tour"},
      {R"({"event": "door", "x": 1, "y": 2})", "params.theta"},
      {R"({"event": "door", "y": 2, "theta": 0})", "params.x"},
      {R"({"event": "door", "x": "1", "y": 2, "theta": 0})", "params.x"},
  };
  for (const auto& [params, field] : cases) {
    try {
      decode_tour_event(J(params));
      ADD_FAILURE() << params << ": accepted";
    } catch (const ProtocolError& e) {
      EXPECT_EQ(e.code(), ErrorCode::BadParams) << params;
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << params << ": " << e.what();
    }
  }
}

// ---- Names ------------------------------------------------------------------------

TEST(ParamsOpNames, RequestOpsRoundTripWithTheProtocolSpelling) {
  const std::pair<RequestOp, const char*> table[] = {
      {RequestOp::Ready, "Ready"},         {RequestOp::Alive, "Alive"},         {RequestOp::Stopped, "Stopped"},
      {RequestOp::OpAck, "OpAck"},         {RequestOp::SendPos, "SendPos"},     {RequestOp::SendGPS, "SendGPS"},
      {RequestOp::SendImage, "SendImage"}, {RequestOp::GetMap, "GetMap"},       {RequestOp::GetPath, "GetPath"},
      {RequestOp::GetPosIni, "GetPosIni"}, {RequestOp::GetPosEnd, "GetPosEnd"}, {RequestOp::SetObject, "SetObject"},
      {RequestOp::TourEvent, "TourEvent"},
  };
  for (const auto& [op, text] : table) {
    EXPECT_EQ(name(op), text);
    EXPECT_EQ(parse_request_op(text), op) << text;
    EXPECT_LE(std::string_view(text).size(), 16u) << "rr.op is VARCHAR(16)";
  }
}

TEST(ParamsOpNames, AnswerOpsRoundTripWithTheProtocolSpelling) {
  const std::pair<AnswerOp, const char*> table[] = {
      {AnswerOp::Start, "Start"},       {AnswerOp::OpAck, "OpAck"},         {AnswerOp::Abort, "Abort"},
      {AnswerOp::SetMap, "SetMap"},     {AnswerOp::SetPath, "SetPath"},     {AnswerOp::SetPosIni, "SetPosIni"},
      {AnswerOp::SetPosEnd, "SetPosEnd"}, {AnswerOp::Error, "Error"},
  };
  for (const auto& [op, text] : table) {
    EXPECT_EQ(name(op), text);
    EXPECT_EQ(parse_answer_op(text), op) << text;
  }
  // Answer-only names are no requests and the other way round (OpAck is both).
  for (const char* t : {"Start", "Abort", "SetMap", "SetPath", "SetPosIni", "SetPosEnd", "Error"})
    EXPECT_FALSE(parse_request_op(t)) << t;
  for (const char* t : {"Ready", "Alive", "GetMap", "SendPos", "SetObject"}) EXPECT_FALSE(parse_answer_op(t)) << t;
  EXPECT_EQ(parse_request_op("OpAck"), RequestOp::OpAck);
  EXPECT_EQ(parse_answer_op("OpAck"), AnswerOp::OpAck);
}

TEST(ParamsOpNames, ExactAndCaseSensitive) {
  for (const char* t : {"ready", "READY", "rEADY", "Ready ", " Ready", "Ready\n", "Ready\t", "", "Sendgps",
                        "SendGps", "sendpos", "GETMAP", "Getmap", "opack", "OpACK", "Ready           ",
                        "GetPosIniXXXXXXX", "Rea", "ReadyReady"})
    EXPECT_FALSE(parse_request_op(t)) << "'" << t << "'";
  EXPECT_FALSE(parse_request_op(std::string_view("Ready\0", 6)));
  for (const char* t : {"start", "ERROR", "error", "Setmap", "SetMap ", ""}) EXPECT_FALSE(parse_answer_op(t)) << t;
}

TEST(ParamsErrorCodeNames, RoundTripAndCaseSensitive) {
  const std::pair<ErrorCode, const char*> table[] = {
      {ErrorCode::UnknownOp, "unknown_op"},        {ErrorCode::BadJson, "bad_json"},
      {ErrorCode::BadParams, "bad_params"},        {ErrorCode::NotYourRobot, "not_your_robot"},
      {ErrorCode::NotRegistered, "not_registered"}, {ErrorCode::PayloadTooLarge, "payload_too_large"},
      {ErrorCode::UnknownAnswer, "unknown_answer"}, {ErrorCode::NoGoal, "no_goal"},
      {ErrorCode::NoPose, "no_pose"},              {ErrorCode::NoPath, "no_path"},
      {ErrorCode::NoPlanner, "no_planner"},        {ErrorCode::Internal, "internal"},
  };
  for (const auto& [c, text] : table) {
    EXPECT_EQ(name(c), text);
    EXPECT_EQ(parse_error_code(text), c) << text;
  }
  for (const char* t : {"Internal", "BAD_PARAMS", "bad-params", "bad_params ", ""}) EXPECT_FALSE(parse_error_code(t)) << t;
}

TEST(ParamsMapEncodingNames, RoundTripAndCaseSensitive) {
  EXPECT_EQ(name(MapEncoding::Seed), "seed");
  EXPECT_EQ(name(MapEncoding::SeedCompress), "seed+compress");
  EXPECT_EQ(parse_map_encoding("seed"), MapEncoding::Seed);
  EXPECT_EQ(parse_map_encoding("seed+compress"), MapEncoding::SeedCompress);
  for (const char* t : {"Seed", "SEED", "seed ", "seed+Compress", "seed compress", "seed+compress ", "compress", "zlib", ""})
    EXPECT_FALSE(parse_map_encoding(t)) << t;
}

}  // namespace
}  // namespace fleetmap
