#include "protocol/connection.h"

namespace fleetmap {

std::string describe(const DbSettings& s) {
  const std::string where = s.socket.empty() ? s.host + ":" + std::to_string(s.port) : s.socket;
  return (s.user.empty() ? std::string("(no user)") : s.user) + "@" + where + "/" + s.database;
}

std::unique_ptr<mysqlpp::Connection> connect(const DbSettings& s, bool multi_statements) {
  auto c = std::make_unique<mysqlpp::Connection>(true);
  try {
    c->set_option(new mysqlpp::SetCharsetNameOption("utf8mb4"));
    c->set_option(new mysqlpp::ConnectTimeoutOption(10));
    if (multi_statements) c->set_option(new mysqlpp::MultiStatementsOption(true));
    const std::string server = s.socket.empty() ? s.host : s.socket;
    c->connect(s.database.c_str(), server.c_str(), s.user.c_str(), s.password.c_str(),
               s.socket.empty() ? s.port : 0);
    execute(*c, "SET SESSION TRANSACTION ISOLATION LEVEL READ COMMITTED");
  } catch (const mysqlpp::Exception& e) {
    throw DbError("cannot connect as " + describe(s) + (s.source.empty() ? "" : " (settings from " + s.source + ")") +
                  ": " + e.what());
  }
  return c;
}

void execute(mysqlpp::Connection& c, const std::string& sql) {
  mysqlpp::Query q = c.query(sql);
  q.execute();
}

Transaction::Transaction(mysqlpp::Connection& c) : c_(c) { execute(c_, "START TRANSACTION"); }

Transaction::~Transaction() {
  if (!done_) {
    try {
      execute(c_, "ROLLBACK");
    } catch (...) {  // the connection may be gone; the server rolls back on disconnect
    }
  }
}

void Transaction::commit() {
  execute(c_, "COMMIT");
  done_ = true;
}

}  // namespace fleetmap
