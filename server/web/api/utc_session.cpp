#include "server/web/api/utc_session.h"

#include "protocol/connection.h"

namespace fleetmap::web {

UtcSession::UtcSession(mysqlpp::Connection& c) : c_(c) {
  execute(c_, "SET @fleetmap_web_saved_tz = @@SESSION.time_zone, SESSION time_zone = '+00:00'");
}

UtcSession::~UtcSession() {
  try {
    execute(c_, "SET SESSION time_zone = @fleetmap_web_saved_tz");
  } catch (...) {  // the connection is gone, and its session with it
  }
}

std::string iso8601_utc(const std::string& t) {
  if (t.empty()) return t;
  std::string out = t;
  if (const size_t space = out.find(' '); space != std::string::npos) out[space] = 'T';
  return out + "Z";
}

}  // namespace fleetmap::web
