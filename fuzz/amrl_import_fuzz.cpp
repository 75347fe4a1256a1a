// AMRL vector maps (common/io/amrl_import.h) from any bytes: read_amrl either returns a
// map or throws MapFormatError. The map it returns is valid, so its seed text reads back.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "common/io/amrl_import.h"
#include "common/io/seed_format.h"
#include "fuzz/fuzz_check.h"

using namespace fleetmap;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  AmrlReport report;
  Map m;
  try {
    m = read_amrl(text, AmrlOptions{}, &report, "fuzz");
  } catch (const MapFormatError&) {
    return 0;
  }
  fuzz::check(report.segments == m.segment_count(), "AmrlReport.segments differs from the map's segment count");
  fuzz::check(report.obstacles == m.obstacles.size(), "AmrlReport.obstacles differs from the map's obstacles");
  try {
    read_seed(write_seed(m), "imported");
  } catch (const MapFormatError& e) {
    fuzz::finding(std::string("read_amrl returned a map whose seed text does not read back: ") + e.what());
  }
  return 0;
}
