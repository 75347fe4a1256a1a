#include "common/raycast/grid_ray_caster.h"

#include <algorithm>
#include <cmath>

namespace fleetmap {

GridRayCaster::GridRayCaster(const Map& map, RayCasterOptions options, GridOptions grid)
    : options_(options),
      grid_options_(grid),
      obstacles_(prepare_laser_obstacles(map, options.laser_height)),
      // Skips longer than rmax are never needed; the cap also bounds the build's work.
      grid_(obstacles_, grid.cell, std::min(options.rmax, 64 * grid.cell)) {
  obstacles_.walls = {};  // copied into the grid's cells
}

size_t GridRayCaster::memory_bytes() const {
  return grid_.memory_bytes() + obstacles_.specials.capacity() * sizeof(SpecialObstacle);
}

double GridRayCaster::cast_direction(Point o, Point d) const {
  const double rmax = options_.rmax;
  if (grid_.empty()) return rmax;

  // The part [t, tend] of the ray inside the grid and within rmax (slab clipping).
  double t = 0, tend = rmax;
  const Rect r = grid_.rect();
  for (int axis = 0; axis < 2; ++axis) {
    const double oa = axis ? o.y : o.x, da = axis ? d.y : d.x;
    const double lo = axis ? r.ymin : r.xmin, hi = axis ? r.ymax : r.xmax;
    if (da == 0) {
      if (oa < lo || oa > hi) return rmax;
      continue;
    }
    double ta = (lo - oa) / da, tb = (hi - oa) / da;
    if (ta > tb) std::swap(ta, tb);
    t = std::max(t, ta);
    tend = std::min(tend, tb);
  }
  if (!(t <= tend)) return rmax;

  const Point corner = grid_.corner();
  const double cell = grid_.cell(), inv_cell = grid_.inv_cell();
  const int nx = grid_.nx(), ny = grid_.ny();
  const int sx = d.x > 0 ? 1 : -1, sy = d.y > 0 ? 1 : -1;
  const double tdx = d.x != 0 ? cell / std::fabs(d.x) : kNoHit;
  const double tdy = d.y != 0 ? cell / std::fabs(d.y) : kNoHit;
  const RaySegment* walls = grid_.walls();
  const bool skip_empty = grid_options_.skip_empty;
  double best = kNoHit;
  int last_special = -1;

  for (;;) {
    // Enter the cell that holds o + t d; the parameters of its next vertical and
    // horizontal boundary crossings.
    const Point p = o + t * d;
    int ix = std::clamp(static_cast<int>(std::floor((p.x - corner.x) * inv_cell)), 0, nx - 1);
    int iy = std::clamp(static_cast<int>(std::floor((p.y - corner.y) * inv_cell)), 0, ny - 1);
    double tx = d.x != 0 ? (corner.x + (ix + (d.x > 0)) * cell - o.x) / d.x : kNoHit;
    double ty = d.y != 0 ? (corner.y + (iy + (d.y > 0)) * cell - o.y) / d.y : kNoHit;
    for (;;) {
      const SegmentGrid::Cell& c = grid_.at(ix, iy);
      const double texit = std::min(tx, ty);
      if (skip_empty && c.skip > 0 && t + c.skip > texit) {  // jump across empty space
        t += c.skip;
        break;
      }
      for (uint32_t i = c.walls_begin; i < c.walls_end; ++i)
        best = std::min(best, ray_segment_distance(walls[i], o, d));
      if (c.specials != 0) {
        const uint32_t* list = grid_.special_lists() + c.specials;
        for (uint32_t k = 1; k <= list[0]; ++k) {
          const int id = static_cast<int>(list[k]);
          if (id == last_special) continue;
          last_special = id;
          best = std::min(best, obstacles_.specials[id].distance(o, d));
        }
      }
      // Anything in a later cell is at least texit away.
      if (best <= texit || texit >= tend) return std::min(best, rmax);
      t = texit;
      if (tx < ty) {
        ix += sx;
        tx += tdx;
        if (ix < 0 || ix >= nx) return std::min(best, rmax);
      } else {
        iy += sy;
        ty += tdy;
        if (iy < 0 || iy >= ny) return std::min(best, rmax);
      }
    }
    if (best <= t || t >= tend) return std::min(best, rmax);
  }
}

}  // namespace fleetmap
