#pragma once
// A standalone SVG picture of a map, for reports, docs and eyeballing imports; later
// also robot trajectories (SvgTrack). Not an interchange format: pixel coordinates are
// rounded to 1/100 px.
//
// Layout: the border rectangle is drawn W*k by H*k pixels, k = width_px / max(W, H), so
// its larger side is width_px; margin_px surrounds it on every side, with the title in
// the top margin and the scale bar in the bottom one. Map point (x, y) is at pixel
//   (margin_px + (x - mx1) * k,  margin_px + (my1 - y) * k)
// so map y grows upwards as in the seed format (map.h, Border).
//
// Segments are <line class="seg stN"> elements, one per segment, grouped per obstacle
// (<g class="obstacle" data-id="..">); colour by shape type (walls dark grey, open
// polygons brown, curved blue, stairs orange, ramps green over a green hatch), stroke
// width by height (thin for h = 0, such as the stairs' closing segment and ramps).
#include <string>
#include <vector>

#include "common/geometry/geometry.h"
#include "common/map/map.h"

namespace fleetmap {

// A polyline in map coordinates drawn over the map, e.g. a robot trajectory; its last
// point is marked with a dot (the robot's latest position).
struct SvgTrack {
  std::string label;   // legend text
  std::string colour;  // any SVG colour, e.g. "#d62728" or "red"; empty: a palette colour
  std::vector<Point> points;
};

struct SvgOptions {
  double width_px = 1200;  // pixels of the map's larger side
  double margin_px = 40;   // around the map area (holds the title and scale bar)
  std::string title;       // empty: none
  double scale_bar_m = 0;  // 0: the largest 1-2-5 length up to a quarter of the width
  std::vector<SvgTrack> tracks;  // drawn in order on top of the map, with a legend
};

// Texts (title, labels, colours, semantics in tooltips) are XML-escaped.
std::string write_svg(const Map& m, const SvgOptions& opt = {});

// &, <, >, " and ' as entities; control characters XML 1.0 cannot hold are dropped.
std::string xml_escape(const std::string& text);

}  // namespace fleetmap
