#include "server/web/http/login_throttle.h"

namespace fleetmap::web {

bool LoginThrottle::blocked(const std::string& address, Clock::time_point now) {
  std::lock_guard lock(mutex_);
  auto it = records_.find(address);
  return it != records_.end() && now < it->second.blocked_until;
}

void LoginThrottle::failed(const std::string& address, Clock::time_point now) {
  std::lock_guard lock(mutex_);
  // Forget addresses that have been quiet for a window: the map stays as small as the
  // set of addresses guessing right now.
  for (auto it = records_.begin(); it != records_.end();) {
    const Record& r = it->second;
    const bool quiet = now >= r.blocked_until && (r.failures.empty() || now - r.failures.back() > window_);
    it = quiet && it->first != address ? records_.erase(it) : std::next(it);
  }
  Record& r = records_[address];
  while (!r.failures.empty() && now - r.failures.front() > window_) r.failures.pop_front();
  r.failures.push_back(now);
  if (r.failures.size() >= failures_) {
    r.blocked_until = now + block_;
    r.failures.clear();
  }
}

void LoginThrottle::succeeded(const std::string& address) {
  std::lock_guard lock(mutex_);
  records_.erase(address);
}

}  // namespace fleetmap::web
