#pragma once
// GeoJSON (RFC 7946) view of a map, for GIS tools and web viewers. One writer, no reader:
// the seed format (seed_format.h) stays the interchange format.
//
//   {"type":"FeatureCollection",
//    "fleetmap":{"map":NAME,"frame":"map","units":"m","border":[mx1,my1,mx4,my4]},
//    "features":[
//     {"type":"Feature","id":0,"geometry":{"type":"Polygon",...},"properties":{"kind":"border"}},
//     {"type":"Feature","id":1,"geometry":{"type":"LineString","coordinates":[[ax,ay],[bx,by]]},
//      "properties":{"kind":"segment","obstacle_id":..,"st":..,"shape":..,
//                    "obstacle_semantic":..,"segment":1,"h":..,"in_out":..,"semantic":..,
//                    "note":..}},   <- "note" only when the segment has one
//     ...]}
//
// Coordinates are in the OutputFrame (output_frame.h): WGS 84 longitude/latitude as RFC
// 7946 section 4 wants ("frame":"wgs84","units":"degree", no "border" member), or, by
// prior arrangement, map-frame metres (the default); the foreign member "fleetmap" (RFC
// 7946 section 6.1) says which, since the RFC removed the "crs" member of the 2008
// draft. Feature ids: 0 the border, then the segments from 1 in map order. The border ring is
// closed and counter-clockwise with y growing upwards (RFC 7946 section 3.1.6); segment
// features follow the map order, "segment" is the 1-based index within the obstacle.
// Numbers are written in the shortest form that reads back to the same double.
// One feature per line, so large maps diff and grep well.
#include <string>

#include "common/io/output_frame.h"
#include "common/map/map.h"

namespace fleetmap {

// Throws std::invalid_argument naming the obstacle and segment when a number is not
// finite or a text is not UTF-8 (JSON can hold neither); a validated map has neither.
std::string write_geojson(const Map& m, const std::string& name = "", const OutputFrame& frame = {});

}  // namespace fleetmap
