#include "client/localization/distance_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/raycast/ray_rules.h"

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

DistanceField::DistanceField(const Map& map, DistanceFieldOptions o) : resolution_(o.resolution) {
  const Rect r = map.border.rect();
  const double w = std::max(0.0, r.xmax - r.xmin) + 2 * o.margin, h = std::max(0.0, r.ymax - r.ymin) + 2 * o.margin;
  while (w / resolution_ * (h / resolution_) > static_cast<double>(o.max_cells)) resolution_ *= 1.25;
  origin_ = {r.xmin - o.margin, r.ymin - o.margin};
  width_ = std::max(1, static_cast<int>(std::ceil(w / resolution_)));
  height_ = std::max(1, static_cast<int>(std::ceil(h / resolution_)));
  std::vector<float> f(static_cast<size_t>(width_) * height_, kFar);

  // Rasterize: points every half cell along each wall.
  const auto mark = [&](Point a, Point b) {
    const int steps = std::max(1, static_cast<int>(std::ceil(2 * fleetmap::distance(a, b) / resolution_)));
    for (int s = 0; s <= steps; ++s) {
      const double t = static_cast<double>(s) / steps;
      const int ix = cell_x(a.x + t * (b.x - a.x)), iy = cell_y(a.y + t * (b.y - a.y));
      if (ix >= 0 && ix < width_ && iy >= 0 && iy < height_) f[index(ix, iy)] = 0;
    }
  };
  for (const Obstacle& ob : map.obstacles)
    for (const Segment& s : ob.segments)
      if (stops_laser(s.h, o.laser_height)) mark(s.a, s.b);

  // Columns, then rows.
  std::vector<int> v;
  std::vector<double> z;
  std::vector<float> col_in(height_), col_out(height_), row_out(width_);
  for (int ix = 0; ix < width_; ++ix) {
    for (int iy = 0; iy < height_; ++iy) col_in[iy] = f[index(ix, iy)];
    transform_1d(col_in.data(), col_out.data(), height_, v, z);
    for (int iy = 0; iy < height_; ++iy) f[index(ix, iy)] = col_out[iy];
  }
  distances_.resize(f.size());
  for (int iy = 0; iy < height_; ++iy) {
    transform_1d(&f[index(0, iy)], row_out.data(), width_, v, z);
    for (int ix = 0; ix < width_; ++ix)
      distances_[index(ix, iy)] = static_cast<float>(std::sqrt(std::min(row_out[ix], kFar)) * resolution_);
  }
}

int DistanceField::cell_x(double x) const { return static_cast<int>(std::floor((x - origin_.x) / resolution_)); }
int DistanceField::cell_y(double y) const { return static_cast<int>(std::floor((y - origin_.y) / resolution_)); }

double DistanceField::distance(Point p) const {
  const int ix = std::clamp(cell_x(p.x), 0, width_ - 1), iy = std::clamp(cell_y(p.y), 0, height_ - 1);
  return distances_[index(ix, iy)];
}

}  // namespace fleetmap::localization
