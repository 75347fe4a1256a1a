#include "server/daemon/db_handler_stores.h"

#include "protocol/scene_store.h"
#include "protocol/tour_store.h"
#include "server/daemon/robot_map_source.h"

namespace fleetmap {

void DbRobotRecords::start_session(unsigned robot_id, long long magic) { robots_.start_session(robot_id, magic); }

void DbRobotRecords::set_task_state(unsigned long long task_id, TaskState state, const std::string& reason) {
  robots_.set_task_state(task_id, state, reason);
}

std::optional<TaskRow> DbRobotRecords::task_pushed_as(unsigned robot_id, unsigned long long answer_id) {
  return robots_.task_pushed_as(robot_id, answer_id);
}

void DbRobotRecords::record_image(unsigned robot_id, const SendImageParams& p, const std::string& data,
                                  const std::string& at) {
  robots_.record_image(robot_id, p, data, at);
}

void DbRobotRecords::record_object(unsigned robot_id, std::optional<unsigned> map_id, const SetObjectParams& p,
                                   const std::string& at) {
  robots_.record_object(robot_id, map_id, p, at);
}

void DbRobotRecords::record_observation(unsigned map_id, unsigned robot_id, const SetObjectParams& p, double ttl_s,
                                        const std::string& at) {
  SceneStore(c_).record_observation(map_id, robot_id, {p.x, p.y}, p.object, ttl_s, at);
  RobotMapSource::shared().note_change(map_id);
}

void DbRobotRecords::record_tour_event(unsigned robot_id, std::optional<unsigned> map_id, const std::string& tour,
                                       const TourEvent& e, const std::string& at) {
  TourStore(c_).record(robot_id, map_id, tour, e, at);
}

std::optional<MapInfo> DbRobotMaps::info(unsigned map_id) {
  auto it = infos_.find(map_id);
  if (it == infos_.end()) it = infos_.emplace(map_id, store_.info(map_id)).first;
  return it->second;
}

Map DbRobotMaps::robot_map(const MapInfo& info, const std::optional<Rect>& window,
                           std::optional<double> laser_height) {
  return RobotMapSource::shared().map(store_, cache_, info, window, laser_height);
}

std::shared_ptr<const Scene> DbRobotMaps::scene(unsigned map_id) {
  return RobotMapSource::shared().scene(store_.connection(), map_id);
}

std::shared_ptr<const MapPlanner> DbRobotMaps::planner(const MapInfo& info, const PlannerProfile& profile) {
  return planners_.get(cache_, store_, info, profile, scene(info.id));
}

std::shared_ptr<const TopoGraph> DbRobotMaps::topo_graph(const MapInfo& info) {
  TopoStore topo(store_.connection());
  return graphs_.get(topo, info.name);
}

}  // namespace fleetmap
