#include "server/web/http/push_queue.h"

namespace fleetmap::web {
namespace {

std::string frame(const nlohmann::json& j) { return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); }

}  // namespace

void PushQueue::hello(nlohmann::json message) { hello_ = std::move(message); }

void PushQueue::robots(const std::vector<nlohmann::json>& robots, bool force) {
  for (const auto& r : robots) robots_[r.value("name", std::string())] = r;
  robots_forced_ = robots_forced_ || force;
}

void PushQueue::tasks(const std::vector<nlohmann::json>& tasks) {
  for (const auto& t : tasks) tasks_[t.value("id", 0ull)] = t;
}

std::optional<std::string> PushQueue::take() {
  if (in_flight_) return std::nullopt;
  std::optional<std::string> out;
  if (hello_) {
    out = frame(*hello_);
    hello_.reset();
  } else if (!robots_.empty() || robots_forced_) {
    nlohmann::json list = nlohmann::json::array();
    for (auto& [name, r] : robots_) list.push_back(std::move(r));
    robots_.clear();
    robots_forced_ = false;
    out = frame({{"type", "robots"}, {"robots", std::move(list)}});
  } else if (!tasks_.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (auto& [id, t] : tasks_) list.push_back(std::move(t));
    tasks_.clear();
    out = frame({{"type", "tasks"}, {"tasks", std::move(list)}});
  }
  in_flight_ = out.has_value();
  return out;
}

void PushQueue::sent() { in_flight_ = false; }

}  // namespace fleetmap::web
