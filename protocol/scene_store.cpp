#include "protocol/scene_store.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <unordered_map>

#include "common/map/map_validation.h"
#include "common/scene/scene_validation.h"
#include "common/geometry/number_format.h"
#include "common/geometry/polygon.h"
#include "protocol/connection.h"
#include "protocol/batch_insert.h"
#include "protocol/live_scene.h"
#include "protocol/map_store.h"
#include "protocol/sql_util.h"
#include "protocol/wkb.h"

namespace fleetmap {
namespace {

constexpr double kFirstBoxHalf = 1.0;   // near(): half side of the first search box (m)
constexpr const char* kLive = "(o.expires_at IS NULL OR o.expires_at > NOW(6))";
constexpr const char* kIndex = "sx_object_elements_footprint";

std::string n(double v) { return format_number(v); }
std::string point_sql(Point p) { return "POINT(" + n(p.x) + "," + n(p.y) + ")"; }
std::string geom_sql(const Polygon& ring) { return "ST_GeomFromText('" + polygon_to_wkt(ring) + "')"; }
std::string box_sql(Point p, double h) {
  return geom_sql({{p.x - h, p.y - h}, {p.x + h, p.y - h}, {p.x + h, p.y + h}, {p.x - h, p.y + h}});
}

// The first bytes of s, at most n, without cutting a UTF-8 character: the column would
// refuse a broken sequence (error 1366, strict mode).
std::string utf8_prefix(const std::string& s, size_t n) {
  if (s.size() <= n) return s;
  while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;
  return s.substr(0, n);
}

// The scene's rules (common/scene/scene_validation.h), thrown before any SQL runs.
void require(const std::optional<std::string>& problem) {
  if (problem) throw std::invalid_argument(*problem);
}

// The first stored key among `keys` in table/column of the map, if any.
std::optional<std::string> first_existing(mysqlpp::Connection& c, const char* table, const char* column,
                                          const std::string& mid, const std::vector<std::string>& keys) {
  for (size_t k = 0; k < keys.size(); k += BatchInsert::kRows) {
    mysqlpp::Query q = c.query();
    q << "SELECT " << column << " FROM " << table << " WHERE map_id = " << mid << " AND " << column << " IN (";
    for (size_t i = k; i < std::min(keys.size(), k + BatchInsert::kRows); ++i) q << (i > k ? "," : "") << mysqlpp::quote << keys[i];
    q << ") ORDER BY " << column << " LIMIT 1";
    mysqlpp::StoreQueryResult r = q.store();
    if (!r.empty()) return sql::to_string(r[0][0]);
  }
  return std::nullopt;
}

constexpr const char* kRowColumns =
    "SELECT o.id, o.object_key, o.tag, t.class, o.dynamic, o.source, r.db_user, o.label, o.seen_at, o.expires_at,"
    " (SELECT COUNT(*) FROM object_elements e WHERE e.object_id = o.id)"
    " FROM env_objects o JOIN tags t ON t.tag = o.tag LEFT JOIN robots r ON r.id = o.robot_id";

ObjectRow object_row(const mysqlpp::Row& r) {
  ObjectRow o;
  o.id = sql::to_uint(r[0]);
  o.key = sql::to_string(r[1]);
  o.tag = sql::to_string(r[2]);
  o.tag_class = sql::to_string(r[3]);
  o.dynamic = sql::to_int(r[4]) != 0;
  o.source = sql::to_string(r[5]);
  if (!r[6].is_null()) o.robot = sql::to_string(r[6]);
  if (!r[7].is_null()) o.label = sql::to_string(r[7]);
  o.seen_at = sql::to_string(r[8]);
  if (!r[9].is_null()) o.expires_at = sql::to_string(r[9]);
  o.elements = static_cast<size_t>(sql::to_uint(r[10]));
  return o;
}

// Full rows for (id, distance) pairs, in the pairs' order.
std::vector<ObjectRow> rows_for(mysqlpp::Connection& c, const std::vector<ObjectRow>& found) {
  if (found.empty()) return {};
  mysqlpp::Query q = c.query();
  q << kRowColumns << " WHERE o.id IN (";
  for (size_t i = 0; i < found.size(); ++i) q << (i ? "," : "") << found[i].id;
  q << ")";
  std::unordered_map<unsigned long long, ObjectRow> by_id;
  for (const mysqlpp::Row& r : q.store()) {
    ObjectRow o = object_row(r);
    by_id.emplace(o.id, std::move(o));
  }
  std::vector<ObjectRow> out;
  for (const ObjectRow& f : found) {
    auto it = by_id.find(f.id);
    if (it == by_id.end()) continue;  // deleted in between (expired, replaced)
    out.push_back(std::move(it->second));
    out.back().distance = f.distance;
  }
  return out;
}

// The candidate search of near() and list(): the elements of the map's live objects
// (with the tag, if any). With box_half, only those whose bounding box meets the square
// of that half side around p, found with the spatial index; without, every element of
// the map (the baseline). The elements' table comes first (STRAIGHT_JOIN): see
// 20_views.sql on MDEV-26123.
std::string candidates_sql(unsigned map_id, Point p, const std::string& tag, std::optional<double> box_half,
                           mysqlpp::Connection& c) {
  mysqlpp::Query q = c.query();
  q << "SELECT e.object_id, o.object_key, ST_AsBinary(e.footprint) FROM object_elements e "
    << (box_half ? "FORCE" : "IGNORE") << " INDEX (" << kIndex << ")"
    << " STRAIGHT_JOIN env_objects o ON o.id = e.object_id WHERE e.map_id = " << map_id;
  if (box_half) q << " AND MBRIntersects(e.footprint, " << box_sql(p, *box_half) << ")";
  if (!tag.empty()) q << " AND o.tag = " << mysqlpp::quote << tag;
  q << " AND " << kLive;
  return q.str();
}

// Per object, its least element distance to p, nearest first, ties by key; at most
// limit objects, and only those within `within`. The distances are computed here,
// exactly (common/geometry/polygon.h): MariaDB 10.11's ST_Distance between a polygon and a point
// is approximate (off by up to 0.17 m on 9 of 200 random boxes; docs/semantic-layer.md).
std::vector<ObjectRow> nearest(mysqlpp::Connection& c, const std::string& sql, Point p, std::optional<size_t> limit,
                               std::optional<double> within, size_t* candidates = nullptr) {
  std::unordered_map<unsigned long long, ObjectRow> by_id;
  mysqlpp::Query q = c.query(sql);
  mysqlpp::UseQueryResult res = q.use();
  while (mysqlpp::Row r = res.fetch_row()) {
    const double d = distance_to_polygon(p, polygon_from_wkb(r[2]));
    auto [it, fresh] = by_id.try_emplace(sql::to_uint(r[0]));
    if (fresh) {
      it->second.id = it->first;
      it->second.key = sql::to_string(r[1]);
      it->second.distance = d;
    } else {
      it->second.distance = std::min(*it->second.distance, d);
    }
  }
  if (candidates) *candidates = by_id.size();
  std::vector<ObjectRow> out;
  for (auto& [id, o] : by_id)
    if (!within || *o.distance <= *within) out.push_back(std::move(o));
  auto closer = [](const ObjectRow& a, const ObjectRow& b) {
    return *a.distance != *b.distance ? *a.distance < *b.distance : a.key < b.key;
  };
  if (limit && out.size() > *limit) {
    std::partial_sort(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(*limit), out.end(), closer);
    out.resize(*limit);
  } else {
    std::sort(out.begin(), out.end(), closer);
  }
  return out;
}

}  // namespace

unsigned SceneStore::map_id(const std::string& map, const char* lock) {
  mysqlpp::Query q = c_.query();
  q << "SELECT id FROM maps WHERE name = " << mysqlpp::quote << map << lock;
  mysqlpp::StoreQueryResult res = q.store();
  if (res.empty()) throw MapNotFound(map);
  return static_cast<unsigned>(sql::to_uint(res[0][0]));
}

SceneImportReport SceneStore::import(const std::string& map, const Scene& scene, const SceneImportOptions& options) {
  if (auto e = check_map_name(map)) throw std::invalid_argument(*e);
  validate_scene(scene);
  SceneImportReport report;
  Transaction tx(c_);
  // A shared lock on the map: it cannot be deleted or replaced under us.
  const std::string mid = std::to_string(map_id(map, " LOCK IN SHARE MODE"));

  std::set<std::string> known;
  for (const mysqlpp::Row& r : c_.query("SELECT tag FROM tags LOCK IN SHARE MODE").store()) known.insert(sql::to_string(r[0]));
  for (const EnvObject& o : scene.objects) {
    if (known.count(o.tag)) continue;
    if (!options.add_tags) throw UnknownTag(o.tag, o.id);
    known.insert(o.tag);
    report.tags_added.push_back(o.tag);
  }
  if (!report.tags_added.empty()) {
    BatchInsert tags(c_, "INSERT INTO tags (tag, class, description) VALUES ");
    for (const std::string& t : report.tags_added) {
      tags.row() << "(" << mysqlpp::quote << t << ",'obstacle','added by objects import --add-tags')";
      tags.end_row();
    }
    tags.flush();
  }

  if (options.replace) {
    // Elements first: one statement instead of a cascade row by row.
    execute(c_, "DELETE e FROM object_elements e JOIN env_objects o ON o.id = e.object_id"
                " WHERE o.map_id = " + mid + " AND o.source = 'imported'");
    report.replaced_objects = c_.query("DELETE FROM env_objects WHERE source = 'imported' AND map_id = " + mid).execute().rows();
    report.replaced_avoided = c_.query("DELETE FROM avoided_areas WHERE map_id = " + mid).execute().rows();
    execute(c_, "DELETE FROM map_bounds WHERE map_id = " + mid);
  }
  // Keys still stored: everything without replace; with it, a robot's observation.
  const char* hint = options.replace ? "" : "; use --replace to replace the map's imported objects and avoided areas";
  std::vector<std::string> keys;
  for (const EnvObject& o : scene.objects) keys.push_back(o.id);
  if (auto k = first_existing(c_, "env_objects", "object_key", mid, keys)) throw SceneKeyExists(map, "an object", *k, hint);
  keys.clear();
  for (const AvoidedArea& a : scene.avoided) keys.push_back(a.id);
  if (auto k = first_existing(c_, "avoided_areas", "area_key", mid, keys)) throw SceneKeyExists(map, "an avoided area", *k, hint);

  BatchInsert objects(c_, "INSERT INTO env_objects (map_id, object_key, tag, dynamic, source) VALUES ");
  for (const EnvObject& o : scene.objects) {
    objects.row() << "(" << mid << "," << mysqlpp::quote << o.id << "," << mysqlpp::quote << o.tag << ","
                  << int(o.dynamic) << ",'imported')";
    objects.end_row();
  }
  objects.flush();
  // Ids by key, read back (multi-row inserts need not number rows consecutively).
  std::unordered_map<std::string, std::string> ids;
  {
    mysqlpp::Query q = c_.query("SELECT object_key, id FROM env_objects WHERE source = 'imported' AND map_id = " + mid);
    mysqlpp::UseQueryResult res = q.use();
    while (mysqlpp::Row r = res.fetch_row()) ids.emplace(sql::to_string(r[0]), sql::to_string(r[1]));
  }
  BatchInsert elements(c_, "INSERT INTO object_elements (object_id, ord, map_id, footprint, zmin, zmax) VALUES ");
  for (const EnvObject& o : scene.objects) {
    for (size_t i = 0; i < o.elements.size(); ++i) {
      const Element& e = o.elements[i];
      elements.row() << "(" << ids.at(o.id) << "," << i << "," << mid << "," << geom_sql(e.footprint) << ","
                     << (e.z ? n(e.z->zmin) : "NULL") << "," << (e.z ? n(e.z->zmax) : "NULL") << ")";
      elements.end_row();
      ++report.elements;
    }
  }
  elements.flush();
  report.objects = scene.objects.size();

  BatchInsert avoided(c_, "INSERT INTO avoided_areas (map_id, area_key, area) VALUES ");
  for (const AvoidedArea& a : scene.avoided) {
    avoided.row() << "(" << mid << "," << mysqlpp::quote << a.id << "," << geom_sql(a.area) << ")";
    avoided.end_row();
  }
  avoided.flush();
  report.avoided = scene.avoided.size();

  if (scene.bounds) {
    execute(c_, "REPLACE INTO map_bounds (map_id, bounds) VALUES (" + mid + "," + geom_sql(*scene.bounds) + ")");
    report.bounds = true;
  }
  tx.commit();
  return report;
}

Scene SceneStore::load(const std::string& map) {
  // One snapshot for every read below: a concurrent import is seen entirely or not at all.
  execute(c_, "SET TRANSACTION ISOLATION LEVEL REPEATABLE READ, READ ONLY");
  Transaction tx(c_);
  Scene s = read_scene(c_, map_id(map), SceneObjects::Imported);
  tx.commit();
  return s;
}

std::vector<ObjectRow> SceneStore::list(const std::string& map, const ObjectFilter& filter) {
  if (!filter.tag.empty()) require(check_tag(filter.tag));
  const unsigned mid = map_id(map);
  if (filter.centre) {
    if (!(filter.radius >= 0 && std::isfinite(filter.radius)))
      throw std::invalid_argument("expected a finite radius >= 0, got " + n(filter.radius));
    // Whatever lies within the radius meets the square around the circle.
    return rows_for(c_, nearest(c_, candidates_sql(mid, *filter.centre, filter.tag, filter.radius, c_),
                                *filter.centre, std::nullopt, filter.radius));
  }
  mysqlpp::Query q = c_.query();
  q << kRowColumns << " WHERE o.map_id = " << mid << " AND " << kLive;
  if (!filter.tag.empty()) q << " AND o.tag = " << mysqlpp::quote << filter.tag;
  q << " ORDER BY o.object_key";
  std::vector<ObjectRow> out;
  for (const mysqlpp::Row& r : q.store()) out.push_back(object_row(r));
  return out;
}

std::vector<ObjectRow> SceneStore::near(const std::string& map, Point p, const std::string& tag, size_t k,
                                        NearAccess access, NearStats* stats) {
  if (!tag.empty()) require(check_tag(tag));
  return near(map_id(map), p, tag, k, access, stats);
}

std::vector<ObjectRow> SceneStore::near(unsigned mid, Point p, const std::string& tag, size_t k, NearAccess access,
                                        NearStats* stats) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw std::invalid_argument("expected a finite point");
  NearStats local;
  NearStats& st = stats ? *stats : local;
  st = {};
  if (k == 0) return {};
  if (access == NearAccess::FullScan) {
    st.rounds = 1;
    return rows_for(c_, nearest(c_, candidates_sql(mid, p, tag, std::nullopt, c_), p, k, std::nullopt, &st.candidates));
  }
  // Grow the box until it holds k objects and the k-th is no farther than the box's half
  // side: anything nearer meets the disc of that radius, hence the box, so the index
  // search found it. Past the map's border (where objects normally are), one search
  // without a box settles it (fewer than k objects with the tag, or far outside).
  const std::optional<MapInfo> info = MapStore(c_).info(mid);
  if (!info) throw DbError("no map with id " + std::to_string(mid));
  const Rect b = info->border.rect();
  const double reach = std::max({std::abs(p.x - b.xmin), std::abs(p.x - b.xmax), std::abs(p.y - b.ymin),
                                 std::abs(p.y - b.ymax), kFirstBoxHalf});
  std::optional<double> half = kFirstBoxHalf;
  for (;;) {
    ++st.rounds;
    st.box_half = half.value_or(INFINITY);
    auto found = nearest(c_, candidates_sql(mid, p, tag, half, c_), p, k, std::nullopt, &st.candidates);
    if (!half || (found.size() == k && *found.back().distance <= *half)) return rows_for(c_, found);
    if (*half >= reach) half.reset();
    else half = *half * 2;
  }
}

