#include "common/planning/rrt_connect.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace fleetmap {

RrtConnect::RrtConnect(const ClearanceChecker& checker, const RrtOptions& options)
    : checker_(checker), opt_(options), rng_(options.seed) {
  if (!(std::isfinite(opt_.step) && opt_.step > 0))
    throw std::invalid_argument("expected an RRT step > 0 (metres), got " + std::to_string(opt_.step));
  if (!(opt_.goal_bias >= 0 && opt_.goal_bias <= 1))
    throw std::invalid_argument("expected an RRT goal bias in [0, 1], got " + std::to_string(opt_.goal_bias));
  if (!(opt_.max_time >= 0))
    throw std::invalid_argument("expected an RRT time limit >= 0 (seconds), got " + std::to_string(opt_.max_time));
}

double RrtConnect::uniform() {
  return static_cast<double>(rng_() >> 11) * 0x1.0p-53;  // the same on every standard library
}

Point RrtConnect::random_config(const Tree& other) {
  if (opt_.goal_bias > 0 && uniform() < opt_.goal_bias) return other.vertices[0];
  const Rect& r = checker_.free_rect();
  const double u = uniform(), v = uniform();
  return {r.xmin + u * (r.xmax - r.xmin), r.ymin + v * (r.ymax - r.ymin)};
}

void RrtConnect::Tree::reset(Point root) {
  vertices.assign(1, root);
  parent.assign(1, -1);
}

void RrtConnect::Tree::add(Point p, size_t parent_index) {
  vertices.push_back(p);
  parent.push_back(static_cast<int>(parent_index));
}

size_t RrtConnect::Tree::nearest(Point q) const {
  size_t best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Point d = vertices[i] - q;
    const double d2 = dot(d, d);
    if (d2 < best_d2) best_d2 = d2, best = i;
  }
  return best;
}

RrtConnect::Status RrtConnect::extend(Tree& t, Point q, size_t* reached) {
  const size_t near = t.nearest(q);
  const Point from = t.vertices[near];
  const double d = distance(from, q);
  if (d == 0) {  // q is already a vertex
    *reached = near;
    return Status::Reached;
  }
  // NEW_CONFIG: at most one step towards q, along a clear motion.
  const Point to = d <= opt_.step ? q : from + (opt_.step / d) * (q - from);
  if (!checker_.motion_clear(from, to)) return Status::Trapped;
  t.add(to, near);
  *reached = t.size() - 1;
  return d <= opt_.step ? Status::Reached : Status::Advanced;
}

RrtConnect::Status RrtConnect::connect(Tree& t, Point q, size_t* reached) {
  Status s;
  do s = extend(t, q, reached);
  while (s == Status::Advanced);
  return s;
}

Path RrtConnect::path(const Tree& from_start, size_t i, const Tree& from_goal, size_t j) const {
  Path p;
  for (int k = static_cast<int>(i); k >= 0; k = from_start.parent[k]) p.push_back(from_start.vertices[k]);
  std::reverse(p.begin(), p.end());
  // Vertex j of from_goal is the same point as vertex i of from_start: where the trees met.
  for (int k = from_goal.parent[j]; k >= 0; k = from_goal.parent[k]) p.push_back(from_goal.vertices[k]);
  return p;
}

std::optional<Path> RrtConnect::solve(Point start, Point goal) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  stats_ = {};
  rng_.seed(opt_.seed);  // every solve starts afresh: same seed, same query, same path
  start_tree_.reset(start);
  goal_tree_.reset(goal);
  auto finish = [&](std::optional<Path> p) {
    stats_.start_tree = start_tree_.size();
    stats_.goal_tree = goal_tree_.size();
    stats_.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return p;
  };
  if (!checker_.point_clear(start) || !checker_.point_clear(goal)) return finish(std::nullopt);
  if (checker_.motion_clear(start, goal)) return finish(Path{start, goal});

  Tree* a = &start_tree_;
  Tree* b = &goal_tree_;
  for (size_t k = 0; k < opt_.max_iterations; ++k) {
    stats_.iterations = k + 1;
    if (opt_.max_time > 0 && (k & 31) == 31 &&
        std::chrono::duration<double>(Clock::now() - t0).count() > opt_.max_time) {
      stats_.timed_out = true;
      break;
    }
    const Point q_rand = random_config(*b);
    size_t i_new = 0, i_met = 0;
    if (extend(*a, q_rand, &i_new) != Status::Trapped) {
      const Point q_new = a->vertices[i_new];
      if (connect(*b, q_new, &i_met) == Status::Reached)
        return finish(a == &start_tree_ ? path(*a, i_new, *b, i_met) : path(*b, i_met, *a, i_new));
    }
    std::swap(a, b);
  }
  return finish(std::nullopt);
}

}  // namespace fleetmap
