#pragma once
// The simulated robot of SPEC 6: a ground-truth world, a differential drive with noisy
// odometry, a 2D laser at its mounting height with noise (and optional people), a noisy
// compass; it localizes on the maps the server sends (global, then tracking), reports
// SendPos at about 3 Hz, takes goals (SetPosEnd), asks for a path (GetPath) and follows
// it by pure pursuit; stops on Abort, and when GetPath answers an Error (no_path: the
// server failed the task) it drops the goal and reports Stopped where it stands.
#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "client/sim/laser_simulator.h"
#include "client/localization/lost_detector.h"
#include "client/localization/particle_filter.h"
#include "client/robot_client.h"
#include "client/route_edges.h"
#include "client/sim/differential_drive.h"
#include "client/sim/pure_pursuit.h"
#include "client/zoom_map_client.h"

namespace fleetmap {

struct SimRobotOptions {
  double laser_height = 0.3;         // hL
  localization::LaserSimulatorOptions laser;  // NL, FOV, sigma_L, people
  double compass_sigma_deg = 1.0;    // compass noise (the filter assumes +-3 degrees)
  // The filter preset of global localization (localization_trials.h, preset()): fast or
  // search (docs/localization.md, "Presets"). fast: under a second per localization where
  // search takes ten, right on a trial in 40 fewer on a quiet floor and far more often
  // among people (docs/localization.md, "The robot's default: fast").
  std::string localizer = "fast";
  size_t global_particles = 6000;    // NP of global localization
  size_t tracking_particles = 1000;  // max NP once localized (KLD sampling)
  double step_s = 0.1;               // simulation and control period
  double scan_every_s = 0.2;         // a filter update this often while moving
  double report_every_s = 1.0 / 3;   // SendPos at 3 Hz
  PurePursuitOptions pursuit;
  OdometryNoise odometry;
  bool zoom = false;                 // keep a window (GetMap) instead of the whole map
  ZoomMapOptions zoom_options;
  bool realtime = true;              // sleep to keep pace with the wall clock
  unsigned seed = 1;
  // A kidnapping (tests, demos): at this simulated time the true robot is moved to the
  // pose without odometry. The lost detector should notice (lost_detector.h).
  std::optional<double> kidnap_at_s;
  Pose kidnap_to;
  localization::LostDetectorOptions lost;
};

class SimRobot {
 public:
  SimRobot(RobotClient& client, const Map& world, Pose start, const Map& first_map, SimRobotOptions options);

  // Global localization from a compass-only prior; returns the updates it took, or
  // nullopt when it did not converge within max_updates, or its cloud still held look-alike
  // places (ParticleFilter::ambiguity: it logs them rather than report one as the pose).
  std::optional<int> localize(int max_updates = 40);
  // Tracking from a known pose (the operator's initial pose, GetPosIni).
  void start_tracking(const Pose& pose, double sd_xy, double sd_theta);

  // Drives until stop is set or duration_s of simulated time has passed.
  void run(const std::atomic<bool>& stop, double duration_s);

  const Pose& truth() const { return drive_.pose(); }
  localization::PoseEstimate estimate() const { return filter_->estimate(); }
  size_t goals_reached() const { return goals_reached_; }
  size_t goals_refused() const { return goals_refused_; }  // GetPath answered an Error
  size_t relocalizations() const { return relocalizations_; }  // the lost detector fired

 private:
  void handle(const ReceivedAnswer& a);
  void filter_step(const Odometry& odometry_since_update);
  double compass();
  void stopped();
  void report_pose(double v, double w);  // SendPos of the filter's estimate
  // The lost detector fired: stop, say so (SendPos "status": "lost"), localize again.
  void relocalize();

  RobotClient& client_;
  SimRobotOptions o_;
  std::shared_ptr<const RayCaster> world_;
  DifferentialDrive drive_;
  localization::LaserSimulator laser_;
  std::unique_ptr<localization::ParticleFilter> filter_;
  localization::ParticleFilterOptions global_options_;  // of every global localization
  localization::LostDetector lost_;
  bool tracking_ = false;  // the detector watches only a tracking filter
  bool localizing_ = false;  // lost and not localized again yet
  size_t relocalizations_ = 0;
  PurePursuit pursuit_;
  RouteEdges route_;  // the path's topological edges, when GetPath went through the graph
  std::unique_ptr<ZoomMapClient> zoom_;
  std::mt19937_64 rng_;
  Map map_;  // the map the filter works on: the whole map or the current window
  std::optional<Point> goal_;
  std::optional<unsigned long long> path_request_;
  double time_s_ = 0;
  size_t goals_reached_ = 0;
  size_t goals_refused_ = 0;
  bool moving_ = false;
  bool bumped_ = false;
  bool pose_resent_ = false;  // this goal's GetPath got no_pose once: the pose was sent again
};

}  // namespace fleetmap
