#include "app/run_program.h"

#include <iostream>

#include "app/exit_code_for.h"
#include "common/core/error.h"

namespace fleetmap {

int run_program(const std::string& program, CLI::App& app, int argc, char** argv, const std::function<int()>& run) {
  try {
    app.parse(argc, argv);
    return run();
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // help on stdout, or CLI11's message on stderr
    return exit_code_for(e);
  } catch (const std::exception& e) {
    if (dynamic_cast<const FileFormatError*>(&e)) std::cerr << e.what() << "\n";
    else std::cerr << program << ": " << error_message(e) << "\n";
    return exit_code_for(e);
  }
}

}  // namespace fleetmap
