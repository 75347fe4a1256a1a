#include "server/web/http/push_hub.h"

#include <algorithm>

namespace fleetmap::web {

void PushHub::subscribe(const std::shared_ptr<PushClient>& client) {
  std::lock_guard lock(mutex_);
  clients_.push_back(client);
  if (!primed_) return;  // its first message comes with the first poll
  FeedUpdate all;
  for (const auto& [name, r] : robots_) all.robots.push_back(r);
  client->push(all, true);
}

void PushHub::publish(const FeedUpdate& update) {
  std::lock_guard lock(mutex_);
  const bool first = !primed_;
  primed_ = true;
  if (!first && update.robots.empty() && update.tasks.empty()) return;
  for (const auto& r : update.robots) robots_[r.value("name", std::string())] = r;
  std::erase_if(clients_, [&](const std::weak_ptr<PushClient>& w) {
    auto c = w.lock();
    if (!c) return true;
    c->push(update, first);
    return false;
  });
}

size_t PushHub::clients() const {
  std::lock_guard lock(mutex_);
  return static_cast<size_t>(std::count_if(clients_.begin(), clients_.end(), [](const auto& w) { return !w.expired(); }));
}

size_t PushHub::robots() const {
  std::lock_guard lock(mutex_);
  return robots_.size();
}

}  // namespace fleetmap::web
