// Onboard localization benchmark (SPEC 6, 8; seed 000 section 4.1): the particle filter
// with the seed's parameters (NP 6000, NL 131 over 180 degrees, RMAX 15 m, sigma_L 5 cm,
// alpha 1, beta 0.1, sigma_m 0.5 m, compass +-3 degrees) on real maps, simulated sensors,
// in three configurations (client/sim/localization_trials.h, the runner that
// `fleetmap-robot --trials` shares): `seed` (eq. 5-6 as written,
// ParticleFilterOptions::seed_model, the baseline), `robust` (beam product with a floor,
// tempering) and `search` (robust_search: robust with the global search, the robot's
// default).
//
//  1. global localization: the share of trials within 0.3 m and 3 degrees after at most
//     10 updates; the seed's figure: Fig. 5, one run, four iterations.
//  2. tracking: RMS and maximum error along a 200 m drive beside dead reckoning;
//  3. update rate: one update of NP particles x NL rays on `threads` threads (the seed's
//     model, one pass), for a tracking cloud and a global one, with the fast caster and
//     with the seed's bounding-circle caster (the seed's method), the baseline.
// Targets: >= 95 % converged, RMS < 0.10 m; the update rate is reported.
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/maps_dir.h"
#include "client/sim/drive_simulator.h"
#include "client/sim/laser_simulator.h"
#include "client/sim/localization_trials.h"
#include "client/localization/particle_filter.h"
#include "common/raycast/grid_ray_caster.h"
#include "common/raycast/seed_ray_caster.h"

