#include "protocol/live_scene.h"

#include <cstdint>
#include <cstring>
#include <unordered_map>

#include "protocol/connection.h"
#include "protocol/sql_util.h"
#include "protocol/wkb.h"

namespace fleetmap {
namespace {

constexpr const char* kLive = "(expires_at IS NULL OR expires_at > NOW(6))";  // as protocol/scene_store.cpp

}  // namespace

std::string live_scene_version(mysqlpp::Connection& c, unsigned map_id) {
  const std::string mid = std::to_string(map_id);
  // SUM(UNIX_TIMESTAMP(seen_at)) (exact decimals) moves whenever any object is seen
  // again; MAX(seen_at) would not when an older observation is refreshed.
  mysqlpp::Query q = c.query(
      "SELECT CONCAT_WS('/', COUNT(*), COALESCE(MAX(id), 0), COALESCE(SUM(UNIX_TIMESTAMP(seen_at)), 0),"
      " COALESCE(SUM(expires_at <= NOW(6)), 0),"
      " (SELECT CONCAT_WS('/', COUNT(*), COALESCE(MAX(id), 0)) FROM avoided_areas WHERE map_id = " + mid + "),"
      " COALESCE((SELECT MD5(ST_AsBinary(bounds)) FROM map_bounds WHERE map_id = " + mid + "), '-'))"
      " FROM env_objects WHERE map_id = " + mid);
  const mysqlpp::StoreQueryResult r = q.store();
  return r.empty() ? std::string() : sql::to_string(r[0][0]);
}

Scene read_scene(mysqlpp::Connection& c, unsigned map_id, SceneObjects which) {
  const std::string mid = std::to_string(map_id);
  Scene s;
  mysqlpp::Query q = c.query("SELECT ST_AsBinary(bounds) FROM map_bounds WHERE map_id = " + mid);
  for (const mysqlpp::Row& r : q.store()) s.bounds = polygon_from_wkb(r[0]);

  std::unordered_map<unsigned long long, size_t> index;  // env_objects.id -> position in s.objects
  q.reset();
  q << "SELECT id, object_key, tag, dynamic FROM env_objects WHERE map_id = " << mid << " AND "
    << (which == SceneObjects::Live ? kLive : "source = 'imported'") << " ORDER BY id";
  for (const mysqlpp::Row& r : q.store()) {
    EnvObject o;
    o.id = sql::to_string(r[1]);
    o.tag = sql::to_string(r[2]);
    o.dynamic = sql::to_int(r[3]) != 0;
    index.emplace(sql::to_uint(r[0]), s.objects.size());
    s.objects.push_back(std::move(o));
  }
  if (!s.objects.empty()) {
    q.reset();
    q << "SELECT object_id, ST_AsBinary(footprint), zmin, zmax FROM object_elements WHERE map_id = " << mid
      << " ORDER BY object_id, ord";
    for (const mysqlpp::Row& r : q.store()) {
      auto it = index.find(sql::to_uint(r[0]));
      if (it == index.end()) continue;  // an observation's (or one that expired between the two reads)
      Element e;
      e.footprint = polygon_from_wkb(r[1]);
      if (!r[2].is_null()) e.z = HeightRange{sql::to_double(r[2]), sql::to_double(r[3])};
      s.objects[it->second].elements.push_back(std::move(e));
    }
  }
  q.reset();
  q << "SELECT area_key, ST_AsBinary(area) FROM avoided_areas WHERE map_id = " << mid << " ORDER BY id";
  for (const mysqlpp::Row& r : q.store()) s.avoided.push_back({sql::to_string(r[0]), polygon_from_wkb(r[1])});
  return s;
}

}  // namespace fleetmap
