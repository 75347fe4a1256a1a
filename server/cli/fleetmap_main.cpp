// fleetmap: the operator command line (maps, robots, goals, tasks, objects, graphs).
// Registers the subcommands and runs the one asked for; exit codes: app/exit_code_for.h.
#include <CLI/CLI.hpp>

#include "app/cli_context.h"
#include "app/run_program.h"
#include "server/cli/gis_commands.h"
#include "server/cli/map_commands.h"
#include "server/cli/nav2_command.h"
#include "server/cli/object_commands.h"
#include "server/cli/plan_command.h"
#include "server/cli/robot_commands.h"
#include "server/cli/scan_command.h"
#include "server/cli/slice_command.h"
#include "server/cli/topo_commands.h"

int main(int argc, char** argv) {
  using namespace fleetmap;
  CLI::App app{"fleetmap: operator command line of the fleetmap map service (maps, robots, goals, tasks)"};
  app.require_subcommand(1);
  app.footer("Exit codes: 0 ok, 1 failure (database, I/O), 2 malformed input, 3 no path, 4 not found or exists, "
             "64 usage.");
  // The connection flags also after the subcommand (`fleetmap robots --config F`): an
  // option a subcommand does not know goes to its parent. Set before the subcommands
  // are added, which inherit it; a subcommand's own option of the same name
  // (`robot add --password-file`: the robot's) still wins.
  app.fallthrough();
  CliContext ctx(Role::Operator);
  ctx.add_connection_options(app);
  add_map_commands(app, ctx);
  add_slice_command(app, ctx);
  add_nav2_command(app, ctx);
  add_plan_command(app, ctx);
  add_robot_commands(app, ctx);
  add_scan_command(app, ctx);
  add_topo_commands(app, ctx);
  add_object_commands(app, ctx);
  add_gis_commands(app, ctx);
  // The command's callback runs inside parse and leaves its exit code in ctx.
  return run_program("fleetmap", app, argc, argv, [&ctx] { return ctx.exit_code(); });
}
