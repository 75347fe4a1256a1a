#pragma once
// A fleetmap map from anything GDAL/OGR reads (seed 001 section III and its appendix on
// GIS): Shapefile, GeoPackage, GeoJSON, OSM XML/PBF, DXF, GML, KML, FlatGeobuf, or a
// PostGIS/MySQL connection string. The format is OGR's business; the rules
// (common/gis/import_rules.h) say which features become obstacles or objects.
// All or nothing: a refused feature throws, naming its layer and feature id.
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/gis/geo_transform.h"
#include "common/gis/import_rules.h"
#include "common/map/map.h"
#include "common/map/map_georef.h"
#include "common/scene/scene.h"

namespace fleetmap {

enum class InvalidPolicy { Repair, Refuse };

struct Clip {
  double minlon, minlat, maxlon, maxlat;  // WGS 84 degrees
};

struct OgrImportOptions {
  std::optional<ImportRules> rules;      // none: osm_default_rules for OSM, else plain_default_rules
  std::vector<std::string> layers;       // overrides rules.layers when given
  std::string crs;                       // the source CRS when the data has none, or to override it
  std::optional<LonLat> origin;          // local TM origin for a geographic source
  std::optional<MapGeoref> frame;        // import into this frame (an existing map's)
  std::optional<Clip> clip;              // keep only what lies inside (features cut at the edge)
  bool clip_to_osm_bounds = true;        // OSM with <bounds>: clip there unless clip is given
  InvalidPolicy invalid = InvalidPolicy::Repair;
  // fraction of the source read (0..1), every feature or so; for the progress line
  std::function<void(double)> progress;
};

struct LayerReport {
  size_t read = 0, kept = 0;
  std::map<std::string, size_t> skipped;  // reason -> count
  size_t obstacles = 0, segments = 0, objects = 0;
  size_t repaired = 0, clipped = 0, repeated_vertices = 0;
};

struct OgrImportReport {
  std::string driver;
  std::map<std::string, LayerReport> layers;
  std::string source_crs;  // as the data (or --crs) gave it; empty: none
  std::string frame;       // how the map frame was chosen, for the operator
  double unit_scale = 1;   // metres per source unit when the source has no CRS
  Rect extent = Rect::none();                        // map frame
  std::optional<std::pair<LonLat, LonLat>> extent_wgs84;  // south-west, north-east
  std::vector<std::string> warnings;                 // invalid geometries repaired, with why
};

struct OgrImport {
  Map map;                          // validated
  Scene scene;                      // validated objects
  std::optional<MapGeoref> georef;  // none: the source had no CRS
  OgrImportReport report;
};

// Throws BadInput (FileFormatError when OGR cannot open or read it) naming the source,
// layer, feature id and what was expected.
OgrImport import_ogr(const std::string& source, const OgrImportOptions& options = {});

// True for a name OGR should read: .osm .pbf .gpkg .geojson .shp .dxf .gml .kml .fgb
// .gpx .sqlite, or a connection string (PG:, MYSQL:).
bool is_ogr_source(const std::string& source);

}  // namespace fleetmap
