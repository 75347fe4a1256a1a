#include "client/localization/unmapped_walls.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fleetmap::localization {

namespace {

struct Point {
  double x, y;
  double range, ux, uy;  // along the beam (ux, uy)
};

double distance(const Point& a, const Point& b) { return std::hypot(b.x - a.x, b.y - a.y); }

// How far p's range is from where its beam meets the line through a and b: the laser's
// error is along the beam, so this is what its noise bounds, at any angle. A line the
// beam runs along (or meets behind the laser) is infinitely far.
double off_chord(const Point& p, const Point& a, const Point& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double across = p.ux * dy - p.uy * dx;
  if (std::fabs(across) < 1e-9 * (std::fabs(dx) + std::fabs(dy)) || (dx == 0 && dy == 0)) return INFINITY;
  const double t = (a.x * dy - a.y * dx) / across;
  return t > 0 ? std::fabs(p.range - t) : INFINITY;
}

// Whether the beam to p meets the line through a and b within max_incidence of its
// normal: along a beam that grazes a line, the line's own error outgrows the noise.
bool meets_head_on(const Point& p, const Point& a, const Point& b, const UnmappedWallOptions& o) {
  const double len = distance(a, b);
  if (len < 1e-12) return false;
  // cos(incidence) = |sin(angle between the line and the beam)|.
  const double cos_incidence = std::fabs((b.x - a.x) * p.uy - (b.y - a.y) * p.ux) / len;
  return cos_incidence >= std::cos(o.max_incidence);
}

// Marks the straight pieces of points[first..last] (inclusive). A piece is straight when
// every range is within straightness of the chord between its ends along its beam, but
// for a few lone ones (a noisy return, a jamb: at most one in ten, both neighbours on the
// line, within 3 x straightness). A person's front leaves the line over several beams.
// Otherwise the piece is split at its worst point.
void mark_straight_pieces(const std::vector<Point>& points, const std::vector<size_t>& beam, size_t first, size_t last,
                          const UnmappedWallOptions& o, std::vector<int>& out, int& pieces) {
  if (last < first || static_cast<int>(last - first + 1) < o.min_beams) return;
  const Point a = points[first], b = points[last];
  std::vector<double> off(last - first + 1);
  size_t worst = first;
  for (size_t k = first; k <= last; ++k) {
    off[k - first] = off_chord(points[k], a, b);
    if (off[k - first] > off[worst - first]) worst = k;
  }
  auto out_of_line = [&](size_t k) { return off[k - first] > o.straightness; };
  size_t outliers = 0;
  bool lone = true;
  for (size_t k = first; k <= last; ++k) {
    if (!out_of_line(k)) continue;
    lone = lone && k > first && k < last && !out_of_line(k - 1) && !out_of_line(k + 1) &&
           off[k - first] <= 3 * o.straightness;
    ++outliers;
  }
  if (outliers == 0 || (lone && outliers * 10 <= last - first + 1)) {
    std::vector<size_t> wall;  // the beams on the line that meet it head on
    for (size_t k = first; k <= last; ++k)
      if (!out_of_line(k) && meets_head_on(points[k], a, b, o)) wall.push_back(k);
    if (wall.empty() || static_cast<int>(wall.size()) < o.min_beams ||
        distance(points[wall.front()], points[wall.back()]) < o.min_length)
      return;
    ++pieces;
    for (size_t k : wall) out[beam[k]] = pieces;
    return;
  }
  // Split at the worst point; at an end, drop it.
  if (worst == first) return mark_straight_pieces(points, beam, first + 1, last, o, out, pieces);
  if (worst == last) return mark_straight_pieces(points, beam, first, last - 1, o, out, pieces);
  mark_straight_pieces(points, beam, first, worst, o, out, pieces);
  mark_straight_pieces(points, beam, worst, last, o, out, pieces);
}

}  // namespace

std::vector<int> unmapped_wall_pieces(const std::vector<double>& ranges, const std::vector<double>& beam_angles,
                                      const std::vector<uint8_t>& stopped_short, const UnmappedWallOptions& options) {
  if (beam_angles.size() != ranges.size() || stopped_short.size() != ranges.size())
    throw std::invalid_argument("unmapped_wall_pieces: expected one angle and one flag per range (" +
                                std::to_string(ranges.size()) + "), got " + std::to_string(beam_angles.size()) +
                                " and " + std::to_string(stopped_short.size()));
  std::vector<int> out(ranges.size(), 0);
  int pieces = 0;
  std::vector<Point> run;
  std::vector<size_t> beam;
  auto close_run = [&] {
    if (!run.empty()) mark_straight_pieces(run, beam, 0, run.size() - 1, options, out, pieces);
    run.clear();
    beam.clear();
  };
  for (size_t j = 0; j < ranges.size(); ++j) {
    if (!stopped_short[j]) {
      close_run();
      continue;
    }
    const double ux = std::cos(beam_angles[j]), uy = std::sin(beam_angles[j]);
    const Point p{ranges[j] * ux, ranges[j] * uy, ranges[j], ux, uy};
    if (!run.empty() && distance(run.back(), p) > options.max_gap) close_run();
    run.push_back(p);
    beam.push_back(j);
  }
  close_run();
  return out;
}

std::vector<uint8_t> unmapped_wall_returns(const std::vector<double>& ranges, const std::vector<double>& beam_angles,
                                           const std::vector<uint8_t>& stopped_short,
                                           const UnmappedWallOptions& options) {
  const std::vector<int> pieces = unmapped_wall_pieces(ranges, beam_angles, stopped_short, options);
  std::vector<uint8_t> out(pieces.size());
  std::transform(pieces.begin(), pieces.end(), out.begin(), [](int piece) { return piece > 0 ? 1 : 0; });
  return out;
}

}  // namespace fleetmap::localization
