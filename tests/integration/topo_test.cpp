// Topological graphs (SPEC 7) through the real `fleetmap` program and a real MariaDB:
// import of the AMRL navigation graphs, routes against Floyd–Warshall, export, the
// inspector's views with a spatial query, and the grants.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The navigation file parsed here, independently of common/topo_json.
struct RefEdge {
  int a, b;
  bool stairs;
  double clearance;
};
struct RefGraph {
  std::vector<int> ids;                 // file order
  std::vector<double> x, y;             // indexed by id (ids of the AMRL files are 0..n-1)
  std::vector<RefEdge> edges;
  size_t stairs = 0;
};

RefGraph parse_ref(const std::string& file) {
  std::ifstream in(real_map(file));
  const nlohmann::json j = nlohmann::json::parse(in);
  RefGraph g;
  for (const auto& n : j.at("nodes")) {
    const int id = n.at("id").get<int>();
    g.ids.push_back(id);
    if (g.x.size() <= static_cast<size_t>(id)) g.x.resize(id + 1, NAN), g.y.resize(id + 1, NAN);
    g.x[id] = n.at("loc").at("x").get<double>();
    g.y[id] = n.at("loc").at("y").get<double>();
  }
  for (const auto& e : j.at("edges")) {
    g.edges.push_back({e.at("s0_id").get<int>(), e.at("s1_id").get<int>(), e.at("has_stairs").get<bool>(),
                       e.at("max_clearance").get<double>()});
    g.stairs += g.edges.back().stairs;
  }
  return g;
}

struct Options {
  bool no_stairs = false;
  double radius = 0;
  std::string flags() const {
    std::string s;
    if (no_stairs) s += " --no-stairs";
    if (radius > 0) s += " --radius " + std::to_string(radius);
    return s;
  }
  bool usable(const RefEdge& e) const { return !(no_stairs && e.stairs) && e.clearance >= radius; }
};

double ref_length(const RefGraph& g, int a, int b) { return std::hypot(g.x[a] - g.x[b], g.y[a] - g.y[b]); }

std::vector<std::vector<double>> floyd_warshall(const RefGraph& g, const Options& o) {
  const size_t n = g.x.size();
  std::vector<std::vector<double>> d(n, std::vector<double>(n, kInf));
  for (size_t i = 0; i < n; ++i) d[i][i] = 0;
  for (const RefEdge& e : g.edges)
    if (o.usable(e)) d[e.a][e.b] = d[e.b][e.a] = std::min(d[e.a][e.b], ref_length(g, e.a, e.b));
  for (size_t k = 0; k < n; ++k)
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < n; ++j) d[i][j] = std::min(d[i][j], d[i][k] + d[k][j]);
  return d;
}

const struct RealGraph {
  const char* vectormap;
  const char* navigation;
  const char* name;
} kGdc1{"GDC1.vectormap.txt", "GDC1.navigation.json", "it_topo_gdc1"},
    kCampus{"UT_Campus.vectormap.txt", "UT_Campus.navigation.json", "it_topo_campus"};

long long map_id(const std::string& name) { return scalar("SELECT id FROM maps WHERE name = '" + name + "'"); }

