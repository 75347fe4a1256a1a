#pragma once
// The seed's ray casting (seed 000 section 4.1), the reference every faster RayCaster is
// checked against. When the map is loaded each obstacle gets its minimum bounding
// circle; for each scan, an obstacle whose circle does not meet the scanner's circle
// (the origin, radius rmax) is ignored, and every segment of the others is tested
// against every ray. O(NL * NS) per scan in the worst case, but simple enough to trust.
#include <cstdint>
#include <vector>

#include "common/map/map.h"
#include "common/raycast/ray_caster.h"
#include "common/raycast/ray_rules.h"

namespace fleetmap {

class SeedRayCaster : public RayCaster {
 public:
  // Throws std::invalid_argument when a ramp's surface encoding is wrong.
  SeedRayCaster(const Map& map, RayCasterOptions options);

  double cast_direction(Point origin, Point dir) const override;
  // Culls once per scan, as the seed does per particle.
  void cast_scan(Point origin, double theta, const std::vector<double>& relative_angles, double* ranges) const override;
  const RayCasterOptions& options() const override { return options_; }

 private:
  // Indices of the obstacles whose bounding circle meets the scanner's circle.
  void cull(Point origin, std::vector<uint32_t>& kept) const;
  // Nearest stop among those obstacles, capped at rmax.
  double cast_among(const std::vector<uint32_t>& kept, Point o, Point d) const;

  RayCasterOptions options_;
  LaserObstacles obstacles_;
};

}  // namespace fleetmap
