#pragma once
// Which features of a GIS source become what in a fleetmap map (seed 001 section III,
// "From GIS to robot map"): obstacles with a shape type, height, in/out and semantic
// (seed 000 section 3), or objects of the semantic layer (seed 002 section 3).
// Read from a small JSON file (docs/gis-import.md), or built in for OSM and for a plain
// polygon or line layer. JSON because nlohmann-json is already a dependency.
#include <optional>
#include <string>
#include <vector>

namespace fleetmap {

// What a matched feature becomes.
enum class FeatureAction {
  Skip,    // counted as skipped, with the rule's name as the reason
  Closed,  // each ring a closed polygon (ST 1); a closed line too, an open line ST 2
  Open,    // each line or ring an open polygon (ST 2): walls, fences
  Stairs,  // a line up the staircase becomes the stairs of seed 000 Fig. 1 (ST 5)
  Object,  // an object of the semantic layer: a point gets a square footprint
};

// Height of an obstacle's segments: the attribute in metres, else levels x
// level_height, else default_height (seed 000 section 3: h per segment).
struct HeightRule {
  std::string attribute;         // e.g. "height"; a number, optionally "m" or "ft"
  std::string levels_attribute;  // e.g. "building:levels"
  double level_height = 3;
  double default_height = 3;
};

struct FeatureRule {
  std::string name;                 // for the report; defaults to key=values
  std::string layer;                // empty: any layer
  std::string geometry;             // "point", "line", "polygon" or empty: any
  std::string key;                  // attribute to match; empty: every feature
  std::vector<std::string> values;  // empty: any non-empty value
  FeatureAction action = FeatureAction::Skip;
  HeightRule height;
  int in_out = 1;                   // seed 000: 0 indoor, 1 outdoor
  bool free_space_inside = false;   // rooms: the robot is inside, so rings turn clockwise
  std::string tag;                  // segment semantic / object tag; empty: the matched value
  double object_size = 0.5;         // side of a point object's square footprint (m)
  std::optional<double> object_height;  // none: a 2D object, blocking at every height
  double step_height = 0.17, step_depth = 0.3, stairs_width = 1.5;  // stairs from a line
};

struct ImportRules {
  std::vector<std::string> layers;  // layers read; empty: every layer
  std::vector<FeatureRule> rules;   // first match wins; no match: skipped ("no rule")
  double curve_step_degrees = 4;    // curves are linearised at this angle step (OGR's default)
  double margin = 2;                // border beyond the kept geometry (m)
};

// Throws FileFormatError naming the source and the JSON field that is wrong.
ImportRules parse_import_rules(const std::string& json_text, const std::string& source);
ImportRules read_import_rules(const std::string& path);

// Built-in rules for GDAL's OSM driver (buildings, barriers, steps, benches and the
// like, indoor rooms and corridors) and for any other source (polygons closed, lines
// open, points objects tagged with their layer name).
ImportRules osm_default_rules();
ImportRules plain_default_rules();

// The attribute keys the rules read (for the OSM driver's generated configuration).
std::vector<std::string> rule_keys(const ImportRules& rules);

}  // namespace fleetmap
