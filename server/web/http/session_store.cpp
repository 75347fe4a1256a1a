#include "server/web/http/session_store.h"

#include "server/web/http/tokens.h"

namespace fleetmap::web {

std::shared_ptr<Session> SessionStore::open(Principal who, std::unique_ptr<mysqlpp::Connection> connection,
                                            Clock::time_point now) {
  auto s = std::make_shared<Session>();
  s->id = random_token();
  s->csrf = random_token();
  s->who = std::move(who);
  s->connection = std::move(connection);
  expire(now);
  std::lock_guard lock(mutex_);
  if (sessions_.size() >= max_)
    throw ApiError(503, "too_many_sessions",
                   "too many people are signed in (max_sessions = " + std::to_string(max_) + "); try again later", 1);
  sessions_[s->id] = {s, now};
  return s;
}

std::shared_ptr<Session> SessionStore::find(const std::string& id, Clock::time_point now) {
  std::lock_guard lock(mutex_);
  auto it = sessions_.find(id);
  if (it == sessions_.end()) return nullptr;
  if (now - it->second.last_used > idle_) {
    sessions_.erase(it);
    return nullptr;
  }
  it->second.last_used = now;
  return it->second.session;
}

void SessionStore::close(const std::string& id) {
  std::lock_guard lock(mutex_);
  sessions_.erase(id);
}

size_t SessionStore::expire(Clock::time_point now) {
  std::lock_guard lock(mutex_);
  size_t n = 0;
  for (auto it = sessions_.begin(); it != sessions_.end();) {
    if (now - it->second.last_used > idle_) {
      it = sessions_.erase(it);
      ++n;
    } else {
      ++it;
    }
  }
  return n;
}

size_t SessionStore::size() const {
  std::lock_guard lock(mutex_);
  return sessions_.size();
}

}  // namespace fleetmap::web
