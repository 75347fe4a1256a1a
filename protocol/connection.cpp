#include "protocol/connection.h"

#include <filesystem>

namespace fleetmap {

std::string describe(const DbSettings& s) {
  const std::string where = s.socket.empty() ? s.host + ":" + std::to_string(s.port) : s.socket;
  return (s.user.empty() ? std::string("(no user)") : s.user) + "@" + where + "/" + s.database;
}

namespace {

// Client error numbers of libmariadb (errmsg.h) and the server's (mysqld_error.h) that a
// person can act on.
constexpr int kNoSocket = 2002, kNoTcp = 2003, kUnknownHost = 2005, kAccessDenied = 1045, kUnknownDatabase = 1049;

std::string hint(int errnum) {
  switch (errnum) {
    case kNoSocket:
    case kNoTcp:
      return ": the database server is not running or not listening there (scripts/db.sh status)";
    case kUnknownHost: return ": no such host";
    case kAccessDenied: return ": the account or its password is wrong";
    case kUnknownDatabase: return ": no such database (load sql/ into it, or fix [database] name)";
  }
  return "";
}

}  // namespace

void check_account(const DbSettings& s) {
  // Without an account libmariadb would log in as the operating system's user, on the
  // default port: refuse rather than reach some other server as root.
  if (s.user.empty()) {
    if (s.source.empty())
      throw DbError("no config file found (looked for " + config_search_path() +
                    ") and no account given (--user, FLEETMAP_USER); start the private instance with scripts/db.sh "
                    "start, or pass --config FILE");
    throw DbError("no database account: " + s.source + " has no 'user' in its [" + s.section +
                  "] section, and none was given (--user, FLEETMAP_USER)");
  }
}

std::unique_ptr<mysqlpp::Connection> connect(const DbSettings& s, bool multi_statements) {
  check_account(s);
  const std::string from = s.source.empty() ? "" : " (settings from " + s.source + ")";
  // MySQL++ takes a missing socket file for a host name ("Bad character '/' in TCP/IP
  // address"): a socket that is not there means the server is not running.
  if (!s.socket.empty() && !std::filesystem::exists(s.socket))
    throw DbError("cannot connect as " + describe(s) + from + ": the socket " + s.socket +
                  " does not exist: the database server is not running (scripts/db.sh start)");
  auto c = std::make_unique<mysqlpp::Connection>(true);
  try {
    c->set_option(new mysqlpp::SetCharsetNameOption("utf8mb4"));
    c->set_option(new mysqlpp::ConnectTimeoutOption(10));
    if (multi_statements) c->set_option(new mysqlpp::MultiStatementsOption(true));
    const std::string server = s.socket.empty() ? s.host : s.socket;
    c->connect(s.database.c_str(), server.c_str(), s.user.c_str(), s.password.c_str(),
               s.socket.empty() ? s.port : 0);
    execute(*c, "SET SESSION TRANSACTION ISOLATION LEVEL READ COMMITTED");
  } catch (const mysqlpp::ConnectionFailed& e) {
    throw DbError("cannot connect as " + describe(s) + from + ": " + e.what() + hint(e.errnum()));
  } catch (const mysqlpp::Exception& e) {
    throw DbError("cannot connect as " + describe(s) + from + ": " + e.what());
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
