#pragma once
// Opening a MySQL++ connection from DbSettings, with the session settings every
// fleetmap program relies on.
#include <memory>
#include <stdexcept>
#include <string>

#include <mysql++/mysql++.h>

#include "common/core/error.h"
#include "protocol/db_settings.h"

namespace fleetmap {

// A database problem a person can act on: names the server and account.
class DbError : public Failure {
 public:
  using Failure::Failure;
};

// Throws DbError when there is no account to connect as: no config file was found and
// no --user given (the message says where the file was looked for), or the file's role
// section names none. connect() asks it first.
void check_account(const DbSettings& s);

// Connects (utf8mb4, READ COMMITTED: a server's SELECT ... FOR UPDATE must not take gap
// locks that block robots' inserts, SPEC 9). Throws DbError, whose message says what
// to do when the server is down (its socket missing, nothing listening) or the account
// is refused. multi_statements lets one
// round trip carry several statements (the server's batched writes, protocol/write_batch.h).
std::unique_ptr<mysqlpp::Connection> connect(const DbSettings& s, bool multi_statements = false);

// Where a connection goes, for logs: "fleetmap_operator@/path/sock/fleetmap".
std::string describe(const DbSettings& s);

// Runs statements that return no rows (START TRANSACTION, COMMIT, ...).
void execute(mysqlpp::Connection& c, const std::string& sql);

// RAII transaction: rolls back unless commit() was called.
class Transaction {
 public:
  explicit Transaction(mysqlpp::Connection& c);
  ~Transaction();
  void commit();
  // The COMMIT went out another way (a multi-statement, protocol/write_batch.h).
  void committed_by_batch() { done_ = true; }
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;

 private:
  mysqlpp::Connection& c_;
  bool done_ = false;
};

}  // namespace fleetmap
