#pragma once
// ApiContext for one request (server/web/api/api.h): a reader leased from the pool when
// first asked for, and the signed-in person's own connection as the writer, held
// exclusively until the request is answered.
#include <memory>
#include <mutex>
#include <optional>

#include "server/web/api/api.h"
#include "server/web/http/reader_pool.h"
#include "server/web/http/session_store.h"

namespace fleetmap::web {

class WebApiContext : public ApiContext {
 public:
  WebApiContext(ReaderPool& readers, std::shared_ptr<Session> session, const ServerConfig& planning)
      : readers_(readers), session_(std::move(session)), planning_(planning) {}

  mysqlpp::Connection& reader() override;
  // Throws ApiError 403 for an inspector (SPEC 4: inspectors only read), 401 when the
  // session's connection was lost (the person signs in again).
  mysqlpp::Connection& writer() override;
  const ServerConfig& planning_defaults() const override { return planning_; }

 private:
  ReaderPool& readers_;
  std::shared_ptr<Session> session_;
  const ServerConfig& planning_;
  std::optional<ReaderPool::Lease> reader_;
  std::unique_lock<std::mutex> writer_lock_;
};

}  // namespace fleetmap::web
