#pragma once
// RRT-Connect (Kuffner & LaValle, "RRT-Connect: An efficient approach to single-query
// path planning", ICRA 2000): the "balanced RRT" of seed 000 §4.2, two trees grown
// alternately from point0 and pointGoal until they meet. For a disc robot in the map
// plane; validity comes from a ClearanceChecker.
//
//   RRT_CONNECT(q_init, q_goal)                     EXTEND(T, q)
//     T_a.init(q_init); T_b.init(q_goal)              q_near <- NEAREST_NEIGHBOR(q, T)
//     for k = 1 to K                                  if NEW_CONFIG(q, q_near, q_new)
//       q_rand <- RANDOM_CONFIG()                       T.add_vertex(q_new); T.add_edge(q_near, q_new)
//       if not (EXTEND(T_a, q_rand) = Trapped)          if q_new = q return Reached
//         if CONNECT(T_b, q_new) = Reached              else return Advanced
//           return PATH(T_a, T_b)                     return Trapped
//       SWAP(T_a, T_b)
//     return Failure                                CONNECT(T, q)
//                                                     repeat S <- EXTEND(T, q) until S != Advanced
//
// NEW_CONFIG moves at most `step` from q_near towards q and accepts the motion when the
// disc stays clear along it. RANDOM_CONFIG is uniform over where the disc's centre may be
// (ClearanceChecker::free_rect), or, with probability goal_bias, the other tree's root.
// Deterministic for a seed, as long as max_time does not cut the run short.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "common/planning/clearance_checker.h"
#include "common/planning/path.h"

namespace fleetmap {

struct RrtOptions {
  double step = 10.0;            // metres: the largest extension (the paper's epsilon);
                                 // 3 to 10 m plan alike on the real maps (bench-planner)
  double goal_bias = 0.05;       // probability of sampling the other tree's root
  size_t max_iterations = 100000;
  double max_time = 2.0;         // seconds, 0: no limit
  uint64_t seed = 1;
};

struct RrtStats {
  size_t iterations = 0;
  size_t start_tree = 0, goal_tree = 0;  // vertices
  double seconds = 0;
  bool timed_out = false;
};

class RrtConnect {
 public:
  // Throws std::invalid_argument for a step or goal bias out of range.
  RrtConnect(const ClearanceChecker& checker, const RrtOptions& options);

  // A path from start to goal whose every segment is clear, or nullopt when start or
  // goal is not clear or the trees did not meet within the limits (which does not prove
  // that no path exists: RRTs are only probabilistically complete).
  std::optional<Path> solve(Point start, Point goal);
  const RrtStats& stats() const { return stats_; }

 private:
  struct Tree {
    std::vector<Point> vertices;
    std::vector<int> parent;  // of each vertex; -1 at the root
    void reset(Point root);
    void add(Point p, size_t parent_index);
    size_t size() const { return parent.size(); }
    // NEAREST_NEIGHBOR by linear scan (the lowest index among equally near ones). A k-d
    // tree rebuilt as the tree grows was tried: no faster on the real maps, where a
    // tree holds a few hundred vertices and the samples fall far from it.
    size_t nearest(Point q) const;
  };
  enum class Status { Trapped, Advanced, Reached };

  Point random_config(const Tree& other);
  Status extend(Tree& t, Point q, size_t* reached);
  Status connect(Tree& t, Point q, size_t* reached);
  Path path(const Tree& from_start, size_t i, const Tree& from_goal, size_t j) const;
  double uniform();  // [0, 1)

  const ClearanceChecker& checker_;
  RrtOptions opt_;
  std::mt19937_64 rng_;
  Tree start_tree_, goal_tree_;
  RrtStats stats_;
};

}  // namespace fleetmap