void ensure_map(const RealGraph& g) {
  if (scalar("SELECT COUNT(*) FROM maps WHERE name = '" + std::string(g.name) + "'") > 0) return;
  RunResult r = run("fleetmap", "map import " + real_map(g.vectormap) + " --name " + g.name);
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

void import_graph(const RealGraph& g) {
  ensure_map(g);
  RunResult r = run("fleetmap", "topo import " + std::string(g.name) + " " + real_map(g.navigation) + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

long long rows(const std::string& table, const std::string& map) {
  return scalar("SELECT COUNT(*) FROM " + table + " t JOIN maps m ON m.id = t.map_id WHERE m.name = '" + map + "'");
}

// Everything an import could touch, in one fingerprint.
std::string fingerprint() {
  auto c = admin();
  mysqlpp::Query q = c->query(
      "SELECT (SELECT COUNT(*) FROM topo_graphs), (SELECT COUNT(*) FROM topo_nodes), (SELECT COUNT(*) FROM topo_edges),"
      " (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', map_id, node_id, x, y))), 0) FROM topo_nodes),"
      " (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', map_id, ord, s0_id, s1_id, type))), 0) FROM topo_edges)");
  mysqlpp::StoreQueryResult r = q.store();
  std::string s;
  for (size_t i = 0; i < r.num_fields(); ++i) s += std::string(r[0][i]) + "/";
  return s;
}

struct RouteLine {
  int id;
  double x, y;
  std::string via;
};

// "ID X Y TYPE" lines, then "length L".
bool parse_route(const std::string& out, std::vector<RouteLine>* nodes, double* length) {
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    if (line.rfind("length ", 0) == 0) {
      ls.ignore(7);
      return static_cast<bool>(ls >> *length);
    }
    RouteLine r;
    std::string x, y;
    if (!(ls >> r.id >> x >> y >> r.via)) return false;
    r.x = std::strtod(x.c_str(), nullptr);
    r.y = std::strtod(y.c_str(), nullptr);
    nodes->push_back(r);
  }
  return false;
}

TEST(TopoImport, RealGraphsStoreEveryNodeAndEdge) {
  for (const RealGraph& rg : {kGdc1, kCampus}) {
    SCOPED_TRACE(rg.navigation);
    const RefGraph ref = parse_ref(rg.navigation);
    ensure_map(rg);
    RunResult r = run("fleetmap", "topo import " + std::string(rg.name) + " " + real_map(rg.navigation) + " --replace");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(std::to_string(ref.ids.size()) + " nodes, " + std::to_string(ref.edges.size()) + " edges"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(rows("topo_nodes", rg.name), static_cast<long long>(ref.ids.size()));
    EXPECT_EQ(rows("topo_edges", rg.name), static_cast<long long>(ref.edges.size()));
    const std::string mid = std::to_string(map_id(rg.name));
    EXPECT_EQ(scalar("SELECT nodes FROM topo_graphs WHERE map_id = " + mid), static_cast<long long>(ref.ids.size()));
    EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_edges WHERE type = 'stairs' AND map_id = " + mid),
              static_cast<long long>(ref.stairs));
    // Geometry agrees with the columns: points on their nodes, lines from s0 to s1.
    EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE ST_X(pos) = x AND ST_Y(pos) = y AND map_id = " + mid),
              static_cast<long long>(ref.ids.size()));
    EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_edges e"
                     " JOIN topo_nodes a ON a.map_id = e.map_id AND a.node_id = e.s0_id"
                     " JOIN topo_nodes b ON b.map_id = e.map_id AND b.node_id = e.s1_id"
                     " WHERE ST_StartPoint(e.geom) = a.pos AND ST_EndPoint(e.geom) = b.pos"
                     " AND ABS(e.length - ST_Length(e.geom)) < 1e-9 AND e.map_id = " + mid),
              static_cast<long long>(ref.edges.size()));
    // Every stored position is the file's, exactly.
    auto c = admin();
    mysqlpp::Query q = c->query("SELECT node_id, x, y FROM topo_nodes WHERE map_id = " + mid);
    for (const mysqlpp::Row& row : q.store()) {
      const int id = std::stoi(std::string(row[0]));
      EXPECT_EQ(std::strtod(std::string(row[1]).c_str(), nullptr), ref.x[id]) << "node " << id;
      EXPECT_EQ(std::strtod(std::string(row[2]).c_str(), nullptr), ref.y[id]) << "node " << id;
    }
  }
}

TEST(TopoImport, ExistingGraphNeedsReplaceAndBadInputChangesNothing) {
  import_graph(kGdc1);
  const std::string before = fingerprint();
  RunResult again = run("fleetmap", "topo import " + std::string(kGdc1.name) + " " + real_map(kGdc1.navigation));
  EXPECT_EQ(again.exit_code, 4);
  EXPECT_NE(again.err.find("--replace"), std::string::npos) << again.err;
  EXPECT_EQ(fingerprint(), before);

  // A broken edge deep in an otherwise valid file: refused before any SQL runs.
  nlohmann::json j = nlohmann::json::parse(read_file(real_map(kCampus.navigation)));
  j["edges"][57]["s1_id"] = 999;
  const std::string bad = temp_path("bad.navigation.json");
  write_file(bad, j.dump(4));
  RunResult r = run("fleetmap", "topo import " + std::string(kGdc1.name) + " " + bad + " --replace");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(bad + ": edges[57].s1_id: expected the id of a node, got 999"), std::string::npos) << r.err;
  write_file(bad, "{\"nodes\": [\n  {\"id\": 1, \"loc\": {\"x\": 1, \"y\": }}]}");
  r = run("fleetmap", "topo import " + std::string(kGdc1.name) + " " + bad + " --replace");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(bad + ": line 2, column"), std::string::npos) << r.err;
  EXPECT_EQ(fingerprint(), before);

  // Unknown map, and a name that is not one.
  r = run("fleetmap", "topo import it_topo_nomap " + real_map(kGdc1.navigation));
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("no map named 'it_topo_nomap'"), std::string::npos) << r.err;
  r = run("fleetmap", "topo import \"x'; DROP TABLE topo_nodes; --\" " + real_map(kGdc1.navigation));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(fingerprint(), before);

  // --replace leaves nothing of the old graph behind.
  r = run("fleetmap", "topo import " + std::string(kGdc1.name) + " " + real_map(kCampus.navigation) + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("nodes lie outside the border"), std::string::npos) << r.err;  // campus on GDC1
  EXPECT_EQ(rows("topo_nodes", kGdc1.name), 102);
  EXPECT_EQ(rows("topo_edges", kGdc1.name), 114);
  import_graph(kGdc1);
  EXPECT_EQ(fingerprint(), before);
}

