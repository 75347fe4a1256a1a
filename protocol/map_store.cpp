#include "protocol/map_store.h"

#include <charconv>
#include <map>

#include "common/map/map_window.h"
#include "common/geometry/number_format.h"
#include "protocol/connection.h"
#include "protocol/sql_util.h"

namespace fleetmap {

using sql::to_double;
using sql::to_int;

namespace {

constexpr size_t kBatchRows = 2000;  // rows per multi-row INSERT

std::string n(double v) { return format_number(v); }

std::string polygon_wkt(const Rect& r) {
  return "POLYGON((" + n(r.xmin) + " " + n(r.ymin) + "," + n(r.xmax) + " " + n(r.ymin) + "," + n(r.xmax) + " " +
         n(r.ymax) + "," + n(r.xmin) + " " + n(r.ymax) + "," + n(r.xmin) + " " + n(r.ymin) + "))";
}

MapInfo info_from_row(const mysqlpp::Row& r) {
  MapInfo i;
  i.id = static_cast<unsigned>(to_int(r[0]));
  i.name = std::string(r[1]);
  i.border = {to_double(r[2]), to_double(r[3]), to_double(r[4]), to_double(r[5])};
  i.obstacles = static_cast<size_t>(to_int(r[6]));
  i.segments = static_cast<size_t>(to_int(r[7]));
  i.source = std::string(r[8]);
  i.imported_at = std::string(r[9]);
  i.revision = static_cast<unsigned>(to_int(r[15]));
  if (!r[10].is_null()) {
    MapGeoref g;
    g.crs = std::string(r[10]);
    g.tx = to_double(r[11]);
    g.ty = to_double(r[12]);
    g.rotation = to_double(r[13]);
    g.scale = to_double(r[14]);
    i.georef = std::move(g);
  }
  return i;
}

constexpr const char* kInfoColumns =
    "id, name, mx1, my1, mx4, my4, obstacles, segments, source, imported_at, geo_crs, geo_tx, geo_ty, geo_rotation, "
    "geo_scale, revision";

// The SET list of a georeference.
void add_geo_assignments(mysqlpp::Query& q, const MapGeoref& g) {
  q << "geo_crs = " << mysqlpp::quote << g.crs << ", geo_tx = " << n(g.tx) << ", geo_ty = " << n(g.ty)
    << ", geo_rotation = " << n(g.rotation) << ", geo_scale = " << n(g.scale);
}

// Segment columns in the order read_segment expects, from table alias s.
constexpr const char* kSegmentColumns = "s.obstacle_ord, s.ax, s.ay, s.bx, s.`by`, s.h, s.in_out, s.semantic, s.note";

Segment read_segment(const mysqlpp::Row& r) {
  Segment s;
  s.a = {to_double(r[1]), to_double(r[2])};
  s.b = {to_double(r[3]), to_double(r[4])};
  s.h = to_double(r[5]);
  s.in_out = static_cast<int>(to_int(r[6]));
  s.semantic = std::string(r[7].data(), r[7].length());
  s.note = std::string(r[8].data(), r[8].length());
  return s;
}

// Sets a session variable for a scope, restoring it on every way out.
class SessionFlag {
 public:
  SessionFlag(mysqlpp::Connection& c, std::string name, int value, int restore)
      : c_(c), name_(std::move(name)), restore_(restore) {
    execute(c_, "SET SESSION " + name_ + " = " + std::to_string(value));
  }
  ~SessionFlag() {
    try {
      execute(c_, "SET SESSION " + name_ + " = " + std::to_string(restore_));
    } catch (...) {  // connection lost: the session, and its setting, are gone
    }
  }

