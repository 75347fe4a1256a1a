#include "client/localization/distance_field.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>

#include "common/map/laser_rules.h"

namespace fleetmap::localization {

namespace {

constexpr float kFar = 1e12f;  // squared cells: "no wall"

// One dimension of the squared distance transform: f holds 0 on walls and kFar
// elsewhere, or the previous pass's squared distances; d receives the result.
// Felzenszwalb & Huttenlocher, "Distance transforms of sampled functions", 2012.
void transform_1d(const float* f, float* d, int n, std::vector<int>& v, std::vector<double>& z) {
  v.assign(n, 0);
  z.assign(n + 1, 0);
  const auto cut = [&](int q, int p) {  // where the parabolas from q and p cross
    return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
  };
  int k = 0;
  z[0] = -std::numeric_limits<double>::infinity();
  z[1] = std::numeric_limits<double>::infinity();
  for (int q = 1; q < n; ++q) {
    double s = cut(q, v[k]);
    while (k > 0 && s <= z[k]) s = cut(q, v[--k]);
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const double dq = q - v[k];
    d[q] = static_cast<float>(std::min<double>(kFar, dq * dq + f[v[k]]));
  }
}

}  // namespace

DistanceField::DistanceField(const Map& map, DistanceFieldOptions o) {
  const Rect r = map.border.rect();
  const double w = std::max(0.0, r.xmax - r.xmin) + 2 * o.margin, h = std::max(0.0, r.ymax - r.ymin) + 2 * o.margin;
  double res = o.resolution;
  while (w / res * (h / res) > static_cast<double>(o.max_cells)) res *= 1.25;
  frame_ = {{r.xmin - o.margin, r.ymin - o.margin}, res, std::max(1, static_cast<int>(std::ceil(w / res))),
            std::max(1, static_cast<int>(std::ceil(h / res)))};
  const int width = frame_.width, height = frame_.height;
  std::vector<float> f(frame_.cells(), kFar);

  // Rasterize: points every half cell along each wall.
  const auto mark = [&](Point a, Point b) {
    const int steps = std::max(1, static_cast<int>(std::ceil(2 * fleetmap::distance(a, b) / res)));
    for (int s = 0; s <= steps; ++s) {
      const double t = static_cast<double>(s) / steps;
      const int64_t ix = frame_.col(a.x + t * (b.x - a.x)), iy = frame_.row(a.y + t * (b.y - a.y));
      if (frame_.inside(ix, iy)) f[frame_.index(ix, iy)] = 0;
    }
  };
  for (const Obstacle& ob : map.obstacles)
    for (const Segment& s : ob.segments)
      if (stops_laser(s.h, o.laser_height)) mark(s.a, s.b);

  // Columns, then rows.
  std::vector<int> v;
  std::vector<double> z;
  std::vector<float> col_in(height), col_out(height), row_out(width);
  for (int ix = 0; ix < width; ++ix) {
    for (int iy = 0; iy < height; ++iy) col_in[iy] = f[index(ix, iy)];
    transform_1d(col_in.data(), col_out.data(), height, v, z);
    for (int iy = 0; iy < height; ++iy) f[index(ix, iy)] = col_out[iy];
  }
  distances_.resize(f.size());
  for (int iy = 0; iy < height; ++iy) {
    transform_1d(&f[index(0, iy)], row_out.data(), width, v, z);
    for (int ix = 0; ix < width; ++ix)
      distances_[index(ix, iy)] = static_cast<float>(std::sqrt(std::min(row_out[ix], kFar)) * res);
  }
}

double DistanceField::distance(Point p) const {
  return distances_[frame_.index(frame_.clamp_col(p.x), frame_.clamp_row(p.y))];
}

}  // namespace fleetmap::localization
