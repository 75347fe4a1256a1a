#include "server/cli/nav2_command.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "common/gis/geo_transform.h"
#include "common/gis/grid_png.h"
#include "common/slicing/map_slice.h"
#include "common/slicing/occupancy_grid.h"
#include "common/slicing/scene_laser.h"
#include "protocol/fleet_store.h"
#include "protocol/map_store.h"
#include "protocol/scene_store.h"
#include "app/exit_codes.h"
#include "common/core/error.h"
#include "server/cli/command.h"
#include "server/cli/map_source.h"

namespace fleetmap {
namespace {

// The robot's laser height from its profile (robots.laser_height); none set: the
// default. Throws RobotNotFound.
double robot_laser_height(mysqlpp::Connection& c, const std::string& robot) {
  return FleetStore(c).profile(robot).laser_height.value_or(kDefaultLaserHeight);
}

std::string file_name(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Nav2's keepout tutorial loads its mask in scale mode (keepout_mask.yaml): darkness over
// occupied_thresh is 100 (lethal for KeepoutFilter), under free_thresh 0. A two-valued mask
// (0 and 254) reads the same in trinary mode; scale also leaves room for graded lanes.
std::string keepout_yaml(const OccupancyGrid& mask, const std::string& image) {
  std::string yaml = write_nav2_yaml(mask, image);
  const std::string trinary = "mode: trinary";
  const size_t at = yaml.find(trinary);
  if (at == std::string::npos) throw std::logic_error("write_nav2_yaml wrote no 'mode: trinary'");
  return yaml.replace(at, trinary.size(), "mode: scale");
}

// Writes BASE.pgm or BASE.png (+ its world file) and BASE.yaml; returns the image's size.
uintmax_t write_pair(const OccupancyGrid& grid, const std::string& base, bool keepout, const std::string& image,
                     const std::string& crs_wkt) {
  const std::string file = base + "." + image, yaml = base + ".yaml";
  uintmax_t bytes = 0;
  if (image == "png") {
    bytes = write_grid_png(grid, file, crs_wkt);
  } else {
    const std::string pgm = write_pgm(grid);
    write_output(pgm, file);
    bytes = pgm.size();
  }
  write_output(keepout ? keepout_yaml(grid, file_name(file)) : write_nav2_yaml(grid, file_name(file)), yaml);
  return bytes;
}

// The CRS of the map frame for GIS tools beside a PNG: the base CRS when the map frame is
// it; else none (a rotated or offset frame is no CRS a world file can name).
std::string frame_crs_wkt(const std::optional<MapGeoref>& g) {
  if (!g || !g->frame_is_crs()) return "";
  return GeoTransform(*g).base_wkt();
}

// map nav2 NAME (--robot R | --laser-height H) -o PREFIX
struct MapNav2Args {
  std::string name, robot, out, image = "pgm";
  std::optional<double> height;
  double resolution = 0.05;
};

int run_map_nav2(const MapNav2Args& a, CliContext& ctx) {
  if (a.robot.empty() == !a.height) throw BadInput("expected --robot R or --laser-height H (one of them)");
  const double hL = a.height ? *a.height : robot_laser_height(ctx.connection(), a.robot);
  MapStore store(ctx.connection());
  const Map map = store.load(a.name);
  const std::string crs_wkt = a.image == "png" ? frame_crs_wkt(store.info(a.name).georef) : "";
  const Scene scene = SceneStore(ctx.connection()).load(a.name);
  // The grid: what stops the laser at hL, walls and objects (as `map slice --format pgm`).
  const Map seen = with_objects_at_height(map, scene, hL);
  const OccupancyGrid grid = rasterize_map(slice_at_height(seen, hL), a.resolution);
  // The mask on the same cells (KeepoutFilter reads it in the map's frame, so origin,
  // resolution and size must match the grid's): every avoided area filled, whatever
  // the laser sees of it; a keep-out zone is no wall (docs/semantic-layer.md).
  OccupancyGrid mask = grid;
  std::fill(mask.cells.begin(), mask.cells.end(), OccupancyGrid::kFree);
  for (const AvoidedArea& area : scene.avoided) fill_polygon(mask, area.area, OccupancyGrid::kOccupied);
  const uintmax_t grid_bytes = write_pair(grid, a.out, false, a.image, crs_wkt);
  const uintmax_t mask_bytes = write_pair(mask, a.out + "_keepout", true, a.image, crs_wkt);
  size_t keepout_cells = 0;
  for (uint8_t c : mask.cells) keepout_cells += c == OccupancyGrid::kOccupied;
  const std::string robot = a.robot.empty() ? "" : " (robot " + a.robot + ")";
  std::fprintf(stderr, "nav2 files of '%s' at hL %g m%s: %d x %d cells of %g m, %zu avoided areas (%zu cells): "
               "%s.%s/.yaml (%ju bytes), %s_keepout.%s/.yaml (%ju bytes)\n",
               a.name.c_str(), hL, robot.c_str(), grid.width, grid.height, a.resolution, scene.avoided.size(),
               keepout_cells, a.out.c_str(), a.image.c_str(), grid_bytes, a.out.c_str(), a.image.c_str(), mask_bytes);
  return exit_code::kOk;
}

}  // namespace

void add_nav2_command(CLI::App& app, CliContext& ctx) {
  auto a = std::make_shared<MapNav2Args>();
  // seed 004's per-robot maps, as Nav2 reads them.
  auto* cmd = app.get_subcommand("map")->add_subcommand(
      "nav2",
      "Nav2 files for a robot profile: PREFIX.pgm/.yaml, map_server's occupancy grid at "
      "the laser height with the objects seen there, and PREFIX_keepout.pgm/.yaml, the KeepoutFilter mask of the "
      "avoided areas (black = keep out; costmap_filter_info_server type 0, base 0, multiplier 1)");
  cmd->add_option("NAME", a->name, "stored map name")->required();
  auto* robot = cmd->add_option("--robot", a->robot, "the robot whose profile gives the laser height "
                                                     "(robots.laser_height; none set: 0.3 m)");
  auto* height = cmd->add_option("--laser-height", a->height, "laser mounting height hL (m)")->check(CLI::Range(0.0, 1000.0));
  robot->excludes(height);
  height->excludes(robot);
  cmd->add_option("-o,--output", a->out, "PREFIX of PREFIX.pgm, PREFIX.yaml, PREFIX_keepout.pgm, PREFIX_keepout.yaml")
      ->required();
  cmd->add_option("--image", a->image,
                  "pgm, or png (GDAL's PNG driver, far smaller; with a world file .pgw, and the CRS in .png.aux.xml "
                  "when the map frame is its base CRS)")
      ->check(CLI::IsMember({"pgm", "png"}))
      ->capture_default_str();
  cmd->add_option("--resolution", a->resolution, "metres per cell")->capture_default_str()->check(CLI::PositiveNumber);
  run_with(*cmd, a, ctx, run_map_nav2);
}

}  // namespace fleetmap
