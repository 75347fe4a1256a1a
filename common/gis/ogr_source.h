#pragma once
// Opening a GIS source with OGR, with what some drivers need beside the name: GDAL's
// OSM driver gets a configuration with the keys the rules read as columns, and a DXF
// file's drawing units ($INSUNITS) give its scale to metres.
#include <gdal_priv.h>

#include <string>
#include <vector>

namespace fleetmap {

// Opens a vector source read-only (a path or an OGR connection string); throws
// FileFormatError naming it and GDAL's reason when OGR cannot.
// Whether s ends with suffix (lower case), ignoring the case of s: file extensions.
bool ends_with_ci(const std::string& s, const std::string& suffix);

GDALDatasetUniquePtr open_ogr_source(const std::string& source, const std::vector<std::string>& keys);

// GDAL's default osmconf.ini with `keys` added to every layer's attributes and names not
// laundered (so "building:levels" stays a column of that name). GDAL 3.6 has no
// TAGS_FORMAT=JSON open option: other keys stay in other_tags, which the semantic keeps.
std::string osm_config_text(const std::vector<std::string>& keys);

// Metres per drawing unit of a DXF file, from its header variable $INSUNITS (AutoCAD:
// 1 in, 2 ft, 4 mm, 5 cm, 6 m, 14 dm, ...); 1 when absent or 0 (unitless). GDAL's DXF
// driver reads the header but does not expose its variables, hence this scan of the
// HEADER section's group code/value pairs. Throws BadInput for a unit it does not know.
double dxf_unit_scale(const std::string& path);

}  // namespace fleetmap
