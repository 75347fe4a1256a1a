#pragma once
// What every operator command shares: connection flags (over config file and
// environment, protocol/db_settings.h), opening the connection once asked, and the exit
// code of the command that ran.
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
  // --config as given (nullopt: the file is found as find_config_file says).
  const std::optional<std::string>& config_path() const { return config_; }
  mysqlpp::Connection& connection();  // connects on first use

  // Set by the command that ran (its callback runs inside CLI::App::parse); main returns it.
  void set_exit_code(int code) { exit_code_ = code; }
  int exit_code() const { return exit_code_; }

 private:
  Role role_;
  std::optional<std::string> config_, host_, socket_, database_, user_, password_file_;
  std::optional<unsigned> port_;
  std::unique_ptr<mysqlpp::Connection> conn_;
  int exit_code_ = 0;
};

}  // namespace fleetmap
