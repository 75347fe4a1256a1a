#include "app/cli_context.h"

#include "app/password_file.h"
#include "protocol/connection.h"

namespace fleetmap {

void CliContext::add_connection_options(CLI::App& app) {
  auto* g = app.add_option_group("Connection", "database settings (override the config file and FLEETMAP_*)");
  g->add_option("--config", config_, "config file (default: $FLEETMAP_CONFIG, $FLEETMAP_HOME/fleetmap.conf, "
                                     "./.fleetmap/fleetmap.conf)");
  g->add_option("--host", host_, "database host");
  g->add_option("--port", port_, "database TCP port")->check(CLI::Range(1, 65535));
  g->add_option("--socket", socket_, "database unix socket (preferred over host:port)");
  g->add_option("--database", database_, "database name");
  g->add_option("--user", user_, "database account");
  g->add_option("--password-file", password_file_, "file holding the account's password")->check(CLI::ExistingFile);
}

DbSettings CliContext::settings() const {
  DbSettings s = load_settings(role_, config_);
  if (host_) {
    s.host = *host_;
    if (!socket_) s.socket.clear();  // an explicit host means TCP
  }
  if (port_) s.port = *port_;
  if (socket_) s.socket = *socket_;
  if (database_) s.database = *database_;
  if (user_) s.user = *user_;
  if (password_file_) s.password = read_password_file(*password_file_);
  return s;
}

mysqlpp::Connection& CliContext::connection() {
  if (!conn_) conn_ = connect(settings());
  return *conn_;
}

}  // namespace fleetmap
