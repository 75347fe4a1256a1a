#pragma once
// Signed-in people (SPEC 4): each session holds that person's own database connection,
// on which every write of theirs runs, and its CSRF token. Sessions end on logout, after
// session_idle_s without a request, or never begin when max_sessions are open.
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <mysql++/mysql++.h>

#include "server/web/api/api.h"

namespace fleetmap::web {

using Clock = std::chrono::steady_clock;

struct Session {
  std::string id;    // the cookie's value: 256 random bits, hex
  std::string csrf;  // X-CSRF-Token of every write: another 256 bits
  Principal who;
  std::unique_ptr<mysqlpp::Connection> connection;  // the person's own
  std::mutex connection_mutex;  // one request at a time on it (ApiContext::writer())
};

class SessionStore {
 public:
  SessionStore(std::chrono::seconds idle, size_t max_sessions) : idle_(idle), max_(max_sessions) {}

  // A new session for who, owning connection; throws ApiError 503 (too_many_sessions)
  // when max_sessions are open after the idle ones were dropped.
  std::shared_ptr<Session> open(Principal who, std::unique_ptr<mysqlpp::Connection> connection,
                                Clock::time_point now = Clock::now());
  // The session with this id, its idle clock restarted; null when unknown or idle too long.
  std::shared_ptr<Session> find(const std::string& id, Clock::time_point now = Clock::now());
  void close(const std::string& id);
  // Drops the sessions idle too long; returns how many.
  size_t expire(Clock::time_point now = Clock::now());
  size_t size() const;

 private:
  struct Entry {
    std::shared_ptr<Session> session;
    Clock::time_point last_used;
  };
  std::chrono::seconds idle_;
  size_t max_;
  mutable std::mutex mutex_;
  std::map<std::string, Entry> sessions_;
};

}  // namespace fleetmap::web
