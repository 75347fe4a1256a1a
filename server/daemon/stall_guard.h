#pragma once
// No robot can stall the others (SPEC 5.3): a robot that keeps a transaction open with
// locks on sa (SELECT ... FOR UPDATE, DELETE, a SERIALIZABLE read of sa_mine) blocks the
// server's inserts of its own answers (its sentinel keeps the locks in its own range of
// sa, sql/10_schema.sql), and with them the rest of the server's batch; no grant prevents
// it. The guard watches, on its
// own connection, which transactions block this server's connections; a robot's that
// blocks the server in two consecutive looks (so not a momentary lock) is ended (KILL)
// and logged. Only the blocker is ended: a robot with an ordinary open transaction that
// blocks nobody is left alone.
#include <atomic>
#include <chrono>
#include <map>
#include <string>

#include "protocol/db_settings.h"

namespace fleetmap {

class StallGuard {
 public:
  StallGuard(DbSettings db, const std::atomic<bool>& stop, std::chrono::milliseconds period)
      : db_(std::move(db)), stop_(stop), period_(period) {}
  void run();  // until stop

 private:
  DbSettings db_;
  const std::atomic<bool>& stop_;
  std::chrono::milliseconds period_;
};

}  // namespace fleetmap