TEST(TopoRoute, RandomPairsAreAsShortAsFloydWarshall) {
  import_graph(kCampus);
  const RefGraph ref = parse_ref(kCampus.navigation);
  const Options options[] = {{}, {.no_stairs = true}, {.no_stairs = true, .radius = 1.5}};
  std::vector<std::vector<double>> d[3];
  for (int k = 0; k < 3; ++k) d[k] = floyd_warshall(ref, options[k]);

  std::mt19937 rng(7);
  size_t found = 0, none = 0;
  for (int pair = 0; pair < 200; ++pair) {
    const int from = ref.ids[rng() % ref.ids.size()], to = ref.ids[rng() % ref.ids.size()];
    const Options& o = options[pair % 3];
    const double best = d[pair % 3][from][to];
    SCOPED_TRACE("pair " + std::to_string(pair) + ": " + std::to_string(from) + " -> " + std::to_string(to) + o.flags());
    RunResult r = run("fleetmap", "topo route " + std::string(kCampus.name) + " " + std::to_string(from) + " " +
                                      std::to_string(to) + o.flags());
    if (std::isinf(best)) {
      EXPECT_EQ(r.exit_code, 3) << r.err;
      EXPECT_NE(r.err.find("no route from " + std::to_string(from) + " to " + std::to_string(to)), std::string::npos)
          << r.err;
      EXPECT_EQ(r.out, "");
      ++none;
      continue;
    }
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::vector<RouteLine> nodes;
    double length = -1;
    ASSERT_TRUE(parse_route(r.out, &nodes, &length)) << r.out;
    ASSERT_FALSE(nodes.empty());
    EXPECT_EQ(nodes.front().id, from);
    EXPECT_EQ(nodes.back().id, to);
    EXPECT_NEAR(length, best, 0.0005 + 1e-9 * best);  // printed to the millimetre
    // The printed route is a walk on usable edges, as long as the shortest one.
    double walked = 0;
    for (size_t i = 0; i < nodes.size(); ++i) {
      EXPECT_EQ(nodes[i].x, ref.x[nodes[i].id]);
      EXPECT_EQ(nodes[i].y, ref.y[nodes[i].id]);
      if (i == 0) continue;
      const int a = nodes[i - 1].id, b = nodes[i].id;
      bool joined = false;
      for (const RefEdge& e : ref.edges)
        joined = joined || (o.usable(e) && ((e.a == a && e.b == b) || (e.a == b && e.b == a)));
      EXPECT_TRUE(joined) << a << " - " << b;
      walked += ref_length(ref, a, b);
    }
    EXPECT_NEAR(walked, best, 1e-9 * (1 + best));
    ++found;
  }
  std::printf("[   INFO   ] 200 pairs: %zu routes, %zu without a route (exit 3)\n", found, none);
  EXPECT_GT(found, 50u);
  EXPECT_GT(none, 10u);
}

