#pragma once
// Robot and task states (SPEC 5.3) as the code handles them. The database keeps them as
// text (robots.state, tasks.state: ENUMs of sql/10_schema.sql, shown by the views as
// they are); the text is read and written only by the table classes of protocol/
// (robot_store, fleet_store, write_batch), through to_string / *_from_string here.
// Operators see the same words (`fleetmap robots`, `fleetmap tasks`).
#include <stdexcept>
#include <string>
#include <string_view>

namespace fleetmap {

// Lost: silent for too long (SPEC 5.3). Localizing: it talks, but its localization
// reported that it does not know its pose (SendPos "status": "lost", docs/protocol.md).
enum class RobotState { Offline, Ready, Moving, Stopped, Lost, Localizing };

enum class TaskState { Assigned, Acknowledged, Active, Done, Aborted, Failed };

// The text of robots.state / tasks.state (SPEC 5.3's words).
std::string_view to_string(RobotState s);
std::string_view to_string(TaskState s);

// A value of the database that is none of the states (a schema this build does not know).
class UnknownState : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws UnknownState naming the column and the states expected ("tasks.state: expected
// one of assigned, ..., got 'paused'"). Exact, case-sensitive: the ENUM's own values.
RobotState robot_state_from_string(std::string_view text);
TaskState task_state_from_string(std::string_view text);

inline constexpr RobotState kRobotStates[] = {RobotState::Offline, RobotState::Ready, RobotState::Moving,
                                              RobotState::Stopped, RobotState::Lost, RobotState::Localizing};
inline constexpr TaskState kTaskStates[] = {TaskState::Assigned, TaskState::Acknowledged, TaskState::Active,
                                            TaskState::Done,     TaskState::Aborted,      TaskState::Failed};

}  // namespace fleetmap
