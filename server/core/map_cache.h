#pragma once
// Whole maps the server sends on Ready, loaded once per map and revision. A replace keeps
// the map's id and moves its revision (MapStore::import, protocol/map_replace.h), so an
// entry of an older revision is loaded again the first time a batch's MapInfo shows the
// newer one; deleted maps are simply never asked for again.
#include <map>
#include <memory>
#include <mutex>

#include "protocol/map_store.h"

namespace fleetmap {

class MapCache {
 public:
  // The map info describes (by id), at its revision or a later one, loaded through store
  // when the cache holds none or an older revision.
  std::shared_ptr<const Map> get(MapStore& store, const MapInfo& info);

 private:
  struct Entry {
    unsigned revision = 0;
    std::shared_ptr<const Map> map;
  };
  std::mutex mutex_;
  std::map<unsigned, Entry> maps_;
};

}  // namespace fleetmap
