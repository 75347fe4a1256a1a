#pragma once
// GeoJSON (RFC 7946) view of a topological graph, for GIS tools and web viewers: one
// Point feature per node, one LineString feature per edge. Written, never read (the
// navigation JSON of topo_json.h is the interchange format). Same conventions as
// map_geojson.h: the OutputFrame's coordinates (WGS 84 or map-frame metres), said by the
// foreign member "fleetmap"; one feature per line; feature ids from 1, the nodes first.
//
//   {"type":"FeatureCollection",
//    "fleetmap":{"map":NAME,"frame":"map","units":"m","layer":"topology"},
//    "features":[
//     {"type":"Feature","id":1,"geometry":{"type":"Point","coordinates":[x,y]},
//      "properties":{"kind":"node","id":..,"name":..}},          <- "name" only when set
//     {"type":"Feature","geometry":{"type":"LineString","coordinates":[[ax,ay],[bx,by]]},
//      "properties":{"kind":"edge","edge":..,"s0_id":..,"s1_id":..,"type":"corridor",
//                    "has_door":..,"has_automated_door":..,"length":..,
//                    "max_clearance":..,"max_speed":..}},        <- limits only when set
//     ...]}
#include <string>

#include "common/io/output_frame.h"
#include "common/planning/topo_graph.h"

namespace fleetmap {

// "edge" is the 0-based position in TopoGraph::edges(). Throws std::invalid_argument for
// a node name that is not UTF-8.
std::string write_topo_geojson(const TopoGraph& g, const std::string& name = "", const OutputFrame& frame = {});

}  // namespace fleetmap
