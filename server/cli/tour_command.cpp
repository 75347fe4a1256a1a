#include "server/cli/tour_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

#include "app/exit_codes.h"
#include "common/core/error.h"
#include "common/geometry/number_format.h"
#include "common/io/topo_json.h"
#include "common/planning/tour_builder.h"
#include "protocol/fleet_store.h"
#include "protocol/map_store.h"
#include "protocol/topo_store.h"
#include "protocol/tour_store.h"
#include "server/cli/command.h"

namespace fleetmap {
namespace {

struct TourBuildArgs {
  std::string map, robot, tour;
  double merge = 1.5;
  bool replace = false, dry_run = false;
};

// "4 crossing, 3 corridor (2 centred), 1 place"
std::string count_kinds(const TourGraph& t) {
  std::map<TourEventKind, std::pair<size_t, size_t>> by_kind;  // nodes, measured
  for (size_t i = 0; i < t.kinds.size(); ++i) {
    ++by_kind[t.kinds[i]].first;
    by_kind[t.kinds[i]].second += t.measured[i];
  }
  std::string s;
  for (auto [k, c] : by_kind) {
    s += (s.empty() ? "" : ", ") + std::to_string(c.first) + " " + std::string(to_string(k));
    if (k == TourEventKind::EnterCorridor || k == TourEventKind::Door || k == TourEventKind::Crossing)
      s += " (" + std::to_string(c.second) + " centred)";
  }
  return s;
}

int run_tour_build(const TourBuildArgs& a, CliContext& ctx) {
  if (!std::isfinite(a.merge) || a.merge < 0) throw BadInput("expected --merge >= 0 metres");
  mysqlpp::Connection& c = ctx.connection();
  const unsigned robot_id = FleetStore(c).robot_id(a.robot);
  const std::vector<TourEvent> events = TourStore(c).load(robot_id, a.tour);
  if (events.empty())
    throw NotFound("robot '" + a.robot + "' has no events in tour '" + a.tour +
                   "'; see 'fleetmap topo tour list --robot " + a.robot + "'");
  const Map map = MapStore(c).load(a.map);
  const TourGraph t = build_tour_graph(map, events, {.merge_distance = a.merge});
  const TopoGraph& g = t.graph;
  std::cerr << events.size() << " events -> " << g.nodes().size() << " nodes: " << count_kinds(t) << "; "
            << g.edges().size() << " edges\n";
  if (a.dry_run) {
    std::cout << write_topo_json(g);
    return exit_code::kOk;
  }
  const std::string source = "tour '" + a.tour + "' of robot '" + a.robot + "'";
  TopoStore(c).import(a.map, g, source, a.replace);
  std::cout << "built graph of '" << a.map << "' from " << source << ": " << g.nodes().size() << " nodes, "
            << g.edges().size() << " edges\n";
  return exit_code::kOk;
}

struct TourListArgs {
  std::string robot;
};

int run_tour_list(const TourListArgs& a, CliContext& ctx) {
  mysqlpp::Connection& c = ctx.connection();
  for (const TourSummary& s : TourStore(c).tours(FleetStore(c).robot_id(a.robot)))
    std::printf("%s\t%zu events\t%s .. %s\n", s.tour.empty() ? "(default)" : s.tour.c_str(), s.events,
                s.first_at.c_str(), s.last_at.c_str());
  return exit_code::kOk;
}

}  // namespace

void add_topo_tour_commands(CLI::App& topo, CliContext& ctx) {
  auto* tour = topo.add_subcommand("tour", "topological maps acquired on a guided tour (seed 003)");
  tour->require_subcommand(1);

  auto b = std::make_shared<TourBuildArgs>();
  auto* build = tour->add_subcommand("build", "build a map's graph from a robot's tour events and store it");
  build->add_option("MAP", b->map, "name of the stored map the tour was on")->required();
  build->add_option("--robot", b->robot, "the robot that was shown around")->required();
  build->add_option("--tour", b->tour, "the tour's name (TourEvent params.tour; default: the unnamed tour)");
  build->add_option("--merge", b->merge, "metres: an event this close to a node of its kind re-uses the node")
      ->capture_default_str();
  build->add_flag("--replace", b->replace, "replace the map's graph if it has one");
  build->add_flag("--dry-run", b->dry_run, "print the graph as navigation JSON, store nothing");
  run_with(*build, b, ctx, run_tour_build);

  auto l = std::make_shared<TourListArgs>();
  auto* list = tour->add_subcommand("list", "a robot's tours: name, events, first and last time");
  list->add_option("--robot", l->robot, "robot name")->required();
  run_with(*list, l, ctx, run_tour_list);
}

}  // namespace fleetmap
