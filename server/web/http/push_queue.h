#pragma once
// What one WebSocket client has yet to receive (docs/web-api.md "The feed"): at most one
// frame in flight; whatever arrives meanwhile is coalesced, the latest state per robot
// and per task, so a client that does not read holds at most one state per robot and
// one per task, however long it stalls.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fleetmap::web {

class PushQueue {
 public:
  // {"type":"hello",...}: sent before anything else.
  void hello(nlohmann::json message);
  // Robot states (objects with "name"): each replaces the pending state of its robot.
  // force: send a robots message even when robots is empty (a client's first, SPEC: it
  // holds every robot, which may be none).
  void robots(const std::vector<nlohmann::json>& robots, bool force = false);
  // Task objects (with "id"): each replaces the pending state of its task.
  void tasks(const std::vector<nlohmann::json>& tasks);

  // The next frame when none is in flight and something is pending (hello, then robots,
  // then tasks); it is then in flight until sent().
  std::optional<std::string> take();
  void sent();

  bool in_flight() const { return in_flight_; }
  size_t pending_robots() const { return robots_.size(); }
  size_t pending_tasks() const { return tasks_.size(); }

 private:
  std::optional<nlohmann::json> hello_;
  std::map<std::string, nlohmann::json> robots_;
  bool robots_forced_ = false;
  std::map<unsigned long long, nlohmann::json> tasks_;
  bool in_flight_ = false;
};

}  // namespace fleetmap::web
