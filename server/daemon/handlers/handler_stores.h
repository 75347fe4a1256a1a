#pragma once
// What the handlers need of the database besides the claimed robot's row and the
// batch's writes (protocol/write_batch.h): two small interfaces, implemented over
// MariaDB by server/daemon/db_handler_stores.h and in memory by the handler tests
// (tests/server/daemon/fake_stores.h).
//
//   RobotRecords  the rare writes a handler makes at once (sessions, task states,
//                 images, observed objects, tour events) and the one lookup OpAck needs
//   RobotMaps     the robot's map, its window, scene and planner
#include <memory>
#include <optional>
#include <string>

#include "common/map/map.h"
#include "common/planning/map_planner.h"
#include "common/planning/topo_graph.h"
#include "common/scene/scene.h"
#include "protocol/fleet_states.h"
#include "protocol/map_store.h"
#include "protocol/params.h"
#include "protocol/robot_store.h"
#include "server/core/planner_cache.h"

namespace fleetmap {

class RobotRecords {
 public:
  virtual ~RobotRecords() = default;

  // A new session (Ready): robots.magic, session_at, state ready.
  virtual void start_session(unsigned robot_id, long long magic) = 0;
  // tasks.state, as task_transition allowed it (protocol/task_lifecycle.h); a reason,
  // when not empty, replaces tasks.reason (why a task failed).
  virtual void set_task_state(unsigned long long task_id, TaskState state, const std::string& reason) = 0;
  // The robot's task whose SetPosEnd or Abort was pushed as this answer, in any state.
  virtual std::optional<TaskRow> task_pushed_as(unsigned robot_id, unsigned long long answer_id) = 0;
  virtual void record_image(unsigned robot_id, const SendImageParams& p, const std::string& data,
                            const std::string& at) = 0;
  // The report as it came (observed_objects).
  virtual void record_object(unsigned robot_id, std::optional<unsigned> map_id, const SetObjectParams& p,
                             const std::string& at) = 0;
  // The map's dynamic object for it (SceneStore::record_observation), expiring ttl_s after
  // this sighting; the robots' maps show it from the next batch on.
  virtual void record_observation(unsigned map_id, unsigned robot_id, const SetObjectParams& p, double ttl_s,
                                  const std::string& at) = 0;
  // A guided tour's event (TourEvent; protocol/tour_store.h).
  virtual void record_tour_event(unsigned robot_id, std::optional<unsigned> map_id, const std::string& tour,
                                 const TourEvent& e, const std::string& at) = 0;
};

class RobotMaps {
 public:
  virtual ~RobotMaps() = default;

  // nullopt: no such map (deleted since it was assigned).
  virtual std::optional<MapInfo> info(unsigned map_id) = 0;
  // The map a robot with this laser height sees (server/daemon/robot_map_source.h):
  // the whole map (window nullopt) or the window, already clipped to the border and not
  // empty. Without a laser height, the stored segments unsliced.
  virtual Map robot_map(const MapInfo& info, const std::optional<Rect>& window,
                        std::optional<double> laser_height) = 0;
  // The map's live scene: imported objects, observations not expired, avoided areas.
  virtual std::shared_ptr<const Scene> scene(unsigned map_id) = 0;
  // The planner of the map for this profile with its live scene. Throws
  // std::invalid_argument for a scene or footprint the planner cannot take.
  virtual std::shared_ptr<const MapPlanner> planner(const MapInfo& info, const PlannerProfile& profile) = 0;
  // The map's topological graph (server/core/topo_cache.h), or nullptr when it has none.
  virtual std::shared_ptr<const TopoGraph> topo_graph(const MapInfo& info) = 0;
};

}  // namespace fleetmap