std::string SceneStore::near_index(const std::string& map, Point p, const std::string& tag, double box_half) {
  const unsigned mid = map_id(map);
  mysqlpp::Query q = c_.query("EXPLAIN " + candidates_sql(mid, p, tag, box_half, c_));
  for (const mysqlpp::Row& r : q.store())
    if (std::string(r["table"]) == "e") return r["key"].is_null() ? "" : std::string(r["key"]);
  return "";
}

std::vector<std::string> SceneStore::avoided_areas_containing(const std::string& map, Point p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw std::invalid_argument("expected a finite point");
  const unsigned mid = map_id(map);
  // The index finds the areas whose bounding box holds p; ST_Intersects counts the boundary in.
  mysqlpp::Query q = c_.query();
  q << "SELECT area_key FROM avoided_areas FORCE INDEX (sx_avoided_areas_area) WHERE MBRContains(area, "
    << point_sql(p) << ") AND ST_Intersects(area, " << point_sql(p) << ") AND map_id = " << mid << " ORDER BY area_key";
  std::vector<std::string> out;
  for (const mysqlpp::Row& r : q.store()) out.push_back(sql::to_string(r[0]));
  return out;
}

std::string SceneStore::add_avoided_area(const std::string& map, const std::string& wkt, const std::string& key) {
  const Polygon ring = parse_polygon_wkt(wkt);
  require(check_polygon(ring, "avoided area"));
  if (!key.empty()) require(check_key(key, "avoided-area"));
  Transaction tx(c_);
  const std::string mid = std::to_string(map_id(map, " LOCK IN SHARE MODE"));
  auto exists = [&](const std::string& k) {
    mysqlpp::Query q = c_.query();
    q << "SELECT 1 FROM avoided_areas WHERE map_id = " << mid << " AND area_key = " << mysqlpp::quote << k;
    return !q.store().empty();
  };
  std::string k = key;
  if (k.empty()) {
    long long next = sql::to_int(c_.query("SELECT COUNT(*) + 1 FROM avoided_areas WHERE map_id = " + mid).store()[0][0]);
    while (exists("avoid-" + std::to_string(next))) ++next;
    k = "avoid-" + std::to_string(next);
  } else if (exists(k)) {
    throw SceneKeyExists(map, "an avoided area", k);
  }
  mysqlpp::Query q = c_.query();
  q << "INSERT INTO avoided_areas (map_id, area_key, area) VALUES (" << mid << "," << mysqlpp::quote << k << ","
    << geom_sql(ring) << ")";
  q.execute();
  tx.commit();
  return k;
}