TEST(TopoRoute, UnknownThingsAreExit4AndNoRouteIsExit3) {
  import_graph(kCampus);
  const std::string campus = kCampus.name;
  RunResult r = run("fleetmap", "topo route it_topo_nomap 1 2");
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("no map named"), std::string::npos) << r.err;

  // A map without a graph.
  ASSERT_EQ(run("fleetmap", "map import " + source_path("maps/example-campus.map") + " --name it_topo_nograph --replace")
                .exit_code,
            0);
  r = run("fleetmap", "topo route it_topo_nograph 1 2");
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("has no topological graph"), std::string::npos) << r.err;
  EXPECT_EQ(run("fleetmap", "topo export it_topo_nograph").exit_code, 4);

  r = run("fleetmap", "topo route " + campus + " 3 5000");
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("no node with id 5000"), std::string::npos) << r.err;
  EXPECT_EQ(run("fleetmap", "topo route " + campus + " abc 3").exit_code, 2);
  EXPECT_EQ(run("fleetmap", "topo route " + campus + " 1 2 --radius -1").exit_code, 64);

  // Two nodes in different components of the campus graph.
  const RefGraph ref = parse_ref(kCampus.navigation);
  const auto d = floyd_warshall(ref, {});
  int a = -1, b = -1;
  for (int i : ref.ids)
    for (int k : ref.ids)
      if (a < 0 && std::isinf(d[i][k])) a = i, b = k;
  ASSERT_GE(a, 0);
  r = run("fleetmap", "topo route " + campus + " " + std::to_string(a) + " " + std::to_string(b));
  EXPECT_EQ(r.exit_code, 3) << r.err;

  // The same node; and ends given as points snap to the nearest node.
  r = run("fleetmap", "topo route " + campus + " 7 7");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<RouteLine> nodes;
  double length = -1;
  ASSERT_TRUE(parse_route(r.out, &nodes, &length)) << r.out;
  ASSERT_EQ(nodes.size(), 1u);
  EXPECT_EQ(length, 0);
  char point[64];
  std::snprintf(point, sizeof point, "%.3f,%.3f", ref.x[12] + 0.2, ref.y[12] - 0.1);
  r = run("fleetmap", "topo route " + campus + " " + point + " 13");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.substr(0, 3), "12 ") << r.out;
  EXPECT_NE(r.err.find("nearest node 12"), std::string::npos) << r.err;
}

TEST(TopoExport, JsonIsTheImportedFileAndGeoJsonHasEveryFeature) {
  for (const RealGraph& rg : {kGdc1, kCampus}) {
    SCOPED_TRACE(rg.navigation);
    import_graph(rg);
    RunResult r = run("fleetmap", "topo export " + std::string(rg.name));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, read_file(real_map(rg.navigation)));  // byte for byte

    const std::string out = temp_path("topo.geojson");
    r = run("fleetmap", "topo export " + std::string(rg.name) + " --format geojson --crs map -o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(read_file(out));
    const RefGraph ref = parse_ref(rg.navigation);
    size_t points = 0, lines = 0;
    for (const auto& f : j.at("features")) {
      points += f["geometry"]["type"] == "Point";
      lines += f["geometry"]["type"] == "LineString";
    }
    EXPECT_EQ(points, ref.ids.size());
    EXPECT_EQ(lines, ref.edges.size());
  }
}

TEST(TopoInspector, ViewsAnswerSpatialQueriesAndGrantsHold) {
  import_graph(kCampus);
  const RefGraph ref = parse_ref(kCampus.navigation);
  // A window over part of the campus, edges chosen off the node coordinates.
  const double x0 = -50.25, y0 = -200.25, x1 = 60.75, y1 = -20.75;
  const std::string poly = "ST_GeomFromText('POLYGON((" + std::to_string(x0) + " " + std::to_string(y0) + "," +
                           std::to_string(x1) + " " + std::to_string(y0) + "," + std::to_string(x1) + " " +
                           std::to_string(y1) + "," + std::to_string(x0) + " " + std::to_string(y1) + "," +
                           std::to_string(x0) + " " + std::to_string(y0) + "))')";
  long long inside = 0, crossing = 0;
  for (int id : ref.ids) inside += ref.x[id] > x0 && ref.x[id] < x1 && ref.y[id] > y0 && ref.y[id] < y1;
  for (const RefEdge& e : ref.edges) {  // bounding boxes that meet the window (MBRIntersects)
    const double ex0 = std::min(ref.x[e.a], ref.x[e.b]), ex1 = std::max(ref.x[e.a], ref.x[e.b]);
    const double ey0 = std::min(ref.y[e.a], ref.y[e.b]), ey1 = std::max(ref.y[e.a], ref.y[e.b]);
    crossing += ex0 <= x1 && ex1 >= x0 && ey0 <= y1 && ey1 >= y0;
  }
  ASSERT_GT(inside, 5);
  ASSERT_LT(inside, static_cast<long long>(ref.ids.size()));

  auto inspector = connect_as(Role::Inspector);
  auto count = [&](mysqlpp::Connection& c, const std::string& sql) {
    mysqlpp::Query q = c.query(sql);
    return std::stoll(std::string(q.store()[0][0]));
  };
  EXPECT_EQ(count(*inspector, "SELECT COUNT(*) FROM v_topo_nodes WHERE map = 'it_topo_campus' AND MBRContains(" +
                                  poly + ", pos)"),
            inside);
  EXPECT_EQ(count(*inspector, "SELECT COUNT(*) FROM v_topo_edges WHERE map = 'it_topo_campus' AND MBRIntersects(geom, " +
                                  poly + ")"),
            crossing);
  EXPECT_EQ(count(*inspector, "SELECT COUNT(*) FROM v_topo_edges WHERE map = 'it_topo_campus' AND type = 'stairs'"),
            static_cast<long long>(ref.stairs));
  // The spatial index is there for the window query to use.
  auto a = admin();
  mysqlpp::Query explain =
      a->query("EXPLAIN SELECT node_id FROM topo_nodes FORCE INDEX (sx_topo_nodes_pos) WHERE MBRContains(" + poly +
               ", pos)");
  EXPECT_EQ(std::string(explain.store()[0]["key"]), "sx_topo_nodes_pos");

  // Inspector: the views only, read only.
  for (const std::string& sql :
       {std::string("SELECT COUNT(*) FROM topo_nodes"), std::string("SELECT COUNT(*) FROM topo_edges"),
        std::string("DELETE FROM v_topo_nodes"), std::string("UPDATE v_topo_edges SET length = 0")}) {
    SCOPED_TRACE(sql);
    mysqlpp::Query q = inspector->query(sql);
    EXPECT_THROW(q.store(), mysqlpp::BadQuery);
  }
  // Server: reads the tables, writes none.
  auto server = connect_as(Role::Server);
  EXPECT_EQ(count(*server, "SELECT COUNT(*) FROM topo_nodes n JOIN maps m ON m.id = n.map_id"
                           " WHERE m.name = 'it_topo_campus'"),
            static_cast<long long>(ref.ids.size()));
  mysqlpp::Query del = server->query("DELETE FROM topo_edges");
  EXPECT_THROW(del.execute(), mysqlpp::BadQuery);
}

