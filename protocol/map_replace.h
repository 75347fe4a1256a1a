#pragma once
// What replacing a stored map (`map import --replace`, MapStore::import) does to what
// depends on it. The maps row keeps its id, so every row that names the map stays its
// own: robots stay assigned (robots.map_id), and its objects (env_objects,
// object_elements), avoided areas, bounds (sql/60_semantic.sql), topological graph
// (sql/50_topology.sql) and georeference (maps.geo_*) stay unless dropped (MapDrop).
//
// A kept dependent is stranded by the new map when it lies well on the old map and not on
// the new one (common/map/map_placement.h: outside the border, or inside a solid obstacle):
//   robot          its last pose or its initial pose (robots on the map, not removed)
//   task           the goal of such a robot's open task (assigned, acknowledged, active)
//   object         a footprint with a vertex outside the border, or buried in a solid
//                  obstacle (live objects: imported ones, observations not expired)
//   avoided area   a vertex outside the border
//   bounds         a vertex outside the border
//   topology node  its position
// Whatever was misplaced on the old map already is not the replace's doing. A replace
// that strands anything is refused (MapWouldStrand; nothing changes) unless forced.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "common/core/error.h"
#include "common/map/map.h"

namespace fleetmap {

// What a replace deletes with the old map (--drop objects,areas,... or --drop all).
// Robots are never dropped: they are unassigned with `robot set` or removed.
struct MapDrop {
  bool objects = false, areas = false, bounds = false, topology = false, georef = false;
  static MapDrop all() { return {true, true, true, true, true}; }
  bool any() const { return objects || areas || bounds || topology || georef; }
  friend bool operator==(const MapDrop&, const MapDrop&) = default;
};

// The words of a --drop list, in the order the help shows them.
inline constexpr const char* kMapDropWords[] = {"objects", "areas", "bounds", "topology", "georef", "all"};

// Throws BadInput naming a word that is none of kMapDropWords.
MapDrop parse_map_drop(const std::vector<std::string>& words);

// A map's dependents, counted.
struct MapDependents {
  size_t robots = 0;      // on the map, not removed
  size_t open_tasks = 0;  // of those robots
  size_t objects = 0;     // env_objects rows (imported and observed)
  size_t areas = 0;
  bool bounds = false;
  bool topology = false;  // a graph, of topo_nodes nodes and topo_edges edges
  size_t topo_nodes = 0, topo_edges = 0;
  std::optional<std::string> georef;  // its base CRS
};

// One line per kind present: "2 robots (stay assigned)", "17 objects", "topology (12
// nodes, 15 edges)", "georeference (EPSG:26910)"; empty when there is nothing.
std::vector<std::string> describe(const MapDependents& d);

struct StrandedDependent {
  std::string what;  // "robot r1: last pose (3, 4)", "object chair-1", "topology node 4"
  std::string why;   // "outside the border (0, 20)-(20, 0)", "inside obstacle 7 'wall'"
  std::string text() const { return what + ": " + why; }
};

struct MapReplaceReport {
  MapDependents kept, dropped;
  bool georef_replaced = false;             // the import brought its own georeference (stored)
  std::vector<StrandedDependent> stranded;  // kept anyway (forced)
};

// A replace refused because it would strand dependents (exit 4, like MapExists: the
// stored state is in the way, and a flag says to go ahead).
class MapWouldStrand : public NotFound {
 public:
  MapWouldStrand(const std::string& name, std::vector<StrandedDependent> stranded);
  const std::vector<StrandedDependent>& stranded() const { return stranded_; }

 private:
  std::vector<StrandedDependent> stranded_;
};

// In the caller's transaction, for the stored map map_id (its maps row locked by the
// caller) that `next` is about to replace: counts its dependents, finds those next
// strands (old_map gives the stored map, called only when something is misplaced on
// next), then deletes what drop says (the georeference: maps.geo_* set NULL). Throws
// MapWouldStrand before changing anything unless force.
MapReplaceReport prepare_replace(mysqlpp::Connection& c, unsigned map_id, const std::string& name, const Map& next,
                                 const MapDrop& drop, bool force, const std::function<Map()>& old_map);

}  // namespace fleetmap
