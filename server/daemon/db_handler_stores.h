#pragma once
// The handlers' store interfaces (handlers/handler_stores.h) over MariaDB: the table
// classes of protocol/ in the batch's connection and transaction, and the process's
// caches (maps, planners, the robots' maps and scenes of robot_map_source.h). One pair
// per batch: map descriptions are looked up once per batch (every GetMap and SendGPS
// needs one).
#include <map>
#include <optional>

#include <mysql++/mysql++.h>

#include "protocol/map_store.h"
#include "protocol/robot_store.h"
#include "server/core/map_cache.h"
#include "server/core/planner_cache.h"
#include "server/core/topo_cache.h"
#include "server/daemon/handlers/handler_stores.h"

namespace fleetmap {

class DbRobotRecords : public RobotRecords {
 public:
  explicit DbRobotRecords(mysqlpp::Connection& c) : c_(c), robots_(c) {}

  void start_session(unsigned robot_id, long long magic) override;
  void set_task_state(unsigned long long task_id, TaskState state, const std::string& reason) override;
  std::optional<TaskRow> task_pushed_as(unsigned robot_id, unsigned long long answer_id) override;
  void record_image(unsigned robot_id, const SendImageParams& p, const std::string& data,
                    const std::string& at) override;
  void record_object(unsigned robot_id, std::optional<unsigned> map_id, const SetObjectParams& p,
                     const std::string& at) override;
  void record_observation(unsigned map_id, unsigned robot_id, const SetObjectParams& p, double ttl_s,
                          const std::string& at) override;
  void record_tour_event(unsigned robot_id, std::optional<unsigned> map_id, const std::string& tour, const TourEvent& e,
                         const std::string& at) override;

 private:
  mysqlpp::Connection& c_;
  RobotStore robots_;
};

class DbRobotMaps : public RobotMaps {
 public:
  DbRobotMaps(mysqlpp::Connection& c, MapCache& cache, PlannerCache& planners, TopoCache& graphs)
      : store_(c), cache_(cache), planners_(planners), graphs_(graphs) {}

  std::optional<MapInfo> info(unsigned map_id) override;
  Map robot_map(const MapInfo& info, const std::optional<Rect>& window, std::optional<double> laser_height) override;
  std::shared_ptr<const Scene> scene(unsigned map_id) override;
  std::shared_ptr<const MapPlanner> planner(const MapInfo& info, const PlannerProfile& profile) override;
  std::shared_ptr<const TopoGraph> topo_graph(const MapInfo& info) override;

 private:
  MapStore store_;
  MapCache& cache_;
  PlannerCache& planners_;
  TopoCache& graphs_;
  std::map<unsigned, std::optional<MapInfo>> infos_;
};

}  // namespace fleetmap
