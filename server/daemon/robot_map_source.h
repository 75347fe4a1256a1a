#pragma once
// The map each robot is served (seed 004 section III.A): Ready's and GetMap's
// SetMap hold what the robot's laser sees, i.e. the stored segment map sliced at the
// laser height of its profile (common/slicing/map_slice.h) plus the map's objects seen at that
// height (common/slicing/scene_laser.h), cut to the window exactly as segments are
// (common/map/map_window.h). The whole map equals `fleetmap map slice NAME --height H`.
//
// A robot without a laser height in its profile (robots.laser_height NULL) gets the
// stored map as it is, without objects (the plain segment map of SPEC 5.4), which its
// own ray caster reads at whatever height its laser is (SPEC 6).
//
// One instance per server process (shared()), used by every worker, three caches:
//   slices   (map id, laser height) -> slice_at_height of the stored map, at the map's
//            revision: a replace keeps the id and moves the revision (MapStore::import),
//            so a slice of an older revision is made again.
//   scenes   map id -> the live scene (protocol/live_scene.h: imported objects and
//            observations not expired), with its version text. The version is read again
//            (one aggregate query) when it was last read more than kRecheck ago, and on
//            every use for kAfterChange after this process recorded an observation on
//            the map: a new import, observation or expiry reaches the robots' maps
//            within about kRecheck, and a robot's own SetObject its next GetMap.
//   objects  (map id, laser height, scene, revision) -> the obstacles the scene adds at
//            that height (numbered after the map's largest obstacle id).
// Loads run outside the lock, in the caller's connection and transaction.
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <mysql++/mysql++.h>

#include "common/map/map.h"
#include "common/scene/scene.h"
#include "protocol/map_store.h"
#include "server/core/map_cache.h"

namespace fleetmap {

class RobotMapSource {
 public:
  static constexpr std::chrono::milliseconds kRecheck{250};
  static constexpr std::chrono::milliseconds kAfterChange{2000};

  static RobotMapSource& shared();

  // The map of `info` a robot with this laser height gets: the whole map (window
  // nullopt) or the window (already intersected with the border, not empty). Throws
  // std::invalid_argument when the stored map cannot be sliced (a malformed ramp).
  Map map(MapStore& maps, MapCache& cache, const MapInfo& info, const std::optional<Rect>& window,
          std::optional<double> laser_height);

  // The map's live scene, re-read when its version changed.
  std::shared_ptr<const Scene> scene(mysqlpp::Connection& c, unsigned map_id);

  // This process changed the map's scene (SetObject): check its version on every use
  // for a while, so that the change is seen as soon as it is committed.
  void note_change(unsigned map_id);

 private:
  struct Indexed {  // obstacles with their bounding boxes, to cut windows quickly
    unsigned revision = 0;  // of the map they were made from
    std::vector<Obstacle> obstacles;
    std::vector<Rect> boxes;
  };
  struct SceneEntry {
    std::string version;
    std::shared_ptr<const Scene> scene;
    std::chrono::steady_clock::time_point checked, recheck_until;
  };
  struct ObjectsEntry {
    std::shared_ptr<const Scene> scene;
    std::shared_ptr<const Indexed> obstacles;
  };
  using Key = std::pair<unsigned, double>;  // map id, laser height

  std::shared_ptr<const Indexed> slice(const Map& full, const MapInfo& info, double laser_height);
  std::shared_ptr<const Indexed> objects(const Map& full, const MapInfo& info, double laser_height,
                                         const std::shared_ptr<const Scene>& scene);

  std::mutex mutex_;
  std::map<Key, std::shared_ptr<const Indexed>> slices_;
  std::map<unsigned, SceneEntry> scenes_;
  std::map<Key, ObjectsEntry> objects_;
};

// GetMap "2.5d" (docs/wire-format.md): the scene's objects whose footprints' bounding
// boxes meet r, whole (every element with its height range), the avoided areas whose
// bounding boxes meet r, and the bounds.
Scene scene_in_window(const Scene& scene, const Rect& r);

}  // namespace fleetmap
