#pragma once
// Importer for AMRL vector maps (../shared/maps/*.vectormap.txt): one wall a line,
// "x1, y1, x2, y2". Lines that continue the previous one (its start is the previous
// end) form one obstacle: a closed polygon (ST 1) when the chain comes back to its
// start, an open polygon (ST 2) otherwise. The format has no heights, in/out flags or
// semantics; they come from AmrlOptions. Zero-length lines are skipped and counted.
#include <string>
#include <string_view>

#include "common/map/map.h"

namespace fleetmap {

struct AmrlOptions {
  double height = 2.0;          // metres: AMRL maps are walls of buildings
  int in_out = 0;               // 0 indoor, 1 outdoor
  std::string semantic = "wall";
  double margin = 1.0;          // border = bounding box of the segments grown by this
  int first_id = 1;             // obstacle ids count up from here
};

struct AmrlReport {
  size_t lines = 0;              // non-blank lines read
  size_t segments = 0;           // segments kept
  size_t zero_length_skipped = 0;
  size_t obstacles = 0;
  size_t closed = 0;             // of which closed polygons
};

// Throws MapFormatError ("file:line: expected ..., got ...") on a malformed line.
Map read_amrl(std::string_view text, const AmrlOptions& options, AmrlReport* report = nullptr,
              const std::string& file = "<input>");
Map read_amrl_file(const std::string& path, const AmrlOptions& options, AmrlReport* report = nullptr);

}  // namespace fleetmap
