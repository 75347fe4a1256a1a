#include "server/web/http/sign_in.h"

#include "protocol/connection.h"

namespace fleetmap::web {
namespace {

constexpr int kAccessDenied = 1045, kDbAccessDenied = 1044;

}  // namespace

std::optional<WebRole> web_role_for(const std::string& current_role) {
  // CURRENT_ROLE() quotes the name ("`fleetmap_operator_role`@`%`" on some versions).
  std::string r = current_role;
  std::erase(r, '`');
  if (const size_t at = r.find('@'); at != std::string::npos) r.resize(at);
  if (r == "fleetmap_operator_role") return WebRole::Operator;
  if (r == "fleetmap_inspector_role") return WebRole::Inspector;
  return std::nullopt;
}

SignedIn sign_in(const DbSettings& web, const std::string& user, const std::string& password) {
  if (user.empty() || password.empty()) throw ApiError(401, "unauthorized", "user and password are required", 1);
  auto c = std::make_unique<mysqlpp::Connection>(true);
  try {
    c->set_option(new mysqlpp::SetCharsetNameOption("utf8mb4"));
    c->set_option(new mysqlpp::ConnectTimeoutOption(10));
    const std::string server = web.socket.empty() ? web.host : web.socket;
    c->connect(web.database.c_str(), server.c_str(), user.c_str(), password.c_str(), web.socket.empty() ? web.port : 0);
  } catch (const mysqlpp::ConnectionFailed& e) {
    if (e.errnum() == kAccessDenied) throw ApiError(401, "unauthorized", "wrong user or password", 1);
    if (e.errnum() == kDbAccessDenied)
      throw ApiError(403, "forbidden", "the account '" + user + "' may not use the fleetmap database", 1);
    throw ApiError(503, "unavailable", std::string("the database cannot be reached: ") + e.what(), 1);
  } catch (const mysqlpp::Exception& e) {
    throw ApiError(503, "unavailable", std::string("the database cannot be reached: ") + e.what(), 1);
  }
  std::string role;
  try {
    // The same session settings as every fleetmap program (protocol/connection.h).
    execute(*c, "SET SESSION TRANSACTION ISOLATION LEVEL READ COMMITTED");
    mysqlpp::StoreQueryResult r = c->query("SELECT COALESCE(CURRENT_ROLE(), '')").store();
    if (!r.empty()) role = std::string(r[0][0].data(), r[0][0].length());
  } catch (const mysqlpp::Exception& e) {
    throw ApiError(503, "unavailable", std::string("the database did not answer: ") + e.what(), 1);
  }
  const std::optional<WebRole> web_role = web_role_for(role);
  if (!web_role) {
    c->disconnect();
    throw ApiError(403, "forbidden",
                   "the account '" + user + "' is neither an operator nor an inspector and cannot sign in here", 1);
  }
  return {Principal{user, *web_role}, std::move(c)};
}

}  // namespace fleetmap::web
