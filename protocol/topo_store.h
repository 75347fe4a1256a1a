#pragma once
// Topological graphs in the database (SPEC 7): tables topo_graphs, topo_nodes (POINT,
// spatial index) and topo_edges (LINESTRING, spatial index), sql/50_topology.sql. One
// graph per stored map, found by the map's name; deleting the map deletes its graph
// (foreign-key cascade), replacing it keeps the graph unless told otherwise
// (protocol/map_replace.h). Rows carry the map's name too, for the inspector
// views (50_topology.sql says why).
//
//   TopoStore store(conn);
//   store.import("campus", read_topo_json_file("UT_Campus.navigation.json"), file, /*replace=*/true);
//   TopoGraph g = store.load("campus");
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "common/core/error.h"
#include "common/planning/topo_graph.h"

namespace fleetmap {

struct TopoInfo {
  std::string map;
  unsigned map_id = 0;
  size_t nodes = 0, edges = 0;
  std::string source;
  std::string imported_at;
};

class TopoGraphNotFound : public NotFound {
 public:
  explicit TopoGraphNotFound(const std::string& map)
      : NotFound("map '" + map + "' has no topological graph; import one with 'fleetmap topo import'") {}
};

class TopoGraphExists : public NotFound {
 public:
  explicit TopoGraphExists(const std::string& map)
      : NotFound("map '" + map + "' has a topological graph; use --replace to replace it") {}
};

class TopoStore {
 public:
  explicit TopoStore(mysqlpp::Connection& c) : c_(c) {}

  // Stores g as the graph of the stored map `map` in one transaction: afterwards either
  // the whole graph is there or nothing changed. Throws MapNotFound, and TopoGraphExists
  // unless replace.
  void import(const std::string& map, const TopoGraph& g, const std::string& source, bool replace);

  // The graph as imported (nodes and edges in file order). Reads under a shared lock on
  // the graph's row, so a concurrent replace is seen entirely or not at all.
  // Throws MapNotFound, TopoGraphNotFound.
  TopoGraph load(const std::string& map);

  TopoInfo info(const std::string& map);  // throws MapNotFound, TopoGraphNotFound
  std::vector<TopoInfo> list();           // every stored graph, by map name

  // Deletes the map's graph; false when it had none. Throws MapNotFound.
  bool remove(const std::string& map);

 private:
  // The map's id (and its name as stored); throws MapNotFound.
  unsigned map_id(const std::string& map, const char* lock, std::string* stored_name = nullptr);
  mysqlpp::Connection& c_;
};

}  // namespace fleetmap
