#pragma once
// Fans the feed's changes out to the WebSocket clients (docs/web-api.md "The feed"). The
// hub keeps the latest state of every robot, so that a new client's first robots message
// holds all of them; each client coalesces on its own (push_queue.h), so a slow one
// never stalls the feed or the others.
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fleetmap::web {

struct FeedUpdate {
  std::vector<nlohmann::json> robots;  // robot states that changed (objects with "name")
  std::vector<nlohmann::json> tasks;   // tasks created or changed (objects with "id")
};

// A subscriber. push() is called with the hub's lock held: it must only queue (and may
// post to its own executor), never block or call back into the hub.
class PushClient {
 public:
  virtual ~PushClient() = default;
  // first: the client's first update, whose robots are every robot the hub knows.
  virtual void push(const FeedUpdate& update, bool first) = 0;
};

class PushHub {
 public:
  // Sends the client the state of every robot (at once, or with the feed's first poll
  // when it has not come yet); the client then gets every publish() until it is
  // destroyed (the hub holds it weakly).
  void subscribe(const std::shared_ptr<PushClient>& client);
  // The feed's first publish holds every robot (possibly none) and primes the hub.
  void publish(const FeedUpdate& update);
  size_t clients() const;
  size_t robots() const;

 private:
  mutable std::mutex mutex_;
  std::vector<std::weak_ptr<PushClient>> clients_;
  std::map<std::string, nlohmann::json> robots_;  // the latest state of each robot
  bool primed_ = false;  // the first poll came: robots_ holds every robot
};

}  // namespace fleetmap::web