 private:
  mysqlpp::Connection& c_;
  std::string name_;
  int restore_;
};

}  // namespace

std::optional<std::string> check_map_name(const std::string& name) {
  bool ok = !name.empty() && name.size() <= 64;
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.');
  if (ok) return std::nullopt;
  return "expected a map name of 1-64 characters from [A-Za-z0-9_.-], got '" + name + "'";
}

unsigned MapStore::import(const Map& m, const std::string& name, const std::string& source, bool replace,
                          const ImportProgress& progress) {
  MapImportOptions o;
  o.replace = replace;
  o.progress = progress;
  return import(m, name, source, o).map_id;
}

MapImportReport MapStore::import(const Map& m, const std::string& name, const std::string& source,
                                 const MapImportOptions& o) {
  if (auto e = check_map_name(name)) throw std::invalid_argument(*e);
  Transaction tx(c_);
  mysqlpp::Query q = c_.query();
  q << "SELECT id FROM maps WHERE name = " << mysqlpp::quote << name << " FOR UPDATE";
  mysqlpp::StoreQueryResult existing = q.store();
  MapImportReport report;
  const size_t total = m.segment_count();
  q.reset();
  if (!existing.empty()) {
    if (!o.replace) throw MapExists(name);
    // The row stays (its id is what robots, objects, areas, bounds and the graph name);
    // its obstacles and segments are replaced. Dependents first: a refusal changes nothing.
    report.replaced = true;
    report.map_id = static_cast<unsigned>(to_int(existing[0][0]));
    report.replace = prepare_replace(c_, report.map_id, name, m, o.drop, o.force, [&] { return load(name); });
    if (o.georef) {  // the import's own, in place of a kept one
      report.replace.kept.georef.reset();
      report.replace.georef_replaced = true;
    }
    const std::string id = std::to_string(report.map_id);
    // Segments first: one statement instead of a cascade row by row.
    execute(c_, "DELETE FROM segments WHERE map_id = " + id);
    execute(c_, "DELETE FROM obstacles WHERE map_id = " + id);
    q << "UPDATE maps SET mx1 = " << n(m.border.mx1) << ", my1 = " << n(m.border.my1) << ", mx4 = " << n(m.border.mx4)
      << ", my4 = " << n(m.border.my4) << ", border = ST_GeomFromText('" << polygon_wkt(m.border.rect())
      << "'), source = " << mysqlpp::quote << source.substr(0, 255) << ", obstacles = " << m.obstacles.size()
      << ", segments = " << total << ", imported_at = CURRENT_TIMESTAMP(6), revision = revision + 1";
    if (o.georef) {
      q << ", ";
      add_geo_assignments(q, *o.georef);
    }
    q << " WHERE id = " << id;
    q.execute();
    // Control points describe the georeference they were fitted to (GeorefStore).
    if (o.georef) execute(c_, "DELETE FROM georef_control_points WHERE map_id = " + id);
  } else {
    q << "INSERT INTO maps (name, mx1, my1, mx4, my4, border, source, obstacles, segments) VALUES ("
      << mysqlpp::quote << name << ", " << n(m.border.mx1) << ", " << n(m.border.my1) << ", " << n(m.border.mx4)
      << ", " << n(m.border.my4) << ", ST_GeomFromText('" << polygon_wkt(m.border.rect()) << "'), "
      << mysqlpp::quote << source.substr(0, 255) << ", " << m.obstacles.size() << ", " << total << ")";
    report.map_id = static_cast<unsigned>(q.execute().insert_id());
    if (o.georef) {
      q.reset();
      q << "UPDATE maps SET ";
      add_geo_assignments(q, *o.georef);
      q << " WHERE id = " << report.map_id;
      q.execute();
    }
  }
  const std::string mid = std::to_string(report.map_id);

  // Every row below references rows inserted just before in this transaction, so the
  // per-row foreign-key lookups prove nothing; skipping them makes a large import
  // markedly faster (scripts/bench-map.sh). Restored before commit.
  SessionFlag no_fk_checks(c_, "foreign_key_checks", 0, 1);

  // Obstacles, in batches.
  for (size_t k = 0; k < m.obstacles.size();) {
    q.reset();
    q << "INSERT INTO obstacles (map_id, ord, obstacle_id, st, semantic, cx, cy, r) VALUES ";
    for (size_t b = 0; b < kBatchRows && k < m.obstacles.size(); ++b, ++k) {
      const Obstacle& o = m.obstacles[k];
      if (b) q << ",";
      q << "(" << mid << "," << k << "," << o.id << "," << static_cast<int>(o.type) << "," << mysqlpp::quote
        << o.semantic << "," << n(o.bound.c.x) << "," << n(o.bound.c.y) << "," << n(o.bound.r) << ")";
    }
    q.execute();
  }

  // Segments, in batches, with their geometry for the spatial index.
  size_t done = 0, rows = 0;
  auto flush = [&] {
    if (rows == 0) return;
    q.execute();
    done += rows;
    rows = 0;
    if (o.progress) o.progress(done, total);
  };
  for (size_t k = 0; k < m.obstacles.size(); ++k) {
    const Obstacle& ob = m.obstacles[k];
    for (size_t i = 0; i < ob.segments.size(); ++i) {
      const Segment& s = ob.segments[i];
      if (rows == 0) {
        q.reset();
        q << "INSERT INTO segments (map_id, obstacle_ord, ord, ax, ay, bx, `by`, h, in_out, semantic, note, geom) "
             "VALUES ";
      } else {
        q << ",";
      }
      q << "(" << mid << "," << k << "," << i << "," << n(s.a.x) << "," << n(s.a.y) << "," << n(s.b.x) << ","
        << n(s.b.y) << "," << n(s.h) << "," << s.in_out << "," << mysqlpp::quote << s.semantic << ","
        << mysqlpp::quote << s.note << ",LineString(Point(" << n(s.a.x) << "," << n(s.a.y) << "),Point("
        << n(s.b.x) << "," << n(s.b.y) << ")))";
      if (++rows == kBatchRows) flush();
    }
  }
  flush();
  tx.commit();
  return report;
}

std::vector<MapInfo> MapStore::list() {
  mysqlpp::Query q = c_.query();
  q << "SELECT " << kInfoColumns << " FROM maps ORDER BY name";
  std::vector<MapInfo> out;
  for (const mysqlpp::Row& r : q.store()) out.push_back(info_from_row(r));
  return out;
}

MapInfo MapStore::info(const std::string& name) {
  mysqlpp::Query q = c_.query();
  q << "SELECT " << kInfoColumns << " FROM maps WHERE name = " << mysqlpp::quote << name;
  mysqlpp::StoreQueryResult res = q.store();
  if (res.empty()) throw MapNotFound(name);
  return info_from_row(res[0]);
}

std::optional<MapInfo> MapStore::info(unsigned id) {
  mysqlpp::Query q = c_.query();
  q << "SELECT " << kInfoColumns << " FROM maps WHERE id = " << id;
  mysqlpp::StoreQueryResult res = q.store();
  if (res.empty()) return std::nullopt;
  return info_from_row(res[0]);
}

void MapStore::set_georef(const std::string& name, const std::optional<MapGeoref>& g) {
  mysqlpp::Query q = c_.query();
  if (g) {
    q << "UPDATE maps SET geo_crs = " << mysqlpp::quote << g->crs << ", geo_tx = " << n(g->tx)
      << ", geo_ty = " << n(g->ty) << ", geo_rotation = " << n(g->rotation) << ", geo_scale = " << n(g->scale);
  } else {
    q << "UPDATE maps SET geo_crs = NULL, geo_tx = NULL, geo_ty = NULL, geo_rotation = NULL, geo_scale = NULL";
  }
  q << " WHERE name = " << mysqlpp::quote << name;
  if (q.execute().rows() == 0) info(name);  // throws MapNotFound when there is no such map
  // Control points describe the georeference they were fitted to (sql/55_georef.sql).
  q.reset();
  q << "DELETE c FROM georef_control_points c JOIN maps m ON m.id = c.map_id WHERE m.name = " << mysqlpp::quote
    << name;
  q.execute();
}

Map MapStore::load(const std::string& name) { return load(name, nullptr); }

Map MapStore::load(const std::string& name, MapInfo* info_out) {
  // Each statement reads what is committed when it runs (READ COMMITTED, protocol/
  // connection.h), and a replace keeps the id: a replace committed between the reads
  // would mix two maps. Every replace moves the revision, so an unchanged revision after
  // the reads means they all saw the same import.
  for (int attempt = 1;; ++attempt) {
    const MapInfo info = this->info(name);
    std::optional<Map> m = read_map(info);
    const std::optional<MapInfo> after = this->info(info.id);
    if (m && after && after->revision == info.revision) {
      if (info_out) *info_out = info;
      return std::move(*m);
    }
    if (!m && after && after->revision == info.revision)
      throw DbError("segment of a missing obstacle in map '" + name + "'");
    if (attempt == 5) throw DbError("map '" + name + "' was replaced again and again while it was read");
  }
}

std::optional<Map> MapStore::read_map(const MapInfo& info) {
  Map m;
  m.border = info.border;
  const std::string mid = std::to_string(info.id);
  mysqlpp::Query q = c_.query();
  q << "SELECT obstacle_id, st, semantic FROM obstacles WHERE map_id = " << mid << " ORDER BY ord";
  for (const mysqlpp::Row& r : q.store()) {
    Obstacle o;
    o.id = static_cast<int>(to_int(r[0]));
    o.type = static_cast<ShapeType>(to_int(r[1]));
    o.semantic = std::string(r[2].data(), r[2].length());
    m.obstacles.push_back(std::move(o));
  }
  q.reset();
  q << "SELECT " << kSegmentColumns << " FROM segments s WHERE s.map_id = " << mid << " ORDER BY s.obstacle_ord, s.ord";
  mysqlpp::UseQueryResult res = q.use();
  bool consistent = true;
  while (mysqlpp::Row r = res.fetch_row()) {
    const size_t k = static_cast<size_t>(to_int(r[0]));
    if (k >= m.obstacles.size()) consistent = false;  // read to the end: the connection must be free again
    else if (consistent) m.obstacles[k].segments.push_back(read_segment(r));
  }
  if (!consistent) return std::nullopt;
  m.compute_bounds();
  return m;
}

bool MapStore::remove(const std::string& name) {
  Transaction tx(c_);
  mysqlpp::Query q = c_.query();
  q << "SELECT id FROM maps WHERE name = " << mysqlpp::quote << name << " FOR UPDATE";
  mysqlpp::StoreQueryResult res = q.store();
  if (res.empty()) return false;
  const std::string id = std::string(res[0][0]);
  execute(c_, "DELETE FROM segments WHERE map_id = " + id);
  execute(c_, "DELETE FROM obstacles WHERE map_id = " + id);
  execute(c_, "DELETE FROM maps WHERE id = " + id);
  tx.commit();
  return true;
}

std::string MapStore::window_sql(unsigned map_id, const Rect& rect, WindowAccess access) const {
  // The spatial index answers MBRIntersects; the cut is exact, in common/.
  const char* hint = access == WindowAccess::SpatialIndex ? " FORCE INDEX (sx_segments_geom)"
                                                          : " IGNORE INDEX (sx_segments_geom, ix_segments_obstacle)";
  return std::string("SELECT ") + kSegmentColumns + ", o.obstacle_id, o.st, o.semantic" +
         " FROM segments s" + hint +
         " JOIN obstacles o ON o.map_id = s.map_id AND o.ord = s.obstacle_ord"
         " WHERE MBRIntersects(s.geom, ST_GeomFromText('" + polygon_wkt(rect) + "'))"
         " AND s.map_id = " + std::to_string(map_id) + " ORDER BY s.obstacle_ord, s.ord";
}

Map MapStore::window(const std::string& name, const Rect& rect, WindowAccess access) {
  return window(this->info(name).id, rect, access);
}

Map MapStore::window(unsigned map_id, const Rect& rect, WindowAccess access) {
  Map out;
  out.border = Border::from_rect(rect);
  if (rect.empty()) return out;
  mysqlpp::Query q = c_.query(window_sql(map_id, rect, access));
  long long current = -1;
  Obstacle whole;  // the candidate segments of the current obstacle, uncut
  auto finish = [&] {
    if (current < 0) return;
    if (auto cut = clip_obstacle(whole, rect)) out.obstacles.push_back(std::move(*cut));
  };
  for (const mysqlpp::Row& r : q.store()) {
    const long long ord = to_int(r[0]);
    if (ord != current) {
      finish();
      current = ord;
      whole = Obstacle{};
      whole.id = static_cast<int>(to_int(r[9]));
      whole.type = static_cast<ShapeType>(to_int(r[10]));
      whole.semantic = std::string(r[11].data(), r[11].length());
    }
    whole.segments.push_back(read_segment(r));
  }
  finish();
  return out;
}

std::string MapStore::window_index(const std::string& name, const Rect& rect) {
  const MapInfo info = this->info(name);
  mysqlpp::Query q = c_.query("EXPLAIN " + window_sql(info.id, rect, WindowAccess::SpatialIndex));
  for (const mysqlpp::Row& r : q.store()) {
    if (std::string(r["table"]) == "s") return r["key"].is_null() ? "" : std::string(r["key"]);
  }
  return "";
}

}  // namespace fleetmap
