#pragma once
// Times the API shows are ISO 8601 in UTC ("2026-12-02T00:36:02.123456Z"), whatever the
// time zone of the database session or of the server. TIMESTAMP columns are stored in
// UTC and shown in the session's zone, so a read that returns them runs with the
// session's zone set to UTC for its duration (and put back after: the reader's
// connections are a pool the next request shares).
#include <string>

#include <mysql++/mysql++.h>

namespace fleetmap::web {

class UtcSession {
 public:
  explicit UtcSession(mysqlpp::Connection& c);
  ~UtcSession();
  UtcSession(const UtcSession&) = delete;
  UtcSession& operator=(const UtcSession&) = delete;

 private:
  mysqlpp::Connection& c_;
};

// "2026-12-02 00:36:02.123456" as read under UtcSession -> "2026-12-02T00:36:02.123456Z";
// "" stays "".
std::string iso8601_utc(const std::string& sql_timestamp);

}  // namespace fleetmap::web
