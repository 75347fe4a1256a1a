#pragma once
// The database as GIS layers (docs/gis-layers.md): tables in the database <db>_gis that
// GDAL's MySQL driver, and so ogrinfo, ogr2ogr and QGIS, read with a CRS, a stable
// feature id and one geometry type each. The one place that knows those tables.
//
// Why tables and not views: GDAL 3.6 takes a layer's FID column from DESCRIBE (the
// first integer column whose Key is PRI), and a MariaDB view has no key; its SRS from
// geometry_columns.srid -> spatial_ref_sys.srtext, per layer name. So each map gets its
// own layers (its own CRS), rebuilt from the fleet tables by publish() after the map is
// imported, replaced or georeferenced, and dropped by publish()/withdraw() once the map
// is gone. DDL commits implicitly: call these outside any transaction.
//
//   per map  "<map>:segments" LINESTRING, ":obstacles" POLYGON (closed shape types),
//            ":open_obstacles" MULTILINESTRING, ":border" POLYGON, ":bounds" POLYGON,
//            ":objects" POLYGON (one feature per element), ":avoided_areas" POLYGON,
//            ":robots" POINT (last positions), ":trajectories" POINT
//            ("#<id>:..." when "<map>:<layer>" exceeds MariaDB's 64 characters)
//   global   "gps_fixes" POINT, WGS 84 (EPSG:4326)
// Robots, trajectories and GPS fixes are as of the last publish (a snapshot).
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

namespace fleetmap {

struct GisLayerInfo {
  std::string table;          // the layer name GIS tools show
  std::string geometry_type;  // OGC: POINT, LINESTRING, POLYGON
  int srid = 0;
};

class GisLayers {
 public:
  // The connection is to the fleet database (its DATABASE() names <db>_gis).
  explicit GisLayers(mysqlpp::Connection& c);

  // Rebuilds every layer of map `name` (throws MapNotFound) and its CRS (crs_wkt, the
  // map frame's OGC WKT: common/gis/map_frame_crs.h), and drops the layers of maps that
  // are gone. with_gps_fixes: the fleet-wide GPS layer too; it holds every fix of every
  // robot (tens of thousands of rows on a busy fleet), so a map change leaves it to
  // `gis publish`.
  void publish(const std::string& name, const std::string& crs_wkt, bool with_gps_fixes = false);
  // Drops the layers of maps that are gone (and refreshes the GPS layer if asked).
  void withdraw(bool with_gps_fixes = false);

  // What geometry_columns lists now.
  std::vector<GisLayerInfo> layers();
  const std::string& database() const { return gis_db_; }

  // The layer table of map (name, id): "<name>:<layer>", or "#<id>:<layer>" when too long.
  static std::string layer_table(const std::string& map, unsigned map_id, const std::string& layer);
  static int map_srid(unsigned map_id) { return 100000 + static_cast<int>(map_id); }
  static constexpr int kWgs84Srid = 4326;
  static const std::vector<std::string>& map_layer_names();

 private:
  struct LayerSpec {
    std::string table;
    const char* type;
    int srid;
    std::string columns;  // CREATE TABLE column list, the geometry column `geom` last
    std::string select;   // the rows, from the fleet tables
  };
  static void stage(std::vector<LayerSpec>& layers, const char* type, int srid, const std::string& table,
                    const std::string& columns, const std::string& select);
  static void stage_gps_fixes(std::vector<LayerSpec>& layers);
  void apply(const std::vector<LayerSpec>& layers);
  void drop_orphans();

  mysqlpp::Connection& c_;
  std::string gis_db_;
};

}  // namespace fleetmap
