#pragma once
// In-memory stores for the handler tests: what a handler wrote at once is recorded for
// the test to look at; maps are Map values served whole or clipped (common/map/map_window.h,
// as the stored map is), planners real MapPlanners built on them.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/map/map_window.h"
#include "protocol/request_queue.h"
#include "server/core/server_config.h"
#include "server/daemon/handlers/handler.h"
#include "server/daemon/handlers/handler_stores.h"
#include "server/daemon/dispatch.h"

namespace fleetmap::fakes {

class FakeRecords : public RobotRecords {
 public:
  struct Image {
    unsigned robot_id;
    SendImageParams p;
    std::string data, at;
  };
  struct Object {
    unsigned robot_id;
    std::optional<unsigned> map_id;
    SetObjectParams p;
    std::string at;
  };
  struct Observation {
    unsigned map_id, robot_id;
    SetObjectParams p;
    double ttl_s;
    std::string at;
  };

  std::map<unsigned, long long> sessions;                 // robot id -> magic
  std::vector<std::pair<unsigned long long, TaskState>> task_states;  // in the order written
  std::map<unsigned long long, std::string> task_reasons;              // the last reason given, by task
  std::vector<TaskRow> tasks;                              // what task_pushed_as looks in
  std::vector<Image> images;
  std::vector<Object> objects;
  std::vector<Observation> observations;
  struct RecordedTourEvent {
    unsigned robot_id;
    std::optional<unsigned> map_id;
    std::string tour;
    TourEvent event;
    std::string at;
  };
  std::vector<RecordedTourEvent> tour_events;

  void start_session(unsigned robot_id, long long magic) override { sessions[robot_id] = magic; }
  void set_task_state(unsigned long long task_id, TaskState state, const std::string& reason) override {
    task_states.emplace_back(task_id, state);
    if (!reason.empty()) task_reasons[task_id] = reason;
    for (TaskRow& t : tasks)
      if (t.id == task_id) t.state = state;
  }
  std::optional<TaskRow> task_pushed_as(unsigned robot_id, unsigned long long answer_id) override {
    for (const TaskRow& t : tasks)
      if (t.robot_id == robot_id && (t.answer_id == answer_id || t.abort_answer_id == answer_id)) return t;
    return std::nullopt;
  }
  void record_image(unsigned robot_id, const SendImageParams& p, const std::string& data,
                    const std::string& at) override {
    images.push_back({robot_id, p, data, at});
  }
  void record_object(unsigned robot_id, std::optional<unsigned> map_id, const SetObjectParams& p,
                     const std::string& at) override {
    objects.push_back({robot_id, map_id, p, at});
  }
  void record_observation(unsigned map_id, unsigned robot_id, const SetObjectParams& p, double ttl_s,
                          const std::string& at) override {
    observations.push_back({map_id, robot_id, p, ttl_s, at});
  }
  void record_tour_event(unsigned robot_id, std::optional<unsigned> map_id, const std::string& tour, const TourEvent& e,
                         const std::string& at) override {
    tour_events.push_back({robot_id, map_id, tour, e, at});
  }
  bool wrote_anything() const {
    return !sessions.empty() || !task_states.empty() || !images.empty() || !objects.empty() || !observations.empty() ||
           !tour_events.empty();
  }
};

class FakeMaps : public RobotMaps {
 public:
  struct Requested {
    std::optional<Rect> window;
    std::optional<double> laser_height;
  };
  std::map<unsigned, std::pair<MapInfo, Map>> maps;
  std::map<unsigned, std::shared_ptr<const Scene>> scenes;
  std::vector<Requested> requested;  // every robot_map call
  bool planner_refuses = false;      // planner() throws std::invalid_argument

  // A map of these obstacles in the border, under this id.
  void add(unsigned id, const std::string& name, const Map& m) {
    MapInfo info;
    info.id = id;
    info.name = name;
    info.border = m.border;
    info.obstacles = m.obstacles.size();
    info.segments = m.segment_count();
    maps[id] = {info, m};
  }