TEST(TopoImport, GraphGoesWithItsMap) {
  const RealGraph rg{"GDC1.vectormap.txt", "GDC1.navigation.json", "it_topo_cascade"};
  import_graph(rg);
  const std::string mid = std::to_string(map_id(rg.name));
  ASSERT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map_id = " + mid), 9);

  // topo delete: the graph goes, the map stays.
  ASSERT_EQ(run("fleetmap", "topo delete " + std::string(rg.name)).exit_code, 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map_id = " + mid), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_edges WHERE map_id = " + mid), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM maps WHERE id = " + mid), 1);
  EXPECT_EQ(run("fleetmap", "topo delete " + std::string(rg.name)).exit_code, 4);

  // map import --replace keeps the graph (the map keeps its row) unless told to drop it;
  // map delete takes it along (the cascade of 50_topology.sql).
  import_graph(rg);
  ASSERT_EQ(run("fleetmap", "map import " + real_map(rg.vectormap) + " --name " + rg.name + " --replace").exit_code, 0);
  EXPECT_EQ(std::to_string(map_id(rg.name)), mid);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map_id = " + mid), 9);
  EXPECT_EQ(run("fleetmap", "topo route " + std::string(rg.name) + " 0 1").exit_code, 0);
  ASSERT_EQ(run("fleetmap", "map import " + real_map(rg.vectormap) + " --name " + rg.name + " --replace --drop topology")
                .exit_code,
            0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map_id = " + mid), 0);
  EXPECT_EQ(run("fleetmap", "topo route " + std::string(rg.name) + " 0 1").exit_code, 4);
  import_graph(rg);
  const std::string mid2 = std::to_string(map_id(rg.name));
  ASSERT_EQ(run("fleetmap", "map delete " + std::string(rg.name)).exit_code, 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_graphs WHERE map_id = " + mid2), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map_id = " + mid2), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_edges WHERE map_id = " + mid2), 0);
}

TEST(TopoCheck, ValidatesWithoutTheDatabase) {
  RunResult ok = run("fleetmap", "--host 192.0.2.1 topo check " + real_map(kCampus.navigation));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("102 nodes, 114 edges (corridor 106, stairs 8), 9 connected components"), std::string::npos)
      << ok.out;
  write_file(temp_path("check.json"), R"({"nodes": [{"id": 0, "loc": {"x": 0, "y": 0}}], "edges": [{"s0_id": 0}]})");
  RunResult bad = run("fleetmap", "--host 192.0.2.1 topo check " + temp_path("check.json"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("check.json: edges[0].s1_id: expected a value, the member is missing"), std::string::npos)
      << bad.err;
}

}  // namespace
}  // namespace fleetmap::test
