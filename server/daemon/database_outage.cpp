#include "server/daemon/database_outage.h"

#include <algorithm>

namespace fleetmap {

DatabaseOutage& DatabaseOutage::shared() {
  static DatabaseOutage outage;
  return outage;
}

bool DatabaseOutage::report(Clock::time_point now) {
  std::lock_guard lock(mutex_);
  if (!down_) {
    down_ = true;
    step_s_ = kFirstStepS;
  } else if (now < next_) {
    return false;
  } else {
    step_s_ = std::min(step_s_ * 2, kLastStepS);
  }
  next_ = now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(step_s_));
  return true;
}

bool DatabaseOutage::end() {
  std::lock_guard lock(mutex_);
  const bool was = down_;
  down_ = false;
  return was;
}

}  // namespace fleetmap
