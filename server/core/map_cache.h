#pragma once
// Whole maps the server sends on Ready, loaded once per map id. A replaced map gets a
// new id (MapStore::import), so an entry never goes stale; deleted maps are simply
// never asked for again.
#include <map>
#include <memory>
#include <mutex>

#include "protocol/map_store.h"

namespace fleetmap {

class MapCache {
 public:
  // The map with this id, loaded through store on first use.
  std::shared_ptr<const Map> get(MapStore& store, unsigned map_id, const std::string& name);

 private:
  std::mutex mutex_;
  std::map<unsigned, std::shared_ptr<const Map>> maps_;
};

}  // namespace fleetmap