namespace {

using namespace fleetmap;
using namespace fleetmap::localization;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Median seconds of one update of NP particles: a global cloud (uniform over the map) or
// a tracking one (N(truth, 0.1 m, 2 degrees)), the same cloud and scan each time.
double update_seconds(const Map& map, std::shared_ptr<const RayCaster> caster, std::shared_ptr<const RayCaster> world,
                      const TrialSettings& s, size_t particles, int repeats, bool global_cloud) {
  ParticleFilterOptions fo = ParticleFilterOptions::seed_model();
  fo.particles = particles;
  fo.threads = s.filter.threads;
  fo.resample_threshold = 0;  // time the sensor update alone
  ParticleFilter pf(map, std::move(caster), fo);
  std::mt19937_64 rng(s.seed);
  const FreeSpace free_space(map);
  LaserSimulator laser(world, s.laser, s.seed);
  const Pose truth = pick_start_pose(free_space, *world, laser.beam_angles(), s.min_hit_fraction, 0.5, rng);
  if (global_cloud) pf.init_global(truth.theta);
  else pf.init_pose(truth, 0.1, deg2rad(2.0));
  const std::vector<double> scan = laser.scan(truth);
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    pf.update(scan, truth.theta);
    times.push_back(seconds_since(t0));
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

// A table row's map name: the file's name without its directory, or "gen:KIND".
std::string map_label(const std::string& path) {
  if (path.rfind("gen:", 0) == 0) return path;
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

void bench_map(const std::string& path, const TrialSettings& base, const std::vector<std::string>& configs,
               bool skip_global, bool skip_tracking, bool skip_rate, std::vector<TableRow>& rows) {
  const Map map = load_map_file(path);
  std::shared_ptr<const RayCaster> world = std::make_shared<GridRayCaster>(map, base.filter.laser);
  report_map_header(stdout, path, map, base);
  TrialSettings s = base;  // every preset's trials on this map share their starts' twin checks
  s.twin_cache = std::make_shared<TwinCache>();
  for (const std::string& c : configs) {
    if (auto g = report_preset(stdout, map, world, s, c, !skip_global, !skip_tracking))
      rows.push_back({map_label(path), c, std::move(*g)});
    if (base.kidnaps > 0 || base.false_alarm_drive > 0) {
      TrialSettings k = base;
      k.filter = trial_filter(base, c);
      report_kidnap(stdout, map, world, k);
    }
  }
  if (skip_rate) return;
  // The seed's method is timed on 300 particles and scaled: it is that much slower.
  const size_t np = base.filter.particles, seed_np = 300;
  auto seed_caster = std::make_shared<SeedRayCaster>(map, base.filter.laser);
  for (bool global_cloud : {false, true}) {
    const double fast = update_seconds(map, world, world, base, np, 7, global_cloud);
    const double seed = update_seconds(map, seed_caster, world, base, seed_np, 3, global_cloud) * np / seed_np;
    std::printf("update rate, NP %zu x NL %d on %d threads, %s cloud: %.1f Hz (%.1f ms); baseline, the seed's "
                "bounding-circle caster: %.2f Hz (timed on %zu particles, scaled)\n",
                np, base.filter.beams, base.filter.threads, global_cloud ? "global  " : "tracking", 1 / fast, 1e3 * fast,
                1 / seed, seed_np);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench-localization: particle filter global localization, tracking and update rate (seed 000 4.1)"};
  std::vector<std::string> maps;
  TrialSettings s;
  std::string config = "all";
  bool skip_global = false, skip_tracking = false, skip_rate = false;
  app.add_option("--map", maps,
                 "maps (AMRL .vectormap.txt, seed .map, or generated: gen:offices, gen:corridor, gen:hall, "
                 "gen:clutter, with an optional :SEED); default GDC1 and UT_Campus in " + maps_dir());
  app.add_option("--trials", s.trials, "global localization trials per map")
      ->check(CLI::Range(0, 1000000000))
      ->capture_default_str();
  app.add_option("--first-trial", s.first_trial,
                 "index of the first trial: each trial's start and draws depend on the seed and its index alone, so "
                 "--first-trial 114 --trials 1 runs trial 114 again")
      ->check(CLI::Range(0, 1000000000))
      ->capture_default_str();
  app.add_option("--seed", s.seed, "seed of every random draw")->capture_default_str();
  app.add_option("--particles", s.filter.particles, "NP")->capture_default_str();
  app.add_option("--updates", s.updates, "updates allowed to converge")->capture_default_str();
  app.add_option("--look-around", s.look_around,
                 "global localization: first steps turning in place (0: wander from the first scan)")
      ->capture_default_str();
  double turn_deg = 60;
  app.add_option("--look-around-turn", turn_deg, "degrees turned per look-around step")->capture_default_str();
  app.add_option("--global-step", s.global_step, "global localization: metres driven between scans after the look around")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  // The search and tempering overrides leave the `seed` preset alone: it is the baseline.
  app.add_option("--search-updates", s.search_updates,
                 "ParticleFilterOptions::search_updates for every preset but seed (default: the preset's); after a "
                 "deferred look around, 2 or more search once, at the first step driven, on every scan")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--search-candidates", s.search_candidates,
                 "places the global search reranks on cast rays, for every preset but seed (default: the preset's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--search-clusters", s.search_clusters,
                 "of those, the places that get particles, for every preset but seed (default: the preset's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--search-particles", s.search_particles,
                 "particles spread over those places, for every preset but seed (default: the preset's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--tempering-ess", s.tempering_ess,
                 "adaptive tempering's share of effective particles, for every preset but seed (0: none; default: "
                 "the preset's)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--tempering-stages", s.tempering_stages,
                 "annealing stages per scan, for every preset but seed (default: the preset's)")
      ->check(CLI::Range(1, 100));
  app.add_option("--settle-after", s.settle_after,
                 "update after which every scan since init is searched at once and the cloud settles on the best "
                 "places, for every preset but seed (0: never; default: the preset's)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--search-sigma", s.search_sigma,
                 "the global search's likelihood field: metres of tolerance, for every preset but seed (default: the "
                 "preset's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--search-max-penalty", s.search_max_penalty,
                 "the likelihood field's floor per point (log-likelihood), for every preset but seed (default: the "
                 "preset's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--search-drops-foreground", s.search_drops_foreground,
                 "1: the searches leave out returns in front of the map (people; foreground.h), 0: they keep them, for "
                 "every preset but seed (default: the preset's)")
      ->check(CLI::Range(0, 1));
  app.add_option("--short-only-foreground", s.short_only_foreground,
                 "1: --short-beyond applies only to returns in front of the map (people; foreground.h), 0: to every "
                 "beam, for every preset (default: the preset's)")
      ->check(CLI::Range(0, 1));
  app.add_option("--search-short-only-foreground", s.search_short_only_foreground,
                 "1: the search's rerank and the weighing of its cloud let only returns in front of the map stop "
                 "short, 0: as the sensor model, for every preset but seed (default: the preset's)")
      ->check(CLI::Range(0, 1));
  app.add_option("--foreground-width", s.foreground_width,
                 "metres: the widest run of returns counted as foreground (default: the preset's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--rivals", s.rivals,
                 "1: the ambiguity verdict also scores the last search's best places the cloud lost (ambiguity.h), "
                 "0: only the cloud's, for every preset but seed (default: the preset's)")
      ->check(CLI::Range(0, 1));
  app.add_option("--drop-ruled-out-rivals", s.drop_ruled_out_rivals,
                 "1: a rival worse than the converged cloud's place by more than --rival-drop-margin on a full "
                 "window of recent scans is dropped for good (ambiguity.h), 0: it is judged again at every verdict, "
                 "for every preset but seed (default: the preset's)")
      ->check(CLI::Range(0, 1));
  app.add_option("--rival-drop-margin", s.rival_drop_margin_z2,
                 "per beam of the residual: how much worse than the cloud's place a rival must fit to be dropped "
                 "(ambiguity.h), for every preset but seed (default: the preset's)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--register-scans", s.register_scans,
                 "1: the rivals are judged with each recent scan registered at the best place (ambiguity.h), 0: on the "
                 "scans as the odometry stitches them, for every preset but seed (default: the preset's)")
      ->check(CLI::Range(0, 1));
  app.add_option("--register-moves-place", s.register_moves_place,
                 "1: when the ambiguity verdict would keep another place, its reference is moved to where its "
                 "registered scans fit best and the others judged again (not among people, nor beyond 0.3 m of the "
                 "reported place; ambiguity.h), 0: never moved, for every preset but seed (default: the preset's)")
      ->check(CLI::Range(0, 1));
  app.add_option("--rival-margin", s.rival_margin_z2,
                 "per beam: a place whose residual is within this of the best place's stays beside it in the "
                 "ambiguity verdict (ambiguity.h), for every preset but seed (default: the preset's)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--candidates-by-residual", s.candidates_by_residual,
                 "1: the cloud's places other than the heaviest and the best are judged by the registered residual, as "
                 "the rivals are (ambiguity.h), 0: by the tempered score's margin, for every preset but seed (default: "
                 "the preset's)")
      ->check(CLI::Range(0, 1));
  app.add_option("--turn-in-place-sds", s.turn_in_place_sds,
                 "a step is a turn in place (the look around goes on, its turn registered on the scans) while its "
                 "translation is below 5 cm plus this many standard deviations of the motion model's translation for "
                 "its turn, for every preset but seed (0: 5 cm alone; default: the preset's)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--roughening-max-xy", s.roughening_max_xy,
                 "metres: the cap of roughening's jitter in x and y, for every preset but seed (default: the preset's, "
                 "0.2)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--roughening-stage-decay", s.roughening_stage_decay,
                 "roughening's jitter (capped) at a scan's s-th annealing stage is multiplied by this to the power s, "
                 "for every preset but seed (1: the same at every stage; default: the preset's)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--kld-min-particles", s.kld_min_particles,
                 "KLD sampling's fewest particles, the global phase's and tracking's where --tracking-min-particles "
                 "is lower, for every preset but seed (default: the preset's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--tracking-sigma-m", s.tracking_sigma_m,
                 "metres: the sensor model's sigma_m from a known pose on (tracking), for every preset but seed "
                 "(default: the preset's; without one, sigma_m throughout)")
      ->check(CLI::PositiveNumber);
  app.add_option("--tracking-min-particles", s.tracking_min_particles,
                 "KLD sampling's fewest particles from a known pose on (tracking), for every preset but seed "
                 "(default: the preset's; 1: the global phase's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--kld-bin-xy", s.kld_bin_xy,
                 "metres: KLD sampling's bin in x and y, for every preset but seed (default: the preset's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--kld-bin-theta", s.kld_bin_theta_deg,
                 "degrees: KLD sampling's bin in heading, for every preset but seed (default: the preset's)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--tracking-fixed,!--no-tracking-fixed", s.tracking_fixed,
               "tracking drives a cloud of NP fixed particles beside the KLD one (default on)");
  app.add_option("--lost-floor", s.lost.floor,
                 "the lost detector's floor: lost when the fast average of the scans' agreement stays below it (and "
                 "below ratio x the slow average) for hold updates")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--lost-ratio", s.lost.ratio,
                 "the lost detector's ratio: lost when the fast average stays below this x the slow one (and below "
                 "the floor) for hold updates")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--lost-tolerance", s.lost.tolerance,
                 "metres: a beam agrees with the estimate when its reading is within this of the ray cast from it "
                 "(the lost detector)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--lost-hold", s.lost.hold, "updates the lost detector's fast average must stay low")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--lost-fast-alpha", s.lost.fast_alpha,
                 "the lost detector's fast average's weight of each new scan, in (0, 1] (0 would never move it)")
      ->capture_default_str()
      ->check(CLI::Range(1e-3, 1.0));
  app.add_option("--lost-unmapped-walls", s.lost.count_unmapped_walls,
                 "1: the lost detector counts beams stopped short on a straight piece longer than people against the "
                 "pose (a wall the map does not hold there; unmapped_walls.h), 0: it leaves every beam stopped short out")
      ->capture_default_str();
  app.add_option("--lost-open-weight", s.lost.open_beam_weight,
                 "how much of a beam that agrees a beam counts that reads nothing where the map has nothing within "
                 "range (the lost detector; 1: a whole one, 0: it tells nothing)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--lost-min-telling", s.lost.min_telling_beams,
                 "scans with fewer beams that agree or disagree leave the lost detector as it was (0: every scan counts)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--lost-hold-against", s.lost.hold_against,
                 "of the hold updates below that say lost, scans that fit below the floor themselves (1: one, then blind "
                 "scans, may say it; the baseline of 2 or more is 1)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--lost-wall-seen-through", s.lost.unmapped_wall_seen_through,
                 "metres: a straight piece the map lacks does not count against the pose where a beam of one of the "
                 "last --lost-wall-memory scans, moved by the odometry, read this much farther (the lost detector; 0: "
                 "off; the baseline of one above 0 is 0)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 5.0));
  app.add_option("--lost-wall-memory", s.lost.unmapped_wall_memory,
                 "earlier scans whose beams may see through a straight piece the map lacks (--lost-wall-seen-through)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--drive", s.drive, "metres of the tracking drive")->capture_default_str();
  app.add_option("--drive-min-walls", s.drive_min_walls,
                 "every drive keeps where this share of 36 rays around meets a wall within the laser's range "
                 "(0: the robot may wander off the map into ground no scan sees)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--people", s.laser.people, "unmodelled obstacles per scan")->capture_default_str();
  double people_field_deg = 0;
  app.add_option("--people-field", people_field_deg,
                 "degrees around the robot's heading where the people stand and walk (0: the laser's field of view, "
                 "every person in every scan; 360: all around the robot, only those in front reach the scans)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 360.0));
  app.add_flag("--exact-people", s.exact_people,
               "tell the filter which returns the simulated people stopped instead of letting it guess them "
               "(foreground.h): the ceiling of any people detector");
  app.add_option("--short-beyond", s.short_beyond,
                 "sensor model: beams stopped more than this many metres short count as this short, for every "
                 "preset, while tracking and while localizing globally (0: eq. 5 as written; negative: the preset's)")
      ->capture_default_str();
  app.add_option("--global-short-beyond", s.global_short_beyond,
                 "sensor model: --short-beyond while localizing globally (the search, the updates after it, the "
                 "verdict), for every preset (negative: the preset's)")
      ->capture_default_str();
  app.add_option("--threads", s.filter.threads, "filter threads")->capture_default_str();
  app.add_option("--config", config, "seed, robust, search, fast (comma-separated) or all")->capture_default_str();
  app.add_option("--kidnaps", s.kidnaps, "kidnapping trials per map and config (0: none)")->capture_default_str();
  app.add_option("--kidnap-after", s.kidnap_after, "metres of tracking before each kidnap")->capture_default_str();
  app.add_option("--recover-updates", s.recover_updates, "updates a recovery may take (0: detection only)")
      ->capture_default_str();
  double false_alarm_hours = 0;
  app.add_option("--report-after", s.report_after,
                 "a recovery reports its pose once the cloud has converged with no look-alike place on this many "
                 "scans in a row, as the robot does (report_gate.h; 1: at the first)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--false-alarm-hours", false_alarm_hours,
                 "hours of driving without a kidnap, for the lost detector's false alarms (a scan every 0.2 s, 0.25 m)")
      ->capture_default_str();
  bool per_trial = false;
  app.add_flag("--per-trial", per_trial, "a line per global trial: start pose, outcome, final error");
  app.add_flag("--explain", s.explain,
               "after each global trial out of bounds at the end: whether the scans favour the estimate or the truth "
               "(each refined; a wrong place that fits better is the model's failure, not the filter's)");
  s.twins = true;
  app.add_flag("--twins,!--no-twins", s.twins,
               "check each start for a twin (a place 1 m or more away whose noiseless scans along the same path match; "
               "twin_places.h), and score ambiguous as the right answer there and success elsewhere (default on)");
  std::string csv;
  app.add_option("--csv", csv,
                 "write a row per global trial to this file (map, config, seed, trial, start, outcome, updates, "
                 "final error, seconds)");
  app.add_flag("--skip-global", skip_global);
  app.add_flag("--skip-tracking", skip_tracking);
  app.add_flag("--skip-rate", skip_rate);
  CLI11_PARSE(app, argc, argv);
  std::vector<std::string> configs;
  if (config == "all" || config == "both") configs = preset_names();  // "both": the old name
  else
    for (size_t at = 0; at <= config.size();) {
      const size_t comma = std::min(config.find(',', at), config.size());
      configs.push_back(config.substr(at, comma - at));
      at = comma + 1;
    }
  for (const std::string& c : configs)
    if (!preset(c)) {
      std::fprintf(stderr, "--config: expected seed, robust, search, fast or all, got %s\n", c.c_str());
      return 2;
    }
  s.look_around_turn = deg2rad(turn_deg);
  s.laser.people_field = deg2rad(people_field_deg);
  s.false_alarm_drive = false_alarm_hours * 3600 / s.scan_period_s * DriveOptions{}.step;
  if (per_trial) s.per_trial = stdout;
  if (maps.empty()) maps = {real_map_path("GDC1.vectormap.txt"), real_map_path("UT_Campus.vectormap.txt")};
  std::FILE* csv_file = nullptr;
  if (!csv.empty() && !(csv_file = std::fopen(csv.c_str(), "w"))) {
    std::fprintf(stderr, "--csv: cannot write %s: %s\n", csv.c_str(), std::strerror(errno));
    return 2;
  }
  std::vector<TableRow> rows;
  try {
    for (const std::string& m : maps) bench_map(m, s, configs, skip_global, skip_tracking, skip_rate, rows);
  } catch (const std::exception& e) {  // a bad map file or name
    std::fprintf(stderr, "bench-localization: %s\n", e.what());
    if (csv_file) std::fclose(csv_file);
    return 2;
  }
  if (!rows.empty()) print_table(stdout, rows);
  if (csv_file) {
    write_trials_csv(csv_file, rows, s.seed);
    if (std::fclose(csv_file) != 0) {
      std::fprintf(stderr, "--csv: writing %s failed\n", csv.c_str());
      return 1;
    }
  }
  return 0;
}
