// fleetmap-server: the map server daemon. This foundation build only checks its
// database settings; the RR/SA loop comes with the server issue.
#include <iostream>

#include <CLI/CLI.hpp>

#include "protocol/connection.h"
#include "server/cli_context.h"
#include "server/exit_codes.h"

int main(int argc, char** argv) {
  using namespace fleetmap;
  CLI::App app{"fleetmap-server: the fleetmap map server (RR/SA protocol)"};
  CliContext ctx(Role::Server);
  ctx.add_connection_options(app);
  bool check = false;
  app.add_flag("--check", check, "connect with the server account, report, and exit");
  CLI11_PARSE(app, argc, argv);
  try {
    ctx.connection();
    std::cout << "fleetmap-server: connected as " << describe(ctx.settings()) << "\n";
    if (!check) {
      std::cerr << "fleetmap-server: the request loop is not built yet (see the server issue)\n";
      return exit_code::kFailure;
    }
    return exit_code::kOk;
  } catch (const std::exception& e) {
    std::cerr << "fleetmap-server: " << e.what() << "\n";
    return exit_code::kFailure;
  }
}
