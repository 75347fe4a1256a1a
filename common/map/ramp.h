#pragma once
// Ramp surface encoding (SPEC 3, docs/map-format.md). A ramp (ST 6) is a closed polygon
// of null-height segments whose obstacle semantic string carries two tokens:
//   normal=NX:NY:NZ   the upward normal of the surface (any length, NZ > 0)
//   foot=X:Y          a point where the surface meets the floor (z = 0)
// e.g. "ramp,concrete,normal=-0.125:0:1,foot=10:5". The surface is the plane with that
// normal through (X, Y, 0); it must not be below the floor at any vertex. Old readers
// see ordinary semantic tokens and still parse the file; a window cut out of the map
// keeps the surface exact, since nothing depends on the polygon's vertices.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "common/map/map.h"

namespace fleetmap {

struct RampSurface {
  Point gradient;     // rise per metre along x and y: (-NX/NZ, -NY/NZ)
  Point foot;         // on the floor
  double height_at(Point p) const { return dot(gradient, p - foot); }
  friend bool operator==(const RampSurface&, const RampSurface&) = default;
};

// The surface encoded in an obstacle semantic string. Throws std::invalid_argument with
// an "expected ..., got ..." message when a token is missing or malformed.
RampSurface parse_ramp_surface(std::string_view semantic);

// The surface of a ramp obstacle, also checking that no vertex lies below the floor.
RampSurface ramp_surface(const Obstacle& ramp);

// The two tokens for a surface, e.g. "normal=-0.125:0:1,foot=10:5".
std::string ramp_tokens(double nx, double ny, double nz, Point foot);

}  // namespace fleetmap
