// Seed map text (common/io/seed_format.h) from any bytes: read_seed either returns a
// valid map or throws MapFormatError. A map it returns must survive the canonical
// writer: write -> read -> write gives the same text (docs/map-format.md).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "common/io/seed_format.h"
#include "fuzz/fuzz_check.h"

using namespace fleetmap;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (MapKind kind : {MapKind::Whole, MapKind::Window}) {
    Map m;
    try {
      m = read_seed(text, "fuzz", kind);
    } catch (const MapFormatError&) {
      continue;
    }
    const std::string once = write_seed(m);
    Map again;
    try {
      again = read_seed(once, "rewritten", kind);
    } catch (const MapFormatError& e) {
      fuzz::finding(std::string("write_seed wrote a map read_seed refuses: ") + e.what());
    }
    fuzz::check(write_seed(again) == once, "write_seed(read_seed(write_seed(m))) differs from write_seed(m)");
  }
  return 0;
}
