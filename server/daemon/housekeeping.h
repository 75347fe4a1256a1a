#pragma once
// The periodic work of the server besides serving requests (SPEC 5.3), done by one
// worker between batches:
//   pushes      an operator's goal goes to its robot as SetPosEnd, an abort as Abort
//               (an abort of a goal never pushed just ends the task)
//   lost robots a registered robot silent for lost_after_periods Alive periods is lost
//               and its open task fails
//   orphans     requests from accounts that are no robot are dropped
//   expiry      observations past their time are deleted (SetObject; the maps and views
//               skip them from expires_at on already), and with history_keep_s the
//               poses and GPS fixes older than that (protocol/history_retention.h)
// The decisions are pure functions below; Housekeeping applies them over MariaDB.
#include <chrono>
#include <cstddef>
#include <optional>

#include <mysql++/mysql++.h>

#include "protocol/robot_store.h"
#include "server/core/server_config.h"

namespace fleetmap {

// What a robot's open task needs pushed.
enum class PushAction {
  None,          // pushed already, nothing asked since
  SendGoal,      // SetPosEnd of a new task
  SendAbort,     // Abort of a task the robot was told of
  AbortUnsent,   // aborted before its SetPosEnd went out: the robot never heard of it
};
PushAction push_action(const TaskRow& task);

// A robot silent (no request, nothing waiting) for longer than this is lost.
double lost_after_s(const ServerConfig& config);

// When a housekeeping worker does its passes: every `period`, and the expiry sweep on
// every `expiry_every`-th pass (the first pass included). Pure: the caller gives the time.
class HousekeepingSchedule {
 public:
  using Clock = std::chrono::steady_clock;
  explicit HousekeepingSchedule(Clock::duration period = std::chrono::milliseconds(100), unsigned expiry_every = 20)
      : period_(period), expiry_every_(expiry_every) {}

  struct Pass {
    bool expire_observations = false;
  };
  // A pass when it is time (then the next one is period from now), else nullopt.
  std::optional<Pass> due(Clock::time_point now);

 private:
  Clock::duration period_;
  unsigned expiry_every_;
  std::optional<Clock::time_point> next_;
  unsigned passes_ = 0;
};

class Housekeeping {
 public:
  Housekeeping(mysqlpp::Connection& c, const ServerConfig& config) : c_(c), config_(config) {}

  // One pass; returns the pushes made (work done, for the loop's idle back-off).
  size_t run(const HousekeepingSchedule::Pass& pass);

  size_t push_operations();
  size_t mark_lost_robots();
  size_t drop_orphan_requests();

 private:
  mysqlpp::Connection& c_;
  const ServerConfig& config_;
};

}  // namespace fleetmap
