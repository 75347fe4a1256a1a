#include "protocol/gis_layers.h"

#include <cstdio>
#include <map>
#include <set>

#include "protocol/connection.h"
#include "protocol/map_store.h"
#include "protocol/sql_util.h"

namespace fleetmap {

namespace {

// MariaDB identifiers: at most 64 characters, backquotes doubled inside.
constexpr size_t kMaxIdentifier = 64;

std::string ident(const std::string& s) {
  std::string out = "`";
  for (char ch : s) {
    out += ch;
    if (ch == '`') out += '`';
  }
  return out + "`";
}

// A short fingerprint of a column list, the same in every build (FNV-1a, 64 bits).
std::string fnv1a(const std::string& s) {
  unsigned long long h = 14695981039346656037ull;
  for (unsigned char ch : s) h = (h ^ ch) * 1099511628211ull;
  char b[20];
  std::snprintf(b, sizeof b, "%016llx", h);
  return b;
}

// Closed shape types (common/map/map.h is_closed): closed polygon, closed curved, ramp.
constexpr const char* kClosedTypes = "(1, 3, 6)";

// Times as ISO 8601 in UTC with its zone: what GIS tools and people read without
// knowing the server's time zone (the session is switched to UTC while publishing).
std::string iso(const std::string& column) { return "DATE_FORMAT(" + column + ", '%Y-%m-%dT%H:%i:%s.%fZ')"; }

// Geometry with the layer's SRID (the stored columns are REF_SYSTEM_ID=0), bit for bit.
std::string with_srid(const std::string& geom, int srid) {
  return "ST_GeomFromWKB(ST_AsWKB(" + geom + "), " + std::to_string(srid) + ")";
}

// Sets a session variable (value: an SQL literal) and restores it when publishing ends,
// however it ends.
class SessionValue {
 public:
  SessionValue(mysqlpp::Connection& c, std::string name, const std::string& value)
      : c_(c), name_(std::move(name)), saved_("@fleetmap_gis_saved_" + name_) {
    execute(c_, "SET " + saved_ + " = @@SESSION." + name_ + ", SESSION " + name_ + " = " + value);
  }
  ~SessionValue() {
    try {
      execute(c_, "SET SESSION " + name_ + " = " + saved_);
    } catch (...) {  // connection lost: the session, and its setting, are gone
    }
  }
  SessionValue(const SessionValue&) = delete;
  SessionValue& operator=(const SessionValue&) = delete;

