#pragma once
// GeoJSON (RFC 7946) of robots' trajectories, for GIS tools: one Point feature per
// reported pose (one geometry type per file, so OGR reads it as one point layer), in
// the OutputFrame's coordinates, with the time in ISO 8601 with its zone
// (RFC 3339, "2026-12-02T00:36:02.123456Z"). Written, never read.
//
//   {"type":"FeatureCollection",
//    "fleetmap":{"map":NAME,"frame":"wgs84","units":"degree","layer":"trajectories"},
//    "features":[
//     {"type":"Feature","id":1,"geometry":{"type":"Point","coordinates":[x,y]},
//      "properties":{"robot":"r1","t":"2026-12-02T00:36:02.123456Z","theta":..,"v":..}},
//     ...]}
//
// theta is the heading in the map frame (radians, counter-clockwise from the map x
// axis), v the speed (m/s), as the robot sent them (SPEC 5.2 SendPos).
#include <string>
#include <vector>

#include "common/io/output_frame.h"

namespace fleetmap {

struct TrackPose {
  std::string t;  // ISO 8601 with a zone
  Point pos;      // map frame
  double theta = 0, v = 0;
};

struct Track {
  std::string robot;
  std::vector<TrackPose> poses;  // in time order
};

// Throws std::invalid_argument for a number that is not finite or a text not UTF-8.
std::string write_trajectory_geojson(const std::vector<Track>& tracks, const std::string& map_name,
                                     const OutputFrame& frame = {});

}  // namespace fleetmap
