#pragma once
// How every fleetmap program ends: parse the command line, run, and turn an exception
// into its message on standard error and its exit code (app/exit_code_for.h).
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace fleetmap {

// Parses argv into app (which runs the subcommand callbacks), then returns run(). Help
// is printed with exit 0; a parse error with CLI11's message and 64; any exception
// thrown while parsing or running as "program: message" (a FileFormatError's
// "file:line: ..." as is) with exit_code_for's code. program: "fleetmap", ...
int run_program(const std::string& program, CLI::App& app, int argc, char** argv, const std::function<int()>& run);

}  // namespace fleetmap
