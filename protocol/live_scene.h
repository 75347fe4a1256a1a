#pragma once
// The scene the server serves robots (seed 002): a map's imported objects plus the robots'
// observations that have not expired, its avoided areas and bounds. SceneStore::load
// reads what an import wrote (observations left out) in a transaction of its own; these
// read with plain SELECTs in the caller's transaction (the server's batch), so they can
// run between a batch's claim and its COMMIT.
//
//   std::string v = live_scene_version(conn, map_id);   // cheap: changes with the scene
//   Scene s = load_live_scene(conn, map_id);
#include <string>

#include <mysql++/mysql++.h>

#include "common/scene/scene.h"

namespace fleetmap {

// A text that changes whenever what load_live_scene returns may have changed: an object
// added or deleted (import, --replace, SetObject, expiry sweep), an observation seen
// again (its seen_at moves and its footprint with it), an observation whose expires_at
// has passed (live readers drop it before the sweep deletes it), an avoided area added
// or removed, the bounds changed. One aggregate over the map's rows of env_objects (index
// on map_id) and two small lookups.
std::string live_scene_version(mysqlpp::Connection& c, unsigned map_id);

enum class SceneObjects {
  Imported,  // what an import wrote (SceneStore::load, exports)
  Live,      // imported ones and observations with expires_at in the future
};

// The map's objects of that kind (in id order), its avoided areas (in id order) and
// bounds, read in the caller's transaction. An unknown map id gives an empty scene.
Scene read_scene(mysqlpp::Connection& c, unsigned map_id, SceneObjects which);

inline Scene load_live_scene(mysqlpp::Connection& c, unsigned map_id) {
  return read_scene(c, map_id, SceneObjects::Live);
}

}  // namespace fleetmap
