#pragma once
// Maps in the database (SPEC 4): tables maps, obstacles, segments (sql/10_schema.sql).
// Every value reaches SQL quoted by MySQL++ or formatted from a double by us.
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "common/map/map.h"
#include "common/map/map_georef.h"
#include "common/core/error.h"
#include "protocol/map_replace.h"

namespace fleetmap {

struct MapInfo {
  unsigned id = 0;
  std::string name;
  Border border;
  size_t obstacles = 0;
  size_t segments = 0;
  std::string source;
  std::string imported_at;
  // Counts the imports under this id (maps.revision): a replace keeps the id, so caches
  // of what was loaded from the map compare this (server/core/map_cache.h).
  unsigned revision = 1;
  // Georeference (maps.geo_*): the base CRS and the similarity from the map frame to it.
  std::optional<MapGeoref> georef;
};

class MapNotFound : public NotFound {
 public:
  explicit MapNotFound(const std::string& name) : NotFound("no map named '" + name + "'") {}
};

class MapExists : public NotFound {
 public:
  explicit MapExists(const std::string& name)
      : NotFound("a map named '" + name + "' exists; use --replace to replace it") {}
};

// Map names: [A-Za-z0-9_.-]{1,64}. Returns an "expected ..., got ..." message when invalid.
std::optional<std::string> check_map_name(const std::string& name);

using ImportProgress = std::function<void(size_t segments_done, size_t segments_total)>;

struct MapImportOptions {
  // Replace a map of the same name (otherwise MapExists): the maps row keeps its id and
  // its dependents stay, except what drop says; a replace that strands dependents is
  // refused unless force (protocol/map_replace.h).
  bool replace = false;
  MapDrop drop;
  bool force = false;
  // The import's own georeference (a GIS source's CRS), stored with the map; it replaces
  // a kept one. Nothing: a new map has none, a replaced one keeps its own (unless dropped).
  std::optional<MapGeoref> georef;
  ImportProgress progress;
};

struct MapImportReport {
  unsigned map_id = 0;
  bool replaced = false;      // an existing map was replaced (same id)
  MapReplaceReport replace;   // what it kept, dropped and stranded (replaced only)
};

// How the window query finds its rows: the spatial index (the product), or a full scan
// of the map's segments (the baseline the benchmark compares it with).
enum class WindowAccess { SpatialIndex, FullScan };

class MapStore {
 public:
  explicit MapStore(mysqlpp::Connection& c) : c_(c) {}
  // The connection (and transaction) this store works in, for other tables' classes.
  mysqlpp::Connection& connection() const { return c_; }

  // Stores m (validated by the caller) under name in one transaction: either the whole
  // map is there afterwards (and what replace dropped is gone) or nothing changed.
  // Throws MapExists (an existing map without replace), MapWouldStrand.
  MapImportReport import(const Map& m, const std::string& name, const std::string& source,
                         const MapImportOptions& options);
  // The same, returning the map's id.
  unsigned import(const Map& m, const std::string& name, const std::string& source, bool replace,
                  const ImportProgress& progress = {});

  std::vector<MapInfo> list();
  MapInfo info(const std::string& name);  // throws MapNotFound
  std::optional<MapInfo> info(unsigned id);
  // Sets or clears (nullopt) a map's georeference, as given (the caller checked it
  // with GeoTransform), and deletes the control points of the one before
  // (protocol/georef_store.h); throws MapNotFound.
  void set_georef(const std::string& name, const std::optional<MapGeoref>& georef);
  // The stored map, as one import wrote it (re-read if a replace commits meanwhile).
  Map load(const std::string& name);
  Map load(const std::string& name, MapInfo* info);  // and the info of the map it read
  bool remove(const std::string& name);

  // The partial map of rect (already intersected with the border by the caller): the
  // segments whose bounding box meets rect, found with the spatial index, cut at its edge.
  Map window(const std::string& name, const Rect& rect, WindowAccess access = WindowAccess::SpatialIndex);
  Map window(unsigned map_id, const Rect& rect, WindowAccess access = WindowAccess::SpatialIndex);

  // The index the window query uses according to EXPLAIN ("sx_segments_geom" expected).
  std::string window_index(const std::string& name, const Rect& rect);

 private:
  // The obstacles and segments of the map info names; nothing when they do not fit
  // together (read while a replace committed).
  std::optional<Map> read_map(const MapInfo& info);
  std::string window_sql(unsigned map_id, const Rect& rect, WindowAccess access) const;
  mysqlpp::Connection& c_;
};

}  // namespace fleetmap
