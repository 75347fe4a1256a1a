#pragma once
// The semantic layer in the database (seed 002 section 3, seed 004 section II): tables tags, env_objects,
// object_elements (footprint POLYGON, spatial index), avoided_areas (POLYGON, spatial
// index) and map_bounds, sql/60_semantic.sql. A map's Scene (common/scene/scene.h) is found by
// the map's name; deleting the map deletes its scene (foreign-key cascade), replacing it
// keeps the scene unless told otherwise (protocol/map_replace.h).
//
//   SceneStore store(conn);
//   store.import("room", read_scene_geojson(text), {.replace = true});
//   auto doors = store.near("room", {2, 3}, "door", 5);      // k nearest by footprint
//   auto inside = store.avoided_areas_containing("room", {4, 1});
//
// Every value reaches SQL quoted by MySQL++ or formatted from a double by us.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "common/core/error.h"
#include "common/io/wkt.h"  // parse_polygon_wkt, polygon_to_wkt: the store's polygon text
#include "common/scene/scene.h"

namespace fleetmap {

// An object or avoided-area key that is already stored (import without replace, avoid add).
class SceneKeyExists : public NotFound {
 public:
  SceneKeyExists(const std::string& map, const std::string& what, const std::string& key, const std::string& hint = "")
      : NotFound("map '" + map + "' already has " + what + " '" + key + "'" + hint) {}
};

// A tag the tags table does not know (import without add_tags).
class UnknownTag : public BadInput {
 public:
  UnknownTag(const std::string& tag, const std::string& object)
      : BadInput("object '" + object + "': unknown tag '" + tag +
                              "'; add it with 'fleetmap tags set' or import with --add-tags") {}
};

struct SceneImportOptions {
  bool replace = false;   // delete the map's imported objects, avoided areas and bounds first
  bool add_tags = false;  // unknown tags join the vocabulary with class "obstacle"
};

struct SceneImportReport {
  size_t objects = 0, elements = 0, avoided = 0;
  size_t replaced_objects = 0, replaced_avoided = 0;  // deleted by replace
  std::vector<std::string> tags_added;
  bool bounds = false;
};

// One stored object, as 'objects list' shows it.
struct ObjectRow {
  unsigned long long id = 0;
  std::string key, tag, tag_class;
  bool dynamic = false;
  std::string source;             // "imported" or "observed"
  std::string robot, label;       // observed objects: who, and the robot's name for it
  std::string seen_at, expires_at;  // expires_at empty: never
  size_t elements = 0;
  std::optional<double> distance;  // to the query point (list within, near)
};

struct ObjectFilter {
  std::string tag;  // empty: every tag
  // Objects whose footprint comes within radius of centre (distance to the polygon, 0 inside).
  std::optional<Point> centre;
  double radius = 0;
};

// How near() finds candidates: the spatial index with a growing search box (the
// product), or every element of the map ordered by distance (the benchmark's baseline).
enum class NearAccess { SpatialIndex, FullScan };

struct NearStats {
  int rounds = 0;         // index searches (box doublings + 1)
  double box_half = 0;    // half side of the last search box (m)
  size_t candidates = 0;  // objects the last search returned
};

// The observation rule (record_observation): a robot that reports the same object name
// within this distance of the footprint it reported before saw the same object again.
inline constexpr double kSamePlace = 1.0;      // metres
inline constexpr double kObservedSide = 0.2;   // side of an observed object's square footprint (m)
inline constexpr double kObservationTtl = 300; // seconds an observation lives unless seen again

struct Observation {
  unsigned long long object_id = 0;
  std::string key;
  bool refreshed = false;  // seen again (true) or a new object (false)
};

class SceneStore {
 public:
  explicit SceneStore(mysqlpp::Connection& c) : c_(c) {}

