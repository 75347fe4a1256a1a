#pragma once
// How an operator command is wired: add_X registers the subcommand's options into an
// Args struct, and the callback runs run_X(args, ctx), whose return value is the exit
// code (app/exit_codes.h). Errors are exceptions, mapped by class (app/exit_code_for.h).
#include <memory>

#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

template <class Args>
void run_with(CLI::App& cmd, std::shared_ptr<Args> args, CliContext& ctx, int (*run)(const Args&, CliContext&)) {
  cmd.callback([args, &ctx, run] { ctx.set_exit_code(run(*args, ctx)); });
}

}  // namespace fleetmap
