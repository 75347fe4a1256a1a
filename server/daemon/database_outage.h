#pragma once
// While the database is unreachable every worker and the stall guard keep trying to
// connect, each on its own back-off; the log gets one line per back-off step for the
// whole process (the first failure at once, then after 0.1, 0.2, 0.4 ... up to 5 s), not
// one per thread and attempt, and one line when a connection succeeds again.
#include <algorithm>
#include <chrono>
#include <mutex>

namespace fleetmap {

class DatabaseOutage {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr double kFirstStepS = 0.1, kLastStepS = 5.0;

  // The process's one instance (the threads share it).
  static DatabaseOutage& shared();

  // A failed attempt at `now`: whether it is the one to log (the first of an outage, or
  // the first after the current step has passed; each logged line doubles the step).
  bool report(Clock::time_point now);
  // A connection succeeded: whether an outage was going on (then log that it is over).
  bool end();

 private:
  std::mutex mutex_;
  bool down_ = false;
  double step_s_ = kFirstStepS;
  Clock::time_point next_{};
};

// One thread's waits between connection attempts: 0.1 s, doubling, at most 5 s.
class RetryBackoff {
 public:
  double next_wait_s() {
    const double w = wait_s_;
    wait_s_ = std::min(wait_s_ * 2, DatabaseOutage::kLastStepS);
    return w;
  }
  void reset() { wait_s_ = DatabaseOutage::kFirstStepS; }

 private:
  double wait_s_ = DatabaseOutage::kFirstStepS;
};

}  // namespace fleetmap
