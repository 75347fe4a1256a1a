#include "client/localization/ambiguity.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>

#include "client/localization/residual_judge.h"

namespace fleetmap::localization {

namespace {

uint64_t key(int64_t x, int64_t y) { return (static_cast<uint64_t>(x) << 32) ^ (static_cast<uint64_t>(y) & 0xffffffffu); }

struct PlaceCandidate {
  Pose mean;
  double share = 0;               // of the total weight
  std::vector<size_t> heaviest;   // its heaviest particles, heaviest first
};

struct PlaceCandidates {
  std::vector<PlaceCandidate> list;  // heaviest first
  double covered = 0;           // share of the weight in every cluster taken
};

PlaceCandidates find_candidates(const std::vector<Pose>& poses, const std::vector<double>& weights,
                           const AmbiguityOptions& o, size_t keep_heaviest) {
  PlaceCandidates out;
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
  for (size_t round = 0; round < kMaxRounds && out.list.size() < o.max_places; ++round) {
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
    std::vector<size_t> members;
    for (size_t i = 0; i < n; ++i) {
      if (taken[i] || std::abs(cell[i].first - centre.first) > 1 || std::abs(cell[i].second - centre.second) > 1)
        continue;
      taken[i] = true;
      members.push_back(i);
      w += weights[i];
      x += weights[i] * poses[i].x;
      y += weights[i] * poses[i].y;
      c += weights[i] * std::cos(poses[i].theta);
      s += weights[i] * std::sin(poses[i].theta);
    }
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) mass.erase(key(centre.first + dx, centre.second + dy));
    out.covered += w / total;
    if (heaviest == 0) heaviest = w;
    const Pose mean{x / w, y / w, std::atan2(s, c)};
    bool apart = true;
    for (const PlaceCandidate& p : out.list) apart = apart && distance(p.mean, mean) > o.min_separation;
    if (!apart) continue;
    const size_t k = std::min(keep_heaviest, members.size());
    std::partial_sort(members.begin(), members.begin() + static_cast<std::ptrdiff_t>(k), members.end(),
                      [&](size_t a, size_t b) { return weights[a] > weights[b]; });
    members.resize(k);
    out.list.push_back({mean, w / total, std::move(members)});
  }
  return out;
}

Ambiguity all_places(const PlaceCandidates& c) {
  Ambiguity out;
  for (const PlaceCandidate& p : c.list) {
    out.places.push_back(p.mean);
    out.weights.push_back(p.share);
  }
  return out;
}

}  // namespace

Ambiguity find_ambiguity(const std::vector<Pose>& poses, const std::vector<double>& weights,
                         const AmbiguityOptions& o) {
  return all_places(find_candidates(poses, weights, o, 0));
}