std::vector<AvoidedArea> SceneStore::avoided_areas(const std::string& map) {
  const unsigned mid = map_id(map);
  mysqlpp::Query q = c_.query();
  q << "SELECT area_key, ST_AsBinary(area) FROM avoided_areas WHERE map_id = " << mid << " ORDER BY id";
  std::vector<AvoidedArea> out;
  for (const mysqlpp::Row& r : q.store()) out.push_back({sql::to_string(r[0]), polygon_from_wkb(r[1])});
  return out;
}

bool SceneStore::remove_avoided_area(const std::string& map, const std::string& key) {
  const unsigned mid = map_id(map);
  mysqlpp::Query q = c_.query();
  q << "DELETE FROM avoided_areas WHERE map_id = " << mid << " AND area_key = " << mysqlpp::quote << key;
  return q.execute().rows() > 0;
}

bool SceneStore::remove_object(const std::string& map, const std::string& key) {
  const unsigned mid = map_id(map);
  mysqlpp::Query q = c_.query();
  // object_elements follow by ON DELETE CASCADE (sql/60_semantic.sql).
  q << "DELETE FROM env_objects WHERE map_id = " << mid << " AND object_key = " << mysqlpp::quote << key;
  return q.execute().rows() > 0;
}

std::vector<TagInfo> SceneStore::tags() {
  std::vector<TagInfo> out;
  for (const mysqlpp::Row& r : c_.query("SELECT tag, class, description FROM tags ORDER BY tag").store())
    out.push_back({sql::to_string(r[0]), sql::to_string(r[1]), sql::to_string(r[2])});
  return out;
}

