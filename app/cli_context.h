#pragma once
// What every operator command shares: connection flags (over config file and
// environment, protocol/db_settings.h) and opening the connection once asked.
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <mysql++/mysql++.h>

#include "protocol/db_settings.h"

namespace fleetmap {

class CliContext {
 public:
  explicit CliContext(Role role) : role_(role) {}

  // --config, --host, --port, --socket, --database, --user, --password-file on app.
  void add_connection_options(CLI::App& app);

  DbSettings settings() const;
  mysqlpp::Connection& connection();  // connects on first use

 private:
  Role role_;
  std::optional<std::string> config_, host_, socket_, database_, user_, password_file_;
  std::optional<unsigned> port_;
  std::unique_ptr<mysqlpp::Connection> conn_;
};

}  // namespace fleetmap
