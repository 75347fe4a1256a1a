#include "server/web/http/web_api_context.h"

namespace fleetmap::web {

mysqlpp::Connection& WebApiContext::reader() {
  if (!reader_) reader_.emplace(readers_.acquire());
  return **reader_;
}

mysqlpp::Connection& WebApiContext::writer() {
  if (!session_) throw ApiError(401, "unauthorized", "sign in first (POST /api/login)", 1);
  if (session_->who.role != WebRole::Operator)
    throw ApiError(403, "forbidden", "'" + session_->who.user + "' is an inspector: inspectors may only read", 1);
  if (!writer_lock_.owns_lock()) {
    writer_lock_ = std::unique_lock(session_->connection_mutex);
    // The password is not kept, so a dropped connection cannot be reopened here.
    if (!session_->connection || !session_->connection->ping())
      throw ApiError(401, "session_lost", "the database connection of this session was lost; sign in again", 1);
  }
  return *session_->connection;
}

}  // namespace fleetmap::web