bool SceneStore::set_tag(const std::string& tag, const std::string& tag_class,
                         const std::optional<std::string>& description) {
  require(check_tag(tag));
  require(check_tag_class(tag_class));
  if (description) require(check_description(*description));
  mysqlpp::Query q = c_.query();
  q << "INSERT INTO tags (tag, class, description) VALUES (" << mysqlpp::quote << tag << "," << mysqlpp::quote
    << tag_class << "," << mysqlpp::quote << description.value_or("") << ") ON DUPLICATE KEY UPDATE class = VALUES(class)";
  if (description) q << ", description = VALUES(description)";
  // rows(): 1 inserted, 2 updated, 0 unchanged.
  return q.execute().rows() == 1;
}

Observation SceneStore::record_observation(unsigned map_id, unsigned robot_id, Point p, const std::string& object,
                                           double ttl_s, const std::string& at) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw std::invalid_argument("expected a finite position");
  if (!(ttl_s > 0 && std::isfinite(ttl_s))) throw std::invalid_argument("expected a time to live > 0 s");
  if (object.empty()) throw std::invalid_argument("expected an object name");
  const std::string label = utf8_prefix(object, 255);
  // The robot's name (for the key), the tag, and the sighting's time as the database keeps it.
  mysqlpp::Query q = c_.query();
  q << "SELECT r.db_user, (SELECT tag FROM tags WHERE tag = " << mysqlpp::quote << label << "), ";
  if (at.empty()) q << "SYSDATE(6)";
  else q << "CAST(" << mysqlpp::quote << at << " AS DATETIME(6))";
  q << " FROM robots r WHERE r.id = " << robot_id;
  mysqlpp::StoreQueryResult res = q.store();
  if (res.empty()) throw std::invalid_argument("no robot with id " + std::to_string(robot_id));
  if (res[0][2].is_null()) throw std::invalid_argument("expected a time 'YYYY-MM-DD hh:mm:ss[.ffffff]', got '" + at + "'");
  const std::string robot = sql::to_string(res[0][0]);
  const std::string tag = res[0][1].is_null() ? "unknown" : sql::to_string(res[0][1]);
  const std::string when = "'" + sql::to_string(res[0][2]) + "'";  // digits, '-', ':', '.', ' ' only
  const std::string expires =
      "TIMESTAMPADD(MICROSECOND, " + std::to_string(std::llround(ttl_s * 1e6)) + ", " + when + ")";
  const std::string square = geom_sql(rectangle_footprint(p, kObservedSide, kObservedSide, 0));
  const std::string mid = std::to_string(map_id), rid = std::to_string(robot_id);

  // Seen again: the same robot, the same name, near the footprint it reported last.
  q.reset();
  q << "SELECT o.id, o.object_key, ST_AsBinary(e.footprint) FROM env_objects o JOIN object_elements e ON e.object_id = o.id"
    << " WHERE o.map_id = " << mid << " AND o.robot_id = " << rid << " AND o.label = " << mysqlpp::quote << label
    << " AND o.source = 'observed' AND o.expires_at > " << when;
  const std::vector<ObjectRow> same = nearest(c_, q.str(), p, 1, kSamePlace);
  Observation out;
  if (!same.empty()) {
    out.object_id = same[0].id;
    out.key = same[0].key;
    out.refreshed = true;
    const std::string id = std::to_string(out.object_id);
    execute(c_, "UPDATE env_objects SET seen_at = " + when + ", expires_at = " + expires + " WHERE id = " + id);
    execute(c_, "UPDATE object_elements SET footprint = " + square + " WHERE object_id = " + id);
    return out;
  }
  q.reset();
  q << "INSERT INTO env_objects (map_id, object_key, tag, dynamic, source, robot_id, label, seen_at, expires_at) VALUES ("
    << mid << ", CONCAT('new/', UUID_SHORT()), " << mysqlpp::quote << tag << ", 1, 'observed', " << rid << ", "
    << mysqlpp::quote << label << ", " << when << ", " << expires << ")";
  out.object_id = q.execute().insert_id();
  const std::string id = std::to_string(out.object_id);
  out.key = robot + "/" + utf8_prefix(label, 200) + "/" + id;
  q.reset();
  q << "UPDATE env_objects SET object_key = " << mysqlpp::quote << out.key << " WHERE id = " << id;
  q.execute();
  execute(c_, "INSERT INTO object_elements (object_id, ord, map_id, footprint) VALUES (" + id + ", 0, " + mid + ", " +
                  square + ")");
  return out;
}

size_t SceneStore::expire_observations(const std::string& now) {
  mysqlpp::Query q = c_.query();
  q << "DELETE FROM env_objects WHERE source = 'observed' AND expires_at <= ";
  if (now.empty()) q << "SYSDATE(6)";
  else q << "CAST(" << mysqlpp::quote << now << " AS DATETIME(6))";
  return q.execute().rows();
}

}  // namespace fleetmap