  // Stores the scene's objects, avoided areas and bounds into the stored map `map` in one
  // transaction: afterwards either all of it is there or nothing changed. Throws
  // MapNotFound, SceneKeyExists (a key stored already: without replace any, with it a
  // robot's observation), UnknownTag (unless add_tags),
  // std::invalid_argument for a scene the model would not accept (duplicate keys, bad
  // polygons). Observed objects are left alone.
  SceneImportReport import(const std::string& map, const Scene& scene, const SceneImportOptions& options);

  // The map's imported objects (in import order), avoided areas and bounds: what import
  // reads. Observed objects are not part of it. Throws MapNotFound.
  Scene load(const std::string& map);

  // Live objects (imported, and observations not yet expired), by key, or by distance
  // when filter.centre is set. Throws MapNotFound.
  std::vector<ObjectRow> list(const std::string& map, const ObjectFilter& filter = {});

  // The k live objects with the tag (empty: any) nearest p, by distance to their nearest
  // footprint (0 inside), nearest first; ties by key. Throws MapNotFound.
  std::vector<ObjectRow> near(const std::string& map, Point p, const std::string& tag, size_t k,
                              NearAccess access = NearAccess::SpatialIndex, NearStats* stats = nullptr);
  std::vector<ObjectRow> near(unsigned map_id, Point p, const std::string& tag, size_t k,
                              NearAccess access = NearAccess::SpatialIndex, NearStats* stats = nullptr);
  // The index near()'s search uses according to EXPLAIN ("sx_object_elements_footprint").
  std::string near_index(const std::string& map, Point p, const std::string& tag, double box_half);

  // Keys of the avoided areas that contain p (the boundary counts as inside), by key.
  std::vector<std::string> avoided_areas_containing(const std::string& map, Point p);
  // Adds an avoided area from WKT 'POLYGON((x y, ...))'; returns its key (generated as
  // "avoid-N" when key is empty). Throws std::invalid_argument (malformed WKT, or a
  // polygon common/geometry/polygon.h refuses), SceneKeyExists, MapNotFound.
  std::string add_avoided_area(const std::string& map, const std::string& wkt, const std::string& key = "");
  std::vector<AvoidedArea> avoided_areas(const std::string& map);
  // Deletes one avoided area; false when the map has none with that key. Throws MapNotFound.
  bool remove_avoided_area(const std::string& map, const std::string& key);
  // Deletes one object, imported or observed, with its elements; false when the map has
  // none with that key. Throws MapNotFound.
  bool remove_object(const std::string& map, const std::string& key);

  std::vector<TagInfo> tags();
  // Adds a tag or changes its class (and its description, when given); true when added.
  // Throws std::invalid_argument for a malformed tag (1-64 bytes of text, no ':') or class.
  bool set_tag(const std::string& tag, const std::string& tag_class, const std::optional<std::string>& description);

  // SetObject (SPEC 5.2): robot robot_id saw `object` at p on map map_id. The same robot
  // reporting the same name within kSamePlace of that object's footprint refreshes it
  // (footprint moved to p, seen_at = at, expires_at = at + ttl); anything else is a new
  // dynamic object with a kObservedSide square footprint, key "<robot>/<object>/<id>" and
  // the object's name as tag when it is one ("unknown" otherwise). `at` is a TIMESTAMP(6)
  // literal (empty: SYSDATE(6)). Runs in the caller's transaction, if any.
  Observation record_observation(unsigned map_id, unsigned robot_id, Point p, const std::string& object,
                                 double ttl_s = kObservationTtl, const std::string& at = "");
  // Deletes the observations whose expires_at is at or before `now` (empty: SYSDATE(6));
  // returns how many.
  size_t expire_observations(const std::string& now = "");

 private:
  unsigned map_id(const std::string& map, const char* lock = "");
  std::vector<ObjectRow> near_round(unsigned map_id, Point p, const std::string& tag, size_t k,
                                    std::optional<double> box_half);
  mysqlpp::Connection& c_;
};

}  // namespace fleetmap
