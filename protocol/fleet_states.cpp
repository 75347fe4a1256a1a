#include "protocol/fleet_states.h"

namespace fleetmap {
namespace {

template <typename State, size_t N>
State from_string(std::string_view text, const State (&all)[N], const char* column) {
  std::string expected;
  for (State s : all) {
    if (to_string(s) == text) return s;
    expected += (expected.empty() ? "" : ", ") + std::string(to_string(s));
  }
  throw UnknownState(std::string(column) + ": expected one of " + expected + ", got '" +
                     std::string(text.substr(0, 32)) + "'");
}

}  // namespace

std::string_view to_string(RobotState s) {
  switch (s) {
    case RobotState::Offline: return "offline";
    case RobotState::Ready: return "ready";
    case RobotState::Moving: return "moving";
    case RobotState::Stopped: return "stopped";
    case RobotState::Lost: return "lost";
    case RobotState::Localizing: return "localizing";
  }
  return "offline";
}

std::string_view to_string(TaskState s) {
  switch (s) {
    case TaskState::Assigned: return "assigned";
    case TaskState::Acknowledged: return "acknowledged";
    case TaskState::Active: return "active";
    case TaskState::Done: return "done";
    case TaskState::Aborted: return "aborted";
    case TaskState::Failed: return "failed";
  }
  return "assigned";
}

RobotState robot_state_from_string(std::string_view text) { return from_string(text, kRobotStates, "robots.state"); }
TaskState task_state_from_string(std::string_view text) { return from_string(text, kTaskStates, "tasks.state"); }

}  // namespace fleetmap
