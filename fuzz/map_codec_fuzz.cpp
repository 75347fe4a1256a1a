// SetMap payloads (protocol/map_codec.h) from any bytes: the first byte picks the
// encoding (seed text or MariaDB COMPRESS()) and the map kind, the rest is the payload.
// decode_map returns a map or throws MapFormatError / std::invalid_argument; a map it
// returns encodes to a payload that decodes to the same map.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "common/io/seed_format.h"
#include "protocol/map_codec.h"
#include "fuzz/fuzz_check.h"

using namespace fleetmap;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const MapEncoding e = (data[0] & 1) ? MapEncoding::SeedCompress : MapEncoding::Seed;
  const MapKind kind = (data[0] & 2) ? MapKind::Window : MapKind::Whole;
  const std::string_view payload(reinterpret_cast<const char*>(data + 1), size - 1);
  Map m;
  try {
    m = decode_map(payload, e, kind);
  } catch (const MapFormatError&) {
    return 0;
  } catch (const std::invalid_argument&) {
    return 0;
  }
  const std::string text = write_seed(m);
  try {
    fuzz::check(write_seed(decode_map(encode_map(m, e), e, kind)) == text, "SetMap payload does not round-trip");
  } catch (const std::exception& ex) {
    fuzz::finding(std::string("encode_map wrote a payload decode_map refuses: ") + ex.what());
  }
  return 0;
}