  std::optional<MapInfo> info(unsigned map_id) override {
    auto it = maps.find(map_id);
    if (it == maps.end()) return std::nullopt;
    return it->second.first;
  }
  Map robot_map(const MapInfo& info, const std::optional<Rect>& window, std::optional<double> laser_height) override {
    requested.push_back({window, laser_height});
    const Map& m = maps.at(info.id).second;
    return window ? clip_map(m, *window) : m;
  }
  std::shared_ptr<const Scene> scene(unsigned map_id) override {
    auto it = scenes.find(map_id);
    return it == scenes.end() ? std::make_shared<const Scene>() : it->second;
  }
  std::shared_ptr<const MapPlanner> planner(const MapInfo& info, const PlannerProfile& profile) override {
    if (planner_refuses) throw std::invalid_argument("obstacle 7: footprint is not a closed polygon");
    profiles.push_back(profile);
    Map m = maps.at(info.id).second;
    m.compute_bounds();
    return std::make_shared<const MapPlanner>(m, server_planner_options(profile));
  }
  std::shared_ptr<const TopoGraph> topo_graph(const MapInfo& info) override {
    auto it = graphs.find(info.id);
    return it == graphs.end() ? nullptr : it->second;
  }
  std::vector<PlannerProfile> profiles;  // every planner() call
  std::map<unsigned, std::shared_ptr<const TopoGraph>> graphs;  // by map id
};

// A 20 m x 10 m map with one wall, 1 m high, from (10, 0) to (10, 6): a robot passes
// above y = 6.
inline Map walled_room() {
  Map m;
  m.border = Border::from_rect({0, 0, 20, 10});
  Obstacle wall;
  wall.id = 1;
  wall.type = ShapeType::ClosedPolygon;
  const Point c[] = {{9.9, 0}, {10.1, 0}, {10.1, 6}, {9.9, 6}};
  for (int i = 0; i < 4; ++i) wall.segments.push_back({.a = c[i], .b = c[(i + 1) % 4], .h = 1.0});
  m.obstacles.push_back(wall);
  m.compute_bounds();
  return m;
}

// A registered robot (Ready done) on map 1.
inline ServedRobot registered_robot(unsigned id = 7, const std::string& account = "r7") {
  ServedRobot s;
  s.robot.id = id;
  s.robot.db_user = account;
  s.robot.map_id = 1;
  s.robot.magic = 42;
  s.robot.state = RobotState::Ready;
  return s;
}

inline Request request(unsigned long long id, const std::string& account, const std::string& op,
                       const std::string& params, std::optional<std::string> payload = std::nullopt) {
  Request r;
  r.id = id;
  r.db_user = account;
  r.op = op;
  r.params = params;
  r.payload = std::move(payload);
  r.created_at = "2026-11-28 07:00:0" + std::to_string(id % 10) + ".000000";
  return r;
}

inline TaskRow task(unsigned long long id, unsigned robot_id, TaskState state, double gx, double gy) {
  TaskRow t;
  t.id = id;
  t.robot_id = robot_id;
  t.state = state;
  t.goal_x = gx;
  t.goal_y = gy;
  return t;
}

// One robot, its stores and the server's settings: send() serves a request through
// dispatch() as the request loop does.
struct Bench {
  ServerConfig config;
  FakeRecords records;
  FakeMaps maps;
  ServedRobot served = registered_robot();
  unsigned long long next_id = 100;

  Bench() { maps.add(1, "room", walled_room()); }
  RobotRow& robot() { return served.robot; }
  RequestWrites send(const std::string& op, const std::string& params,
                     std::optional<std::string> payload = std::nullopt) {
    return dispatch(config, records, maps, served, request(++next_id, served.robot.db_user, op, params, payload));
  }
};

// The error code of a single Error answer, or "" when the writes are something else.
inline std::string error_code(const RequestWrites& w) {
  if (w.answers.size() != 1 || w.answers[0].op != AnswerOp::Error) return "";
  return w.answers[0].params.at("code").get<std::string>();
}

}  // namespace fleetmap::fakes