 private:
  mysqlpp::Connection& c_;
  std::string name_, saved_;
};

}  // namespace

const std::vector<std::string>& GisLayers::map_layer_names() {
  static const std::vector<std::string> names = {"segments",      "obstacles", "open_obstacles", "border", "bounds",
                                                 "objects",       "avoided_areas", "robots",     "trajectories"};
  return names;
}

std::string GisLayers::layer_table(const std::string& map, unsigned map_id, const std::string& layer) {
  // ':' is not allowed in map names (check_map_name), '#' neither: no two maps' layers
  // can share a table name.
  const std::string t = map + ":" + layer;
  if (t.size() <= kMaxIdentifier) return t;
  return "#" + std::to_string(map_id) + ":" + layer;
}

GisLayers::GisLayers(mysqlpp::Connection& c) : c_(c) {
  mysqlpp::Query q = c_.query("SELECT DATABASE()");
  const mysqlpp::StoreQueryResult r = q.store();
  if (r.empty() || r[0][0].is_null()) throw DbError("GIS layers: the connection has no current database");
  gis_db_ = sql::to_string(r[0][0]) + "_gis";
}

void GisLayers::stage(std::vector<LayerSpec>& layers, const char* type, int srid, const std::string& table,
                      const std::string& columns, const std::string& select) {
  layers.push_back({table, type, srid, columns, select});
}

void GisLayers::apply(const std::vector<LayerSpec>& layers) {
  // The tables first (DDL commits implicitly): created when missing, re-created when
  // their columns changed (kept in the table comment).
  std::map<std::string, std::string> existing;  // table -> comment
  {
    mysqlpp::Query q = c_.query();
    q << "SELECT table_name, table_comment FROM information_schema.tables WHERE table_schema = "
      << mysqlpp::quote << gis_db_;
    for (const mysqlpp::Row& r : q.store()) existing[sql::to_string(r[0])] = sql::to_string(r[1]);
  }
  const std::string db = ident(gis_db_) + ".";
  for (const LayerSpec& l : layers) {
    const std::string signature = "fleetmap layer " + fnv1a(l.columns);
    const auto it = existing.find(l.table);
    if (it != existing.end() && it->second == signature) continue;
    execute(c_, "DROP TABLE IF EXISTS " + db + ident(l.table));
    mysqlpp::Query q = c_.query();
    q << "CREATE TABLE " << db << ident(l.table) << " (" << l.columns
      << ", SPATIAL INDEX sx_geom (geom)) ENGINE=InnoDB COMMENT=" << mysqlpp::quote << signature;
    q.execute();
  }
  // Then the rows and the metadata in one transaction: a GIS tool reading meanwhile
  // sees the layers as they were or as they are, never half of them.
  Transaction tx(c_);
  const std::string gc = db + "geometry_columns";
  for (const LayerSpec& l : layers) {
    execute(c_, "DELETE FROM " + db + ident(l.table));
    execute(c_, "INSERT INTO " + db + ident(l.table) + " " + l.select);
    // The columns GDAL's MySQL driver reads (f_table_name, type, coord_dimension, srid).
    mysqlpp::Query q = c_.query();
    q << "REPLACE INTO " << gc << " (f_table_schema, f_table_name, f_geometry_column, coord_dimension, srid, type) "
      << "VALUES (" << mysqlpp::quote << gis_db_ << ", " << mysqlpp::quote << l.table << ", 'geom', 2, " << l.srid
      << ", '" << l.type << "')";
    q.execute();
  }
  tx.commit();
}

void GisLayers::publish(const std::string& name, const std::string& crs_wkt, bool with_gps_fixes) {
  const MapInfo map = MapStore(c_).info(name);
  const std::string id = std::to_string(map.id);
  const int srid = map_srid(map.id);
  const SessionValue utc(c_, "time_zone", "'+00:00'");
  // A polygon's ring is one GROUP_CONCAT: as long as the largest packet allowed.
  const SessionValue concat(c_, "group_concat_max_len", "67108864");

  mysqlpp::Query q = c_.query();
  q << "REPLACE INTO " << ident(gis_db_) << ".spatial_ref_sys (srid, auth_name, auth_srid, srtext) VALUES (" << srid
    << ", 'fleetmap', " << id << ", " << mysqlpp::quote << crs_wkt << ")";
  q.execute();

  const auto table = [&](const char* layer) { return layer_table(name, map.id, layer); };
  const std::string S = std::to_string(srid);

  std::vector<LayerSpec> layers;
  stage(layers, "LINESTRING", srid, table("segments"),
        "fid BIGINT UNSIGNED NOT NULL PRIMARY KEY, obstacle_id INT NOT NULL, obstacle_ord INT UNSIGNED NOT NULL, "
        "ord INT UNSIGNED NOT NULL, st TINYINT UNSIGNED NOT NULL, h DOUBLE NOT NULL, in_out TINYINT UNSIGNED NOT NULL, "
        "semantic VARCHAR(1024) NOT NULL, note VARCHAR(1024) NOT NULL, geom LINESTRING NOT NULL",
        "SELECT s.id, o.obstacle_id, s.obstacle_ord, s.ord, o.st, s.h, s.in_out, s.semantic, s.note, " +
            with_srid("s.geom", srid) +
            " FROM segments s STRAIGHT_JOIN obstacles o ON o.map_id = s.map_id AND o.ord = s.obstacle_ord"
            " WHERE s.map_id = " + id);

  // Closed obstacles as the ring through their segments' start points (consecutive
  // segments share an end, seed 000 section 3), in the map's orientation. FID = ord + 1.
  // The semantic is TEXT as in `obstacles`: a GIS feature's attributes exceed 1 KiB.
  const std::string points = "GROUP_CONCAT(CONCAT(s.ax, ' ', s.ay) ORDER BY s.ord SEPARATOR ',')";
  const std::string obstacle_columns =
      "fid BIGINT UNSIGNED NOT NULL PRIMARY KEY, obstacle_id INT NOT NULL, ord INT UNSIGNED NOT NULL, "
      "st TINYINT UNSIGNED NOT NULL, semantic TEXT NOT NULL, segments INT UNSIGNED NOT NULL, "
      "h_min DOUBLE NOT NULL, h_max DOUBLE NOT NULL, ";
  const std::string obstacle_from =
      " FROM obstacles o STRAIGHT_JOIN segments s ON s.map_id = o.map_id AND s.obstacle_ord = o.ord"
      " WHERE o.map_id = " + id;
  const std::string closed = "(o.st IN " + std::string(kClosedTypes) + " AND COUNT(*) >= 3)";
  stage(layers, "POLYGON", srid, table("obstacles"), obstacle_columns + "geom POLYGON NOT NULL",
        "SELECT o.ord + 1, o.obstacle_id, o.ord, o.st, o.semantic, COUNT(*), MIN(s.h), MAX(s.h), "
        "ST_GeomFromText(CONCAT('POLYGON((', " + points + ", ',', SUBSTRING_INDEX(" + points + ", ',', 1), '))'), " +
            S + ")" + obstacle_from + " GROUP BY o.ord HAVING " + closed);
  // Open obstacles as one part per segment: a stairs' steps are parallel segments, not
  // a chain (SPEC 3, ST=5), and one geometry type per layer.
  stage(layers, "MULTILINESTRING", srid, table("open_obstacles"), obstacle_columns + "geom MULTILINESTRING NOT NULL",
        "SELECT o.ord + 1, o.obstacle_id, o.ord, o.st, o.semantic, COUNT(*), MIN(s.h), MAX(s.h), "
        "ST_GeomFromText(CONCAT('MULTILINESTRING(', GROUP_CONCAT(CONCAT('(', s.ax, ' ', s.ay, ',', s.bx, ' ', s.`by`, ')') "
        "ORDER BY s.ord SEPARATOR ','), ')'), " + S + ")" + obstacle_from + " GROUP BY o.ord HAVING NOT " + closed);
  stage(layers, "POLYGON", srid, table("border"),
        "fid BIGINT UNSIGNED NOT NULL PRIMARY KEY, name VARCHAR(64) NOT NULL, source VARCHAR(255) NOT NULL, "
        "obstacles INT UNSIGNED NOT NULL, segments INT UNSIGNED NOT NULL, imported_at VARCHAR(32) NOT NULL, "
        "geom POLYGON NOT NULL",
        "SELECT id, name, source, obstacles, segments, " + iso("imported_at") + ", " + with_srid("border", srid) +
            " FROM maps WHERE id = " + id);
  stage(layers, "POLYGON", srid, table("bounds"), "fid BIGINT UNSIGNED NOT NULL PRIMARY KEY, geom POLYGON NOT NULL",
        "SELECT map_id, " + with_srid("bounds", srid) + " FROM map_bounds WHERE map_id = " + id);

  // One feature per element: an object's footprints may overlap, and a MULTIPOLYGON of
  // overlapping parts is invalid (OGC SF 6.1.14). FID = object id * 65536 + element.
  stage(layers, "POLYGON", srid, table("objects"),
        "fid BIGINT UNSIGNED NOT NULL PRIMARY KEY, object_id BIGINT UNSIGNED NOT NULL, object_key VARCHAR(255) NOT NULL, "
        "tag VARCHAR(64) NOT NULL, class VARCHAR(16) NOT NULL, dynamic TINYINT NOT NULL, source VARCHAR(16) NOT NULL, "
        "element INT UNSIGNED NOT NULL, zmin DOUBLE NULL, zmax DOUBLE NULL, seen_at VARCHAR(32) NOT NULL, "
        "geom POLYGON NOT NULL",
        "SELECT e.object_id * 65536 + e.ord, e.object_id, o.object_key, o.tag, t.class, o.dynamic, o.source, e.ord, "
        "e.zmin, e.zmax, " + iso("o.seen_at") + ", " + with_srid("e.footprint", srid) +
            " FROM object_elements e STRAIGHT_JOIN env_objects o ON o.id = e.object_id"
            " STRAIGHT_JOIN tags t ON t.tag = o.tag"
            " WHERE e.map_id = " + id + " AND e.ord < 65536 AND (o.expires_at IS NULL OR o.expires_at > NOW(6))");
  stage(layers, "POLYGON", srid, table("avoided_areas"),
        "fid BIGINT UNSIGNED NOT NULL PRIMARY KEY, area_key VARCHAR(255) NOT NULL, created_at VARCHAR(32) NOT NULL, "
        "geom POLYGON NOT NULL",
        "SELECT id, area_key, " + iso("created_at") + ", " + with_srid("area", srid) +
            " FROM avoided_areas WHERE map_id = " + id);

  stage(layers, "POINT", srid, table("robots"),
        "fid BIGINT UNSIGNED NOT NULL PRIMARY KEY, name VARCHAR(80) NOT NULL, state VARCHAR(16) NOT NULL, "
        "theta DOUBLE NULL, v DOUBLE NULL, last_seen VARCHAR(32) NULL, geom POINT NOT NULL",
        "SELECT id, db_user, state, theta, v, " + iso("last_seen") + ", " + with_srid("Point(x, y)", srid) +
            " FROM robots WHERE map_id = " + id + " AND removed_at IS NULL AND x IS NOT NULL AND y IS NOT NULL");
  // The poses of the robots now on this map (trajectories carry no map of their own).
  stage(layers, "POINT", srid, table("trajectories"),
        "fid BIGINT UNSIGNED NOT NULL PRIMARY KEY, robot VARCHAR(80) NOT NULL, t VARCHAR(32) NOT NULL, "
        "theta DOUBLE NOT NULL, v DOUBLE NOT NULL, w DOUBLE NULL, geom POINT NOT NULL",
        "SELECT tr.id, r.db_user, " + iso("tr.t") + ", tr.theta, tr.v, tr.w, " + with_srid("tr.pos", srid) +
            " FROM robots r STRAIGHT_JOIN trajectories tr ON tr.robot_id = r.id WHERE r.map_id = " + id);

  if (with_gps_fixes) stage_gps_fixes(layers);
  apply(layers);
  drop_orphans();
}

void GisLayers::withdraw(bool with_gps_fixes) {
  const SessionValue utc(c_, "time_zone", "'+00:00'");
  std::vector<LayerSpec> layers;
  if (with_gps_fixes) stage_gps_fixes(layers);
  apply(layers);
  drop_orphans();
}

void GisLayers::stage_gps_fixes(std::vector<LayerSpec>& layers) {
  // WGS 84 in GIS axis order: x = longitude, y = latitude.
  stage(layers, "POINT", kWgs84Srid, "gps_fixes",
        "fid BIGINT UNSIGNED NOT NULL PRIMARY KEY, robot VARCHAR(80) NOT NULL, t VARCHAR(32) NOT NULL, "
        "lat DOUBLE NOT NULL, lon DOUBLE NOT NULL, x DOUBLE NULL, y DOUBLE NULL, geom POINT NOT NULL",
        "SELECT g.id, r.db_user, " + iso("g.t") + ", g.lat, g.lon, g.x, g.y, " +
            with_srid("Point(g.lon, g.lat)", kWgs84Srid) + " FROM gps_fixes g STRAIGHT_JOIN robots r ON r.id = g.robot_id");
}

void GisLayers::drop_orphans() {
  std::set<std::string> names, ids;
  {
    mysqlpp::Query q = c_.query("SELECT id, name FROM maps");
    for (const mysqlpp::Row& r : q.store()) {
      ids.insert("#" + sql::to_string(r[0]));
      names.insert(sql::to_string(r[1]));
    }
  }
  std::vector<std::string> gone;
  {
    mysqlpp::Query q = c_.query();
    q << "SELECT table_name FROM information_schema.tables WHERE table_schema = " << mysqlpp::quote << gis_db_;
    for (const mysqlpp::Row& r : q.store()) {
      const std::string t = sql::to_string(r[0]);
      const size_t colon = t.rfind(':');
      if (colon == std::string::npos) continue;  // geometry_columns, spatial_ref_sys, gps_fixes
      const std::string owner = t.substr(0, colon);
      const bool leftover = t.size() > 4 && (t.ends_with("~new") || t.ends_with("~old"));
      if (leftover || !(names.contains(owner) || ids.contains(owner))) gone.push_back(t);
    }
  }
  for (const std::string& t : gone) execute(c_, "DROP TABLE IF EXISTS " + ident(gis_db_) + "." + ident(t));
  const std::string db = ident(gis_db_);
  mysqlpp::Query q = c_.query();
  q << "DELETE FROM " << db << ".geometry_columns WHERE f_table_name NOT IN (SELECT table_name FROM "
    << "information_schema.tables WHERE table_schema = " << mysqlpp::quote << gis_db_ << ")";
  q.execute();
  q.reset();
  // Map frames' CRSs (srid 100000 + map id) of maps that are gone.
  q << "DELETE FROM " << db << ".spatial_ref_sys WHERE srid > 100000 AND srid - 100000 NOT IN (SELECT id FROM maps)";
  q.execute();
}

std::vector<GisLayerInfo> GisLayers::layers() {
  std::vector<GisLayerInfo> out;
  mysqlpp::Query q = c_.query("SELECT f_table_name, type, srid FROM " + ident(gis_db_) +
                              ".geometry_columns ORDER BY f_table_name");
  for (const mysqlpp::Row& r : q.store())
    out.push_back({sql::to_string(r[0]), sql::to_string(r[1]), static_cast<int>(sql::to_int(r[2]))});
  return out;
}

}  // namespace fleetmap
