#pragma once
// Login (SPEC 4): a MariaDB connection opened with exactly the credentials a person typed,
// to the web program's own server and database; the database's answer to
// CURRENT_ROLE() says who they are. No second user store.
#include <memory>
#include <optional>
#include <string>

#include <mysql++/mysql++.h>

#include "protocol/db_settings.h"
#include "server/web/api/api.h"

namespace fleetmap::web {

// fleetmap_operator_role -> Operator, fleetmap_inspector_role -> Inspector; any other
// role (robots, the server, the web account itself, none) -> nullopt.
std::optional<WebRole> web_role_for(const std::string& current_role);

struct SignedIn {
  Principal who;
  std::unique_ptr<mysqlpp::Connection> connection;  // the person's own, kept by the session
};

// Connects as user/password with web's host, port, socket and database. Throws ApiError:
// 401 (unauthorized) for refused credentials, 403 (forbidden) for an account that is
// neither an operator nor an inspector (its connection closed), 503 (unavailable) when
// the database cannot be reached.
SignedIn sign_in(const DbSettings& web, const std::string& user, const std::string& password);

}  // namespace fleetmap::web
