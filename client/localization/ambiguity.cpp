#include "client/localization/ambiguity.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace fleetmap::localization {

namespace {

uint64_t key(int64_t x, int64_t y) { return (static_cast<uint64_t>(x) << 32) ^ (static_cast<uint64_t>(y) & 0xffffffffu); }

}  // namespace

Ambiguity find_ambiguity(const std::vector<Pose>& poses, const std::vector<double>& weights,
                         const AmbiguityOptions& o) {
  Ambiguity out;
  const size_t n = std::min(poses.size(), weights.size());
  double total = 0;
  for (size_t i = 0; i < n; ++i) total += weights[i];
  if (n == 0 || !(total > 0)) return out;
  const double inv = 1 / o.cell;
  std::vector<std::pair<int64_t, int64_t>> cell(n);
  std::unordered_map<uint64_t, double> mass;
  for (size_t i = 0; i < n; ++i) {
    cell[i] = {static_cast<int64_t>(std::floor(poses[i].x * inv)), static_cast<int64_t>(std::floor(poses[i].y * inv))};
    mass[key(cell[i].first, cell[i].second)] += weights[i];
  }
  std::vector<bool> taken(n, false);  // particles of the clusters already taken
  double heaviest = 0;
  // Every cluster taken, even one too close to count, removes its cells, so each round
  // looks at what is left. The rounds are capped: a nearly uniform cloud (just after
  // init_global) has thousands of comparable blocks, and is ambiguous after a few.
  constexpr size_t kMaxRounds = 64;
  for (size_t round = 0; round < kMaxRounds && out.places.size() < o.max_places; ++round) {
    double best = 0;
    std::pair<int64_t, int64_t> centre{};
    for (size_t i = 0; i < n; ++i) {
      if (taken[i]) continue;
      double m = 0;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy) {
          const auto it = mass.find(key(cell[i].first + dx, cell[i].second + dy));
          if (it != mass.end()) m += it->second;
        }
      if (m > best) {
        best = m;
        centre = cell[i];
      }
    }
    if (!(best > 0) || best < o.min_ratio * heaviest) break;  // nothing comparable is left
    double w = 0, x = 0, y = 0, c = 0, s = 0;
    for (size_t i = 0; i < n; ++i) {
      if (taken[i] || std::abs(cell[i].first - centre.first) > 1 || std::abs(cell[i].second - centre.second) > 1)
        continue;
      taken[i] = true;
      w += weights[i];
      x += weights[i] * poses[i].x;
      y += weights[i] * poses[i].y;
      c += weights[i] * std::cos(poses[i].theta);
      s += weights[i] * std::sin(poses[i].theta);
    }
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) mass.erase(key(centre.first + dx, centre.second + dy));
    if (heaviest == 0) heaviest = w;
    const Pose mean{x / w, y / w, std::atan2(s, c)};
    bool apart = true;
    for (const Pose& p : out.places) apart = apart && distance(p, mean) > o.min_separation;
    if (!apart) continue;
    out.places.push_back(mean);
    out.weights.push_back(w / total);
  }
  return out;
}

}  // namespace fleetmap::localization
