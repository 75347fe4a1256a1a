#pragma once
// The navigation-graph JSON of the AMRL maps (ut-amrl/amrl_maps *.navigation.json), read into a
// TopoGraph and written back. Reader -> validator -> model in one pass: every node and
// edge is checked before the graph is built, and the first problem is reported with the
// element's index and field: "campus.json: edges[12].s1_id: expected the id of a node, got 400".
//
//   {"edges": [{"s0_id": 1, "s1_id": 0,                        node ids, required
//               "has_door": false, "has_automated_door": false,  booleans, optional
//               "has_stairs": false, "has_elevator": false,      (absent: false)
//               "max_clearance": 1.0, "max_speed": 2.0,          finite, optional
//                                                                (absent: no limit)
//               "type": "room"},                                 ours, optional
//              ...],
//    "nodes": [{"id": 0, "loc": {"x": -26.6, "y": 19.6},          required; ids unique, >= 0
//               "name": "charging station"},                      ours, optional
//              ...]}
//
// Edge type: from the flags (topo_graph.h: stairs, elevator, door, else corridor). An
// explicit "type" is what gives "room" (seed 003), which the AMRL flags cannot express;
// it must agree with the flags when any of them is set (has_stairs with "room" is an
// error). Members we do not know are ignored, so newer AMRL files still load.
//
// The writer produces the same layout (keys sorted, 4-space indent, "type" only where
// the flags do not already say it, "name" only when set), so an AMRL file read and
// written again comes back byte for byte.
#include <stdexcept>
#include <string>
#include <string_view>

#include "common/planning/topo_graph.h"
#include "common/core/error.h"

namespace fleetmap {

// "file: where: expected ..., got ...", where is "edges[3].s1_id" or "line 4, column 9".
class TopoFormatError : public FileFormatError {
 public:
  TopoFormatError(std::string file, std::string where, std::string message);
  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_, where_, message_;
};

TopoGraph read_topo_json(std::string_view text, const std::string& file = "<input>");
TopoGraph read_topo_json_file(const std::string& path);  // throws TopoFormatError also when unreadable

// Throws std::invalid_argument for a node name that is not UTF-8 (JSON cannot hold it).
std::string write_topo_json(const TopoGraph& g);

}  // namespace fleetmap
