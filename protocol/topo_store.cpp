#include "protocol/topo_store.h"

#include <cmath>
#include <limits>

#include "common/geometry/number_format.h"
#include "protocol/batch_insert.h"
#include "protocol/connection.h"
#include "protocol/map_store.h"
#include "protocol/sql_util.h"

namespace fleetmap {
namespace {


std::string n(double v) { return format_number(v); }

// Infinity is "no limit" in the model and NULL in the table.
std::string limit(double v) { return std::isfinite(v) ? n(v) : "NULL"; }
double limit(const mysqlpp::String& s) {
  return s.is_null() ? std::numeric_limits<double>::infinity() : sql::to_double(s);
}

constexpr const char* kInfoSql =
    "SELECT m.name, g.map_id, g.nodes, g.edges, g.source, g.imported_at FROM topo_graphs g "
    "JOIN maps m ON m.id = g.map_id";

TopoInfo info_from_row(const mysqlpp::Row& r) {
  TopoInfo i;
  i.map = sql::to_string(r[0]);
  i.map_id = static_cast<unsigned>(sql::to_uint(r[1]));
  i.nodes = static_cast<size_t>(sql::to_uint(r[2]));
  i.edges = static_cast<size_t>(sql::to_uint(r[3]));
  i.source = sql::to_string(r[4]);
  i.imported_at = sql::to_string(r[5]);
  return i;
}


}  // namespace

unsigned TopoStore::map_id(const std::string& map, const char* lock, std::string* stored_name) {
  mysqlpp::Query q = c_.query();
  q << "SELECT id, name FROM maps WHERE name = " << mysqlpp::quote << map << lock;
  mysqlpp::StoreQueryResult res = q.store();
  if (res.empty()) throw MapNotFound(map);
  if (stored_name) *stored_name = sql::to_string(res[0][1]);
  return static_cast<unsigned>(sql::to_uint(res[0][0]));
}

void TopoStore::import(const std::string& map, const TopoGraph& g, const std::string& source, bool replace) {
  if (auto e = check_map_name(map)) throw std::invalid_argument(*e);
  Transaction tx(c_);
  // A shared lock on the map: it cannot be deleted or replaced under us.
  std::string stored_name;  // as in maps.name (the lookup ignores case)
  const std::string mid = std::to_string(map_id(map, " LOCK IN SHARE MODE", &stored_name));
  mysqlpp::Query q = c_.query();
  q << "SELECT map_id FROM topo_graphs WHERE map_id = " << mid << " FOR UPDATE";
  if (!q.store().empty()) {
    if (!replace) throw TopoGraphExists(map);
    // Children first: one statement each instead of a cascade row by row.
    execute(c_, "DELETE FROM topo_edges WHERE map_id = " + mid);
    execute(c_, "DELETE FROM topo_nodes WHERE map_id = " + mid);
    execute(c_, "DELETE FROM topo_graphs WHERE map_id = " + mid);
  }
  q.reset();
  q << "INSERT INTO topo_graphs (map_id, source, nodes, edges) VALUES (" << mid << ", " << mysqlpp::quote
    << source.substr(0, 255) << ", " << g.nodes().size() << ", " << g.edges().size() << ")";
  q.execute();

  BatchInsert nodes(c_, "INSERT INTO topo_nodes (map_id, map, node_id, ord, name, x, y, pos) VALUES ");
  for (size_t k = 0; k < g.nodes().size(); ++k) {
    const TopoNode& node = g.nodes()[k];
    mysqlpp::Query& r = nodes.row();
    r << "(" << mid << "," << mysqlpp::quote << stored_name << "," << node.id << "," << k << ",";
    if (node.name.empty()) r << "NULL";
    else r << mysqlpp::quote << node.name;
    r << "," << n(node.pos.x) << "," << n(node.pos.y) << ",Point(" << n(node.pos.x) << "," << n(node.pos.y) << "))";
    nodes.end_row();
  }
  nodes.flush();

  BatchInsert edges(c_,
                    "INSERT INTO topo_edges (map_id, map, ord, s0_id, s1_id, type, has_door, has_automated_door, "
                    "max_clearance, max_speed, length, geom) VALUES ");
  for (size_t k = 0; k < g.edges().size(); ++k) {
    const TopoEdge& e = g.edges()[k];
    const Point a = g.node(e.a).pos, b = g.node(e.b).pos;
    edges.row() << "(" << mid << "," << mysqlpp::quote << stored_name << "," << k << "," << e.a << "," << e.b << ",'" << to_string(e.type) << "',"
                << int(e.door) << "," << int(e.automated_door) << "," << limit(e.max_clearance) << ","
                << limit(e.max_speed) << "," << n(g.length(k)) << ",LineString(Point(" << n(a.x) << "," << n(a.y)
                << "),Point(" << n(b.x) << "," << n(b.y) << ")))";
    edges.end_row();
  }
  edges.flush();
  tx.commit();
}

TopoGraph TopoStore::load(const std::string& map) {
  Transaction tx(c_);
  const std::string mid = std::to_string(map_id(map, ""));
  mysqlpp::Query q = c_.query();
  q << "SELECT map_id FROM topo_graphs WHERE map_id = " << mid << " LOCK IN SHARE MODE";
  if (q.store().empty()) throw TopoGraphNotFound(map);

  TopoGraph g;
  try {
    q.reset();
    q << "SELECT node_id, name, x, y FROM topo_nodes WHERE map_id = " << mid << " ORDER BY ord";
    for (const mysqlpp::Row& r : q.store()) {
      TopoNode node;
      node.id = static_cast<int>(sql::to_int(r[0]));
      if (!r[1].is_null()) node.name = sql::to_string(r[1]);
      node.pos = {sql::to_double(r[2]), sql::to_double(r[3])};
      g.add_node(std::move(node));
    }
    q.reset();
    q << "SELECT s0_id, s1_id, type, has_door, has_automated_door, max_clearance, max_speed FROM topo_edges "
         "WHERE map_id = "
      << mid << " ORDER BY ord";
    for (const mysqlpp::Row& r : q.store()) {
      TopoEdge e;
      e.a = static_cast<int>(sql::to_int(r[0]));
      e.b = static_cast<int>(sql::to_int(r[1]));
      const auto type = edge_type_from_string(sql::to_string(r[2]));
      if (!type) throw DbError("unexpected edge type from the database: '" + sql::to_string(r[2]) + "'");
      e.type = *type;
      e.door = sql::to_int(r[3]) != 0;
      e.automated_door = sql::to_int(r[4]) != 0;
      e.max_clearance = limit(r[5]);
      e.max_speed = limit(r[6]);
      g.add_edge(std::move(e));
    }
  } catch (const TopoGraphError& e) {
    throw DbError("the stored graph of map '" + map + "' is inconsistent: " + e.what());
  }
  tx.commit();
  return g;
}

TopoInfo TopoStore::info(const std::string& map) {
  map_id(map, "");  // MapNotFound before TopoGraphNotFound
  mysqlpp::Query q = c_.query();
  q << kInfoSql << " WHERE m.name = " << mysqlpp::quote << map;
  mysqlpp::StoreQueryResult res = q.store();
  if (res.empty()) throw TopoGraphNotFound(map);
  return info_from_row(res[0]);
}

std::vector<TopoInfo> TopoStore::list() {
  mysqlpp::Query q = c_.query();
  q << kInfoSql << " ORDER BY m.name";
  std::vector<TopoInfo> out;
  for (const mysqlpp::Row& r : q.store()) out.push_back(info_from_row(r));
  return out;
}

bool TopoStore::remove(const std::string& map) {
  Transaction tx(c_);
  const std::string mid = std::to_string(map_id(map, " LOCK IN SHARE MODE"));
  execute(c_, "DELETE FROM topo_edges WHERE map_id = " + mid);
  execute(c_, "DELETE FROM topo_nodes WHERE map_id = " + mid);
  mysqlpp::Query q = c_.query();
  q << "DELETE FROM topo_graphs WHERE map_id = " << mid;
  const bool had = q.execute().rows() > 0;
  tx.commit();
  return had;
}

}  // namespace fleetmap