Ambiguity find_ambiguity(const std::vector<Pose>& poses, const std::vector<double>& weights,
                         const AmbiguityOptions& o, const PlaceScore& score, const std::vector<Pose>& rivals,
                         const PlaceScore& residual, const RegisteredResidual& registered) {
  const PlaceCandidates c = find_candidates(poses, weights, o, o.refine);
  // One candidate: nothing to compare. A diffuse cloud: the candidates are a sample of
  // many comparable lumps, and the best of them says nothing about the rest.
  const bool with_rivals = o.rivals && !rivals.empty() && residual && !c.list.empty();
  if ((c.list.size() < 2 && !with_rivals) || c.covered < o.diffuse_share) return all_places(c);
  // Each candidate at its best pose: a cluster's mean may sit a little off the pose its
  // best particles found, and 0.1 m off costs more per beam than a look-alike place.
  std::vector<double> ll;
  std::vector<Pose> at;  // each candidate's best pose
  for (const PlaceCandidate& p : c.list) {
    double best = score(p.mean);
    at.push_back(p.mean);
    for (size_t i : p.heaviest) {
      const double s = score(poses[i]);
      if (s > best) best = s, at.back() = poses[i];
    }
    ll.push_back(best);
  }
  const size_t best_scored = static_cast<size_t>(std::max_element(ll.begin(), ll.end()) - ll.begin());
  // With a residual, the cloud's other candidates are judged as the rivals are (below):
  // the tempered score let places 120 m apart that are no twins come within its margin
  // on the campus (0.019 per beam apart; by the registered residual, 0.4 and more).
  const bool by_residual = o.candidates_by_residual && static_cast<bool>(residual);
  std::optional<ResidualJudge> residual_judge;
  if (residual) residual_judge.emplace(o, residual, registered);
  size_t top = best_scored;
  std::optional<ResidualJudge::Reference> reference;
  if (by_residual || with_rivals) reference = residual_judge->reference_at(at[top]);
  // The best by the tempered score and the heaviest (what estimate() reports) disagree:
  // the residual, each registered at itself, decides which is the reference; the other
  // is judged against it. (On the campus the tempered score put a place 120 m off 0.011
  // per beam above the truth, whose residual was 0.4 better.)
  if (by_residual && top != 0) {
    ResidualJudge::Reference heaviest = residual_judge->reference_at(at[0]);
    if (heaviest.place.score >= reference->place.score) reference = std::move(heaviest), top = 0;
  }
  Ambiguity out = all_places(c);
  if (ll.size() >= 2) {
    std::vector<double> sorted = ll;
    std::sort(sorted.begin(), sorted.end(), std::greater<>());
    const double best = sorted[0];
    out = {};
    out.runner_up_gap = best - sorted[1];
    out.heaviest_gap = best - ll[0];
    for (size_t k = 0; k < c.list.size(); ++k) {
      // The heaviest explains the scans worse than the best place: that one stays beside
      // it (it is within the margin of itself), so the verdict is ambiguous.
      if (k > 0 && k != top && (by_residual || !(ll[k] >= best - o.margin_per_beam))) continue;
      out.places.push_back(c.list[k].mean);
      out.weights.push_back(c.list[k].share);
    }
  }
  // What is judged by residual: the cloud's other candidates (at their best poses, with
  // their weights), then the rivals (with none); a rival at a candidate is that candidate.
  std::vector<Pose> others;
  std::vector<double> others_weight;
  if (by_residual)
    for (size_t k = 1; k < c.list.size(); ++k)
      if (k != top) others.push_back(at[k]), others_weight.push_back(c.list[k].share);
  std::vector<Pose> candidates = at;
  for (const PlaceCandidate& p : c.list) candidates.push_back(p.mean);
  if (with_rivals)
    for (size_t k = 0; k < std::min(rivals.size(), o.max_rivals); ++k)
      if (!by_residual || !near_any(candidates, rivals[k], o.min_separation)) others.push_back(rivals[k]), others_weight.push_back(0);
  if (others.empty()) return out;
  // The places the others must be apart from: the heaviest and the reference's candidate
  // (the residual's judge) or every candidate (the tempered score's margin).
  std::vector<Pose> held{at[0], c.list[0].mean, at[top], c.list[top].mean};
  if (!by_residual) {
    held.insert(held.end(), at.begin(), at.end());
    for (const PlaceCandidate& p : c.list) held.push_back(p.mean);
  }
  std::vector<ResidualJudge::Kept> kept = residual_judge->judge(others, held, *reference);
  // Some place kept: the reference is moved to where its registered scans fit best and
  // the others judged again (register_moves_place). Where none is kept, the reference
  // already stands out, and moving it (a few tenths of a second) would not change that.
  if (!kept.empty() && registered && o.register_moves_place) {
    // Moved farther than move_max_shift from the place the filter reports, it found that
    // place off, not the look-alikes worse: the verdict stays.
    const ResidualJudge::Reference moved = residual_judge->register_at(reference->place.pose, true);
    if (moved.place.score > reference->place.score && distance(moved.place.pose, c.list[top].mean) <= o.move_max_shift)
      kept = residual_judge->judge(others, held, moved, true, kept);
  }
  for (const ResidualJudge::Kept& k : kept) {
    out.places.push_back(k.place);
    out.weights.push_back(others_weight[k.other]);
  }
  return out;
}

}  // namespace fleetmap::localization
