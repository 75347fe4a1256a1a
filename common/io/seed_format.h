#pragma once
// The seed text format (seed 000 appendix A, SPEC 3): reader and canonical writer.
//
//   border;            obstacle;                 ax;ay;
//   mx1;my1;           id;ST;NS;semantic;        bx;by;
//   mx4;my4;           #                         h;inOut;semantic;[%note]
//   #                                            #
//
// Fields end with ';'; semantic strings may contain commas; a '%' starts a comment
// that runs to the end of the line (kept as the segment's or obstacle's note); CRLF
// and blank lines are accepted. See docs/map-format.md.
#include <stdexcept>
#include <string>
#include <string_view>

#include "common/map/map.h"
#include "common/core/error.h"
#include "common/map/map_validation.h"

namespace fleetmap {

// "file:line: expected ..., got ..."
class MapFormatError : public FileFormatError {
 public:
  MapFormatError(std::string file, size_t line, std::string message);
  const std::string& file() const { return file_; }
  size_t line() const { return line_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  size_t line_;
  std::string message_;
};

// Parses and validates (map_validation.h) a whole file; throws MapFormatError at the
// first problem. The returned map has its bounding circles computed.
// A window (SPEC 5.4) is read with MapKind::Window: its cut obstacles are accepted.
Map read_seed(std::string_view text, const std::string& file = "<input>", MapKind kind = MapKind::Whole);
Map read_seed_file(const std::string& path, MapKind kind = MapKind::Whole);

// Canonical text: LF line ends, shortest round-trip numbers, no blank lines.
std::string write_seed(const Map& map);

}  // namespace fleetmap
