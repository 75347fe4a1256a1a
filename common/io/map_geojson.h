#pragma once
// GeoJSON (RFC 7946) view of a map, for GIS tools and web viewers. One writer, no reader:
// the seed format (seed_format.h) stays the interchange format.
//
//   {"type":"FeatureCollection",
//    "fleetmap":{"map":NAME,"frame":"map","units":"m","border":[mx1,my1,mx4,my4]},
//    "features":[
//     {"type":"Feature","geometry":{"type":"Polygon",...},"properties":{"kind":"border"}},
//     {"type":"Feature","geometry":{"type":"LineString","coordinates":[[ax,ay],[bx,by]]},
//      "properties":{"kind":"segment","obstacle_id":..,"st":..,"shape":..,
//                    "obstacle_semantic":..,"segment":1,"h":..,"in_out":..,"semantic":..,
//                    "note":..}},   <- "note" only when the segment has one
//     ...]}
//
// Coordinates are map-frame metres, not the WGS 84 longitude/latitude of RFC 7946
// section 4; the foreign member "fleetmap" (RFC 7946 section 6.1) says so, since the
// "crs" member of the 2008 GeoJSON draft was removed by the RFC. The border ring is
// closed and counter-clockwise with y growing upwards (RFC 7946 section 3.1.6); segment
// features follow the map order, "segment" is the 1-based index within the obstacle.
// Numbers are written in the shortest form that reads back to the same double.
// One feature per line, so large maps diff and grep well.
#include <string>

#include "common/map/map.h"

namespace fleetmap {

// Throws std::invalid_argument naming the obstacle and segment when a number is not
// finite or a text is not UTF-8 (JSON can hold neither); a validated map has neither.
std::string write_geojson(const Map& m, const std::string& name = "");

}  // namespace fleetmap
