// fleetmap-robot: the simulated robot. A placeholder until the robot issue: it only
// documents its options.
#include <iostream>

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"fleetmap-robot: simulated robot for the fleetmap map service (not built yet: see the robot issue)"};
  CLI11_PARSE(app, argc, argv);
  std::cerr << "fleetmap-robot: not implemented yet\n";
  return 1;
}
