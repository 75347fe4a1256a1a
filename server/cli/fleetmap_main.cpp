// fleetmap: the operator command line (maps now; robots, goals and tasks with the
// server issue). Parses options and calls library code; exit codes in exit_codes.h.
#include <iostream>

#include <CLI/CLI.hpp>

#include "common/io/seed_format.h"
#include "protocol/connection.h"
#include "protocol/map_store.h"
#include "app/cli_context.h"
#include "app/exit_codes.h"
#include "server/cli/map_commands.h"
#include "server/cli/nav2_command.h"
#include "server/cli/object_commands.h"
#include "server/cli/plan_command.h"
#include "server/cli/robot_commands.h"
#include "server/cli/scan_command.h"
#include "server/cli/slice_command.h"
#include "server/cli/topo_commands.h"
#include "protocol/fleet_store.h"

int main(int argc, char** argv) {
  using namespace fleetmap;
  CLI::App app{"fleetmap: operator command line of the fleetmap map service (maps, robots, goals, tasks)"};
  app.require_subcommand(1);
  app.footer("Exit codes: 0 ok, 1 failure (database, I/O), 2 malformed input, 4 not found or exists, 64 usage.");
  CliContext ctx(Role::Operator);
  ctx.add_connection_options(app);
  int code = exit_code::kOk;
  add_map_commands(app, ctx, &code);
  add_slice_command(app, ctx, &code);
  add_nav2_command(app, ctx, &code);
  add_plan_command(app, ctx, &code);
  add_robot_commands(app, ctx, &code);
  add_scan_command(app, ctx, &code);
  add_topo_commands(app, ctx, &code);
  add_object_commands(app, ctx, &code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return exit_code::kUsage;
  } catch (const MapFormatError& e) {
    std::cerr << e.what() << "\n";
    return exit_code::kBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "fleetmap: " << e.what() << "\n";
    return exit_code::kBadInput;
  } catch (const RobotNotFound& e) {
    std::cerr << "fleetmap: " << e.what() << "\n";
    return exit_code::kNotFound;
  } catch (const MapNotFound& e) {
    std::cerr << "fleetmap: " << e.what() << "\n";
    return exit_code::kNotFound;
  } catch (const MapExists& e) {
    std::cerr << "fleetmap: " << e.what() << "\n";
    return exit_code::kNotFound;
  } catch (const mysqlpp::Exception& e) {
    std::cerr << "fleetmap: database error: " << e.what() << "\n";
    return exit_code::kFailure;
  } catch (const std::exception& e) {
    std::cerr << "fleetmap: " << e.what() << "\n";
    return exit_code::kFailure;
  }
  return code;
}
