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

namespace fleetmap {

struct MapInfo {
  unsigned id = 0;
  std::string name;
  Border border;
  size_t obstacles = 0;
  size_t segments = 0;
  std::string source;
  std::string imported_at;
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

// How the window query finds its rows: the spatial index (the product), or a full scan
// of the map's segments (the baseline the benchmark compares it with).
enum class WindowAccess { SpatialIndex, FullScan };

class MapStore {
 public:
  explicit MapStore(mysqlpp::Connection& c) : c_(c) {}
  // The connection (and transaction) this store works in, for other tables' classes.
  mysqlpp::Connection& connection() const { return c_; }

  // Stores m (validated by the caller) under name in one transaction: either the whole
  // map is there afterwards or nothing changed. Throws MapExists unless replace.
  unsigned import(const Map& m, const std::string& name, const std::string& source, bool replace,
                  const ImportProgress& progress = {});

  std::vector<MapInfo> list();
  MapInfo info(const std::string& name);  // throws MapNotFound
  std::optional<MapInfo> info(unsigned id);
  // Sets or clears (nullopt) a map's georeference, as given (the caller checked it
  // with GeoTransform), and deletes the control points of the one before
  // (protocol/georef_store.h); throws MapNotFound.
  void set_georef(const std::string& name, const std::optional<MapGeoref>& georef);
  Map load(const std::string& name);
  bool remove(const std::string& name);

  // The partial map of rect (already intersected with the border by the caller): the
  // segments whose bounding box meets rect, found with the spatial index, cut at its edge.
  Map window(const std::string& name, const Rect& rect, WindowAccess access = WindowAccess::SpatialIndex);
  Map window(unsigned map_id, const Rect& rect, WindowAccess access = WindowAccess::SpatialIndex);

  // The index the window query uses according to EXPLAIN ("sx_segments_geom" expected).
  std::string window_index(const std::string& name, const Rect& rect);

 private:
  std::string window_sql(unsigned map_id, const Rect& rect, WindowAccess access) const;
  mysqlpp::Connection& c_;
};

}  // namespace fleetmap
