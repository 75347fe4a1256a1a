#pragma once
// A map and what lies on it, written through OGR as GIS layers (seed 001 appendix on
// GIS): GeoPackage, FlatGeobuf or any OGR vector driver, with the CRS in the file, one
// geometry type per layer, a feature id (FID and an "id" field, the same number) and
// valid polygons.
//
//   layer            geometry         one feature per
//   border           Polygon          the map's border
//   segments         LineString       segment (map order; the fields of map_geojson.h)
//   obstacles        Polygon          closed obstacle (is_closed: polygons, curves, ramps)
//   open_obstacles   LineString       open obstacle (open polygons and curves, stairs)
//   objects          MultiPolygon     object: the union of its elements' footprints
//   object_elements  Polygon          element of an object, with its height range
//   avoided_areas    Polygon          avoided area
//   bounds           Polygon          the scene's bounds
//   topo_nodes       Point            node of the topological graph
//   topo_edges       LineString       edge
//   trajectory_points Point           reported pose (t in UTC, theta, v)
//   trajectories     LineString       robot: its poses in time order
//
// Empty layers are not written. Polygons that GEOS finds invalid (an object's
// overlapping elements, a self-touching ring) are repaired by union (objects) or
// MakeValid (the others, one feature per part), never written invalid.
//
// The frame (ExportCrs): the map frame, whose CRS is the base CRS when the map frame is
// that CRS (MapGeoref::frame_is_crs), else an engineering CRS in metres named after the
// map (LOCAL_CS, as an unreferenced map or one rotated or offset in its base); or the
// base CRS; or WGS 84 (EPSG:4326, longitude first). The last two need a georeference.
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/io/trajectory_geojson.h"
#include "common/map/map.h"
#include "common/map/map_georef.h"
#include "common/planning/topo_graph.h"
#include "common/scene/scene.h"

namespace fleetmap {

enum class ExportCrs { Map, Base, Wgs84 };

// "map", "base" or "wgs84"; throws BadInput naming what came.
ExportCrs parse_export_crs(const std::string& s);

// The GDAL driver of a --format: "gpkg" -> GPKG, "fgb" -> FlatGeobuf, else the GDAL
// short name itself (any case). Throws BadInput when GDAL has no such driver, or one
// that cannot create vector files.
std::string ogr_driver_for(const std::string& format);

struct OgrExportOptions {
  std::string format = "gpkg";  // as ogr_driver_for takes it
  ExportCrs crs = ExportCrs::Map;
  std::string map_name;
  std::optional<MapGeoref> georef;
  std::set<std::string> only_layers;  // empty: every layer
};

struct OgrLayerReport {
  std::string name;
  size_t features = 0;
  size_t repaired = 0;  // polygons made valid
};

class OgrExport {
 public:
  // Creates the file (an existing one is replaced). Throws BadInput for a crs that needs
  // a georeference the map has not, IoError when the file cannot be created.
  OgrExport(const std::string& path, const OgrExportOptions& options);
  ~OgrExport();
  OgrExport(const OgrExport&) = delete;
  OgrExport& operator=(const OgrExport&) = delete;

  void add_map(const Map& map);
  void add_scene(const Scene& scene);
  void add_topology(const TopoGraph& graph);
  void add_tracks(const std::vector<Track>& tracks);

  // Writes and closes the file; throws IoError when the driver fails. The destructor
  // closes too, without throwing.
  void close();

  const std::vector<OgrLayerReport>& layers() const { return reports_; }
  // The CRS written, as WKT.
  std::string crs_wkt() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<OgrLayerReport> reports_;
};

}  // namespace fleetmap
