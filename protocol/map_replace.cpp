#include "protocol/map_replace.h"

#include <memory>

#include "common/geometry/number_format.h"
#include "common/map/map_placement.h"
#include "protocol/live_scene.h"
#include "protocol/sql_util.h"

namespace fleetmap {
namespace {

constexpr size_t kListed = 20;  // stranded dependents named in a refusal; the rest counted

std::string pt(double x, double y) { return "(" + format_number(x) + ", " + format_number(y) + ")"; }

std::string plural(size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

size_t count(mysqlpp::Connection& c, const std::string& sql) {
  mysqlpp::StoreQueryResult r = c.query(sql).store();
  return r.empty() ? 0 : static_cast<size_t>(sql::to_uint(r[0][0]));
}

// Finds what the new map strands: misplaced on next, well placed on the old map (loaded
// once, when first needed).
class StrandCheck {
 public:
  StrandCheck(const Map& next, const std::function<Map()>& old_map) : next_(next), old_map_(old_map) {}

  void point(const std::string& what, double x, double y) {
    if (auto why = next_.point_problem({x, y}); why && !old().point_problem({x, y}))
      out.push_back({what + " " + pt(x, y), *why});
  }
  void polygon(const std::string& what, const Polygon& ring, bool solid_inside) {
    if (auto why = next_.polygon_problem(ring, solid_inside); why && !old().polygon_problem(ring, solid_inside))
      out.push_back({what, *why});
  }

  std::vector<StrandedDependent> out;

 private:
  const MapPlacement& old() {
    if (!old_) old_ = std::make_unique<MapPlacement>(old_map_());
    return *old_;
  }
  MapPlacement next_;
  const std::function<Map()>& old_map_;
  std::unique_ptr<MapPlacement> old_;
};

}  // namespace

MapDrop parse_map_drop(const std::vector<std::string>& words) {
  MapDrop d;
  for (const std::string& w : words) {
    if (w == "all") d = MapDrop::all();
    else if (w == "objects") d.objects = true;
    else if (w == "areas") d.areas = true;
    else if (w == "bounds") d.bounds = true;
    else if (w == "topology") d.topology = true;
    else if (w == "georef") d.georef = true;
    else throw BadInput("--drop: expected objects, areas, bounds, topology, georef or all, got '" + w + "'");
  }
  return d;
}

std::vector<std::string> describe(const MapDependents& d) {
  std::vector<std::string> out;
  if (d.robots) out.push_back(plural(d.robots, "robot", "robots") + " (stay assigned)");
  if (d.open_tasks) out.push_back(plural(d.open_tasks, "open task", "open tasks"));
  if (d.objects) out.push_back(plural(d.objects, "object", "objects"));
  if (d.areas) out.push_back(plural(d.areas, "avoided area", "avoided areas"));
  if (d.bounds) out.push_back("bounds");
  if (d.topology)
    out.push_back("topology (" + plural(d.topo_nodes, "node", "nodes") + ", " + plural(d.topo_edges, "edge", "edges") +
                  ")");
  if (d.georef) out.push_back("georeference (" + d.georef->substr(0, 60) + (d.georef->size() > 60 ? "..." : "") + ")");
  return out;
}

namespace {

std::string strand_message(const std::string& name, const std::vector<StrandedDependent>& s) {
  std::string m = "replacing map '" + name + "' would strand " + plural(s.size(), "dependent", "dependents") +
                  " (misplaced on the new map, not on the old one):";
  for (size_t i = 0; i < s.size() && i < kListed; ++i) m += "\n  " + s[i].text();
  if (s.size() > kListed) m += "\n  ... and " + std::to_string(s.size() - kListed) + " more";
  return m + "\nmove or remove them, drop them with --drop, or replace anyway with --force";
}

}  // namespace

MapWouldStrand::MapWouldStrand(const std::string& name, std::vector<StrandedDependent> stranded)
    : NotFound(strand_message(name, stranded)), stranded_(std::move(stranded)) {}

MapReplaceReport prepare_replace(mysqlpp::Connection& c, unsigned map_id, const std::string& name, const Map& next,
                                 const MapDrop& drop, bool force, const std::function<Map()>& old_map) {
  const std::string mid = std::to_string(map_id);
  MapDependents all;
  StrandCheck check(next, old_map);

  // Robots and their open tasks: always kept.
  mysqlpp::Query q = c.query();
  q << "SELECT db_user, x, y, ini_x, ini_y FROM robots WHERE map_id = " << mid << " AND removed_at IS NULL ORDER BY id";
  for (const mysqlpp::Row& r : q.store()) {
    ++all.robots;
    const std::string robot = "robot " + sql::to_string(r[0]);
    if (!r[1].is_null() && !r[2].is_null()) check.point(robot + ": last pose", sql::to_double(r[1]), sql::to_double(r[2]));
    if (!r[3].is_null() && !r[4].is_null())
      check.point(robot + ": initial pose", sql::to_double(r[3]), sql::to_double(r[4]));
  }
  q.reset();
  q << "SELECT t.id, r.db_user, t.goal_x, t.goal_y FROM tasks t JOIN robots r ON r.id = t.robot_id WHERE r.map_id = "
    << mid << " AND r.removed_at IS NULL AND t.state IN " << sql::open_task_states() << " ORDER BY t.id";
  for (const mysqlpp::Row& r : q.store()) {
    ++all.open_tasks;
    check.point("task " + sql::to_string(r[0]) + " of robot " + sql::to_string(r[1]) + ": goal",
                sql::to_double(r[2]), sql::to_double(r[3]));
  }

  // The semantic layer: live objects, avoided areas, bounds.
  all.objects = count(c, "SELECT COUNT(*) FROM env_objects WHERE map_id = " + mid);
  all.areas = count(c, "SELECT COUNT(*) FROM avoided_areas WHERE map_id = " + mid);
  all.bounds = count(c, "SELECT COUNT(*) FROM map_bounds WHERE map_id = " + mid) > 0;
  if ((all.objects && !drop.objects) || (all.areas && !drop.areas) || (all.bounds && !drop.bounds)) {
    const Scene scene = read_scene(c, map_id, SceneObjects::Live);
    if (!drop.objects)
      for (const EnvObject& o : scene.objects)
        for (size_t i = 0; i < o.elements.size(); ++i) {
          const std::string what = "object " + o.id + (o.elements.size() > 1 ? " element " + std::to_string(i + 1) : "");
          const size_t before = check.out.size();
          check.polygon(what, o.elements[i].footprint, true);
          if (check.out.size() > before) break;  // one line per object
        }
    if (!drop.areas)
      for (const AvoidedArea& a : scene.avoided) check.polygon("avoided area " + a.id, a.area, false);
    if (!drop.bounds && scene.bounds) check.polygon("bounds", *scene.bounds, false);
  }

  // The topological graph.
  q.reset();
  q << "SELECT nodes, edges FROM topo_graphs WHERE map_id = " << mid;
  for (const mysqlpp::Row& r : q.store()) {
    all.topology = true;
    all.topo_nodes = static_cast<size_t>(sql::to_uint(r[0]));
    all.topo_edges = static_cast<size_t>(sql::to_uint(r[1]));
  }
  if (all.topology && !drop.topology) {
    q.reset();
    q << "SELECT node_id, name, x, y FROM topo_nodes WHERE map_id = " << mid << " ORDER BY ord";
    for (const mysqlpp::Row& r : q.store())
      check.point("topology node " + sql::to_string(r[0]) + (r[1].is_null() ? "" : " '" + sql::to_string(r[1]) + "'"),
                  sql::to_double(r[2]), sql::to_double(r[3]));
  }

  q.reset();
  q << "SELECT geo_crs FROM maps WHERE id = " << mid;
  for (const mysqlpp::Row& r : q.store())
    if (!r[0].is_null()) all.georef = sql::to_string(r[0]);

  if (!check.out.empty() && !force) throw MapWouldStrand(name, std::move(check.out));

  // Nothing refused: split into kept and dropped, and drop.
  MapReplaceReport rep;
  rep.stranded = std::move(check.out);
  rep.kept.robots = all.robots;
  rep.kept.open_tasks = all.open_tasks;
  (drop.objects ? rep.dropped : rep.kept).objects = all.objects;
  (drop.areas ? rep.dropped : rep.kept).areas = all.areas;
  (drop.bounds ? rep.dropped : rep.kept).bounds = all.bounds;
  MapDependents& topo = drop.topology ? rep.dropped : rep.kept;
  topo.topology = all.topology;
  topo.topo_nodes = all.topo_nodes;
  topo.topo_edges = all.topo_edges;
  (drop.georef ? rep.dropped : rep.kept).georef = all.georef;

  // Children first: one statement each instead of a cascade row by row.
  if (drop.objects && all.objects) {
    execute(c, "DELETE FROM object_elements WHERE map_id = " + mid);
    execute(c, "DELETE FROM env_objects WHERE map_id = " + mid);
  }
  if (drop.areas && all.areas) execute(c, "DELETE FROM avoided_areas WHERE map_id = " + mid);
  if (drop.bounds && all.bounds) execute(c, "DELETE FROM map_bounds WHERE map_id = " + mid);
  if (drop.topology && all.topology) {
    execute(c, "DELETE FROM topo_edges WHERE map_id = " + mid);
    execute(c, "DELETE FROM topo_nodes WHERE map_id = " + mid);
    execute(c, "DELETE FROM topo_graphs WHERE map_id = " + mid);
  }
  if (drop.georef && all.georef) {
    execute(c, "UPDATE maps SET geo_crs = NULL, geo_tx = NULL, geo_ty = NULL, geo_rotation = NULL, geo_scale = NULL"
               " WHERE id = " + mid);
    execute(c, "DELETE FROM georef_control_points WHERE map_id = " + mid);
  }
  return rep;
}

}  // namespace fleetmap
