#include "server/daemon/robot_map_source.h"

#include <algorithm>

#include "common/slicing/map_slice.h"
#include "common/map/map_window.h"
#include "common/geometry/polygon.h"
#include "common/slicing/scene_laser.h"
#include "protocol/live_scene.h"

namespace fleetmap {
namespace {

constexpr size_t kMaxEntries = 64;  // (map, height) pairs kept; more are dropped wholesale

// Closed boxes: touching counts, so no obstacle that clip_obstacle would keep is skipped.
bool meet(const Rect& a, const Rect& b) {
  return a.xmin <= b.xmax && b.xmin <= a.xmax && a.ymin <= b.ymax && b.ymin <= a.ymax;
}

template <class Cache>
void bound_size(Cache& cache) {
  if (cache.size() >= kMaxEntries) cache.clear();
}

}  // namespace

RobotMapSource& RobotMapSource::shared() {
  static RobotMapSource source;
  return source;
}

std::shared_ptr<const RobotMapSource::Indexed> RobotMapSource::slice(const Map& full, const MapInfo& info,
                                                                     double laser_height) {
  const Key key{info.id, laser_height};
  {
    std::lock_guard lock(mutex_);
    if (auto it = slices_.find(key); it != slices_.end() && it->second->revision == info.revision) return it->second;
  }
  auto s = std::make_shared<Indexed>();
  s->revision = info.revision;
  s->obstacles = slice_at_height(full, laser_height).obstacles;  // outside the lock: O(map)
  for (const Obstacle& o : s->obstacles) s->boxes.push_back(o.box());
  std::lock_guard lock(mutex_);
  bound_size(slices_);
  return slices_[key] = std::move(s);
}

std::shared_ptr<const RobotMapSource::Indexed> RobotMapSource::objects(const Map& full, const MapInfo& info,
                                                                       double laser_height,
                                                                       const std::shared_ptr<const Scene>& scene) {
  const Key key{info.id, laser_height};
  {
    std::lock_guard lock(mutex_);
    if (auto it = objects_.find(key); it != objects_.end() && it->second.scene == scene &&
                                      it->second.obstacles->revision == info.revision)
      return it->second.obstacles;
  }
  // with_objects_at_height numbers the objects' obstacles after the map's largest id; a
  // map of that one obstacle gives the same numbers as the whole map would.
  Map stub;
  int largest = 0;
  for (const Obstacle& o : full.obstacles) largest = std::max(largest, o.id);
  if (!full.obstacles.empty()) {
    stub.obstacles.emplace_back();
    stub.obstacles.back().id = largest;
  }
  Map seen = with_objects_at_height(stub, *scene, laser_height);
  auto out = std::make_shared<Indexed>();
  out->revision = info.revision;
  out->obstacles.assign(std::make_move_iterator(seen.obstacles.begin() + static_cast<long>(stub.obstacles.size())),
                        std::make_move_iterator(seen.obstacles.end()));
  for (const Obstacle& o : out->obstacles) out->boxes.push_back(o.box());
  std::lock_guard lock(mutex_);
  bound_size(objects_);
  objects_[key] = {scene, out};
  return out;
}

std::shared_ptr<const Scene> RobotMapSource::scene(mysqlpp::Connection& c, unsigned map_id) {
  const auto now = std::chrono::steady_clock::now();
  std::string known;
  {
    std::lock_guard lock(mutex_);
    if (auto it = scenes_.find(map_id); it != scenes_.end()) {
      if (now - it->second.checked < kRecheck && now >= it->second.recheck_until) return it->second.scene;
      known = it->second.version;
    }
  }
  const std::string version = live_scene_version(c, map_id);
  std::lock_guard lock(mutex_);
  SceneEntry& e = scenes_[map_id];
  if (e.scene && version == known && e.version == known) {
    e.checked = now;
    return e.scene;
  }
  // Loaded under the lock: a change is rare, and two workers must not both load it.
  e.scene = std::make_shared<const Scene>(load_live_scene(c, map_id));
  e.version = version;
  e.checked = now;
  return e.scene;
}

void RobotMapSource::note_change(unsigned map_id) {
  std::lock_guard lock(mutex_);
  scenes_[map_id].recheck_until = std::chrono::steady_clock::now() + kAfterChange;
}

Map RobotMapSource::map(MapStore& maps, MapCache& cache, const MapInfo& info, const std::optional<Rect>& window,
                        std::optional<double> laser_height) {
  if (!laser_height) return window ? maps.window(info.id, *window) : *cache.get(maps, info);

  const std::shared_ptr<const Map> full = cache.get(maps, info);
  const auto sliced = slice(*full, info, *laser_height);
  const auto added = objects(*full, info, *laser_height, scene(maps.connection(), info.id));
  Map out;
  if (!window) {
    out.border = full->border;
    out.obstacles = sliced->obstacles;
    out.obstacles.insert(out.obstacles.end(), added->obstacles.begin(), added->obstacles.end());
    return out;
  }
  // clip_map of the slice with the objects, skipping the obstacles whose box misses r.
  out.border = Border::from_rect(*window);
  for (const Indexed* part : {sliced.get(), added.get()})
    for (size_t i = 0; i < part->obstacles.size(); ++i)
      if (meet(part->boxes[i], *window))
        if (auto c = clip_obstacle(part->obstacles[i], *window)) out.obstacles.push_back(std::move(*c));
  return out;
}

Scene scene_in_window(const Scene& scene, const Rect& r) {
  Scene out;
  out.bounds = scene.bounds;
  for (const EnvObject& o : scene.objects)
    if (std::any_of(o.elements.begin(), o.elements.end(),
                    [&](const Element& e) { return !e.footprint.empty() && meet(polygon_bounds(e.footprint), r); }))
      out.objects.push_back(o);
  for (const AvoidedArea& a : scene.avoided)
    if (!a.area.empty() && meet(polygon_bounds(a.area), r)) out.avoided.push_back(a);
  return out;
}

}  // namespace fleetmap
