#pragma once
// No robot can stall the others (SPEC 5.3). Two ways a robot's connection blocks others,
// both watched here on the guard's own connection (information_schema INNODB_LOCK_WAITS,
// INNODB_TRX, PROCESSLIST; the server account has PROCESS, sql/30_grants.sql):
//   * it blocks the server: a transaction that keeps locks on sa (SELECT ... FOR UPDATE,
//     DELETE, a SERIALIZABLE read of sa_mine) blocks the server's inserts of its own
//     answers (its sentinel keeps the locks in its own range of sa, sql/10_schema.sql),
//     and with them the rest of the server's batch; no grant prevents it. Seen in two
//     consecutive looks (so not a momentary lock): ended.
//   * it blocks another robot: sentinels keep robots out of each other's answers, but rr
//     is one table with one AUTO_INCREMENT, and a robot's INSERT INTO rr ... SELECT holds
//     the table's AUTO-INC lock for the whole statement (innodb_autoinc_lock_mode 1), which
//     the robot can make as long as it likes (SLEEP in its WHERE): every other robot's
//     request waits. Blocking another robot's connection for robot_block_ms: ended.
// Ended means KILL CONNECTION (its transaction rolls back) and one log line naming it
// (and the robot it blocked). Only the blocker is ended: a robot with an ordinary open
// transaction that blocks nobody is left alone, and so is a robot whose own two
// connections wait on each other (it stalls only itself).
#include <atomic>
#include <chrono>
#include <map>
#include <string>

#include "protocol/db_settings.h"

namespace fleetmap {

class StallGuard {
 public:
  StallGuard(DbSettings db, const std::atomic<bool>& stop, std::chrono::milliseconds period,
             std::chrono::duration<double, std::milli> robot_block = std::chrono::milliseconds(2000))
      : db_(std::move(db)), stop_(stop), period_(period), robot_block_(robot_block) {}
  void run();  // until stop

 private:
  DbSettings db_;
  const std::atomic<bool>& stop_;
  std::chrono::milliseconds period_;
  std::chrono::duration<double, std::milli> robot_block_;
};

}  // namespace fleetmap
