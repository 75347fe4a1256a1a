// The params column (protocol/params.h) from any bytes, as the server reads what a robot
// wrote in rr and a robot reads what it finds in sa: parse_params and every decode_*
// either return or throw ProtocolError. What a robot decodes from the server must
// re-encode to params that decode to the same thing.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "protocol/params.h"
#include "fuzz/fuzz_check.h"

using namespace fleetmap;

namespace {

template <class Decode>
void refused_or_decoded(const Json& j, Decode decode) {
  try {
    decode(j);
  } catch (const ProtocolError&) {
  }
}

// decode -> encode -> decode -> encode: the two encodings are equal.
template <class Decode>
void round_trip(const Json& j, Decode decode, const char* what) {
  Json once;
  try {
    once = encode(decode(j));
  } catch (const ProtocolError&) {
    return;
  }
  try {
    fuzz::check(encode(decode(once)) == once, what);
  } catch (const ProtocolError& e) {
    fuzz::finding(std::string(what) + ": the re-encoded params are refused: " + e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Json j;
  try {
    j = parse_params(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const ProtocolError&) {
    // The decoders also get what parse_params refuses to build: any JSON value.
    j = Json::parse(reinterpret_cast<const char*>(data), reinterpret_cast<const char*>(data) + size, nullptr, false);
  }
  // Robot -> server (handlers run these on every rr row).
  refused_or_decoded(j, decode_ready);
  refused_or_decoded(j, decode_op_ack);
  refused_or_decoded(j, decode_send_pos);
  refused_or_decoded(j, decode_send_gps);
  refused_or_decoded(j, decode_send_image);
  refused_or_decoded(j, decode_get_map);
  refused_or_decoded(j, decode_set_object);
  refused_or_decoded(j, decode_empty);
  // Server -> robot.
  round_trip(j, decode_start, "Start params");
  round_trip(j, decode_set_map, "SetMap params");
  round_trip(j, decode_set_path, "SetPath params");
  round_trip(j, decode_set_pose, "SetPosIni/SetPosEnd params");
  round_trip(j, decode_error, "Error params");
  return 0;
}
