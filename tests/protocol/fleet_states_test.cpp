// Robot and task states against the ENUMs of sql/10_schema.sql: each value reads back as
// its state and writes back as the same text; any other text is refused by name.
#include "protocol/fleet_states.h"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "protocol/sql_util.h"

namespace fleetmap {
namespace {

TEST(FleetStates, RobotStatesAreTheSchemasEnumValues) {
  // robots.state ENUM('offline','ready','moving','stopped','lost','localizing')
  const std::pair<const char*, RobotState> values[] = {{"offline", RobotState::Offline},
                                                       {"ready", RobotState::Ready},
                                                       {"moving", RobotState::Moving},
                                                       {"stopped", RobotState::Stopped},
                                                       {"lost", RobotState::Lost},
                                                       {"localizing", RobotState::Localizing}};
  for (const auto& [text, state] : values) {
    EXPECT_EQ(robot_state_from_string(text), state) << text;
    EXPECT_EQ(to_string(state), text);
  }
  EXPECT_EQ(std::size(kRobotStates), std::size(values));
}

TEST(FleetStates, TaskStatesAreTheSchemasEnumValues) {
  // tasks.state ENUM('assigned','acknowledged','active','done','aborted','failed')
  const std::pair<const char*, TaskState> values[] = {
      {"assigned", TaskState::Assigned}, {"acknowledged", TaskState::Acknowledged}, {"active", TaskState::Active},
      {"done", TaskState::Done},         {"aborted", TaskState::Aborted},           {"failed", TaskState::Failed}};
  for (const auto& [text, state] : values) {
    EXPECT_EQ(task_state_from_string(text), state) << text;
    EXPECT_EQ(to_string(state), text);
  }
  EXPECT_EQ(std::size(kTaskStates), std::size(values));
}

TEST(FleetStates, UnknownTextIsRefusedNamingTheColumnAndTheStates) {
  for (const char* bad : {"", "Ready", "READY", "ready ", "paused", "runnning"}) {
    try {
      robot_state_from_string(bad);
      FAIL() << "'" << bad << "' accepted as a robot state";
    } catch (const UnknownState& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("robots.state"), std::string::npos) << m;
      EXPECT_NE(m.find("offline, ready, moving, stopped, lost"), std::string::npos) << m;
      EXPECT_NE(m.find("got '" + std::string(bad) + "'"), std::string::npos) << m;
    }
  }
  for (const char* bad : {"", "Done", "running", "aborted\n"}) {
    try {
      task_state_from_string(bad);
      FAIL() << "'" << bad << "' accepted as a task state";
    } catch (const UnknownState& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("tasks.state"), std::string::npos) << m;
      EXPECT_NE(m.find("assigned, acknowledged, active, done, aborted, failed"), std::string::npos) << m;
    }
  }
}

TEST(FleetStates, TheOpenStatesInSqlAreTheOnesRobotRemoveFails) {
  // robot_remove applies TaskEvent::RobotRemoved in SQL (sql/40_robot_accounts.sql): it
  // must fail the same open tasks the server works on.
  EXPECT_EQ(sql::open_task_states(), "('assigned', 'acknowledged', 'active')");
  std::ifstream in(FLEETMAP_SOURCE_DIR "/sql/40_robot_accounts.sql");
  ASSERT_TRUE(in) << "cannot read sql/40_robot_accounts.sql";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("t.state IN " + sql::open_task_states()), std::string::npos);
  EXPECT_EQ(sql::quoted(RobotState::Lost), "'lost'");
}

}  // namespace
}  // namespace fleetmap
