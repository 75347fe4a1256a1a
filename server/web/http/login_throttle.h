#pragma once
// Slows password guessing (docs/web-api.md): after 5 failed logins from one address
// within a minute, that address gets 429 for a minute.
#include <chrono>
#include <deque>
#include <map>
#include <mutex>
#include <string>

namespace fleetmap::web {

class LoginThrottle {
 public:
  using Clock = std::chrono::steady_clock;
  explicit LoginThrottle(size_t failures = 5, std::chrono::seconds window = std::chrono::seconds(60),
                         std::chrono::seconds block = std::chrono::seconds(60))
      : failures_(failures), window_(window), block_(block) {}

  // True while address may not try again.
  bool blocked(const std::string& address, Clock::time_point now = Clock::now());
  void failed(const std::string& address, Clock::time_point now = Clock::now());
  void succeeded(const std::string& address);

 private:
  struct Record {
    std::deque<Clock::time_point> failures;  // within the window
    Clock::time_point blocked_until{};
  };
  size_t failures_;
  std::chrono::seconds window_, block_;
  std::mutex mutex_;
  std::map<std::string, Record> records_;
};

}  // namespace fleetmap::web
