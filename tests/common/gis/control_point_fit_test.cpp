// The control-point fit (common/gis/control_point_fit.h): a georeference made with
// GeoTransform is recovered from its own points; noise shows up as the rms; the DXF
// floor plan's three ground control points (../shared/maps/gis/README.md) fit with
// residuals that PROJ's geodesic confirms point by point.
#include "common/gis/control_point_fit.h"

#include <geodesic.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "common/core/error.h"

namespace fleetmap {
namespace {

double geodesic_distance(LonLat a, LonLat b) {
  geod_geodesic g;
  geod_init(&g, 6378137, 1 / 298.257223563);
  double s = 0;
  geod_inverse(&g, a.lat, a.lon, b.lat, b.lon, &s, nullptr, nullptr);
  return s;
}

// A georeference in the local TM at (lat, lon) that puts the centroid of pts there, so
// that the fit (which works in the TM at the points' mean fix) lands on nearly the same
// plane and its parameters compare with these.
MapGeoref truth_around(double lat, double lon, double rotation, double scale, const std::vector<Point>& pts) {
  Point c{0, 0};
  for (const Point& p : pts) c = {c.x + p.x / static_cast<double>(pts.size()), c.y + p.y / static_cast<double>(pts.size())};
  MapGeoref g = georef_from_origin(lat, lon, rotation);
  g.scale = scale;
  const double cr = std::cos(rotation), sr = std::sin(rotation);
  g.tx = -scale * (cr * c.x - sr * c.y);
  g.ty = -scale * (sr * c.x + cr * c.y);
  return g;
}

std::vector<ControlPoint> points_of(const MapGeoref& g, const std::vector<Point>& pts) {
  const GeoTransform t(g);
  std::vector<ControlPoint> out;
  for (const Point& p : pts) out.push_back({p, t.to_wgs84(p)});
  return out;
}

const std::vector<Point> kCorners{{2000, 2000}, {2180, 2010}, {2150, 2160}, {1990, 2120}, {2080, 2070}};

TEST(ControlPointFit, RecoversASyntheticGeoreference) {
  const MapGeoref truth = truth_around(30.2862, -97.7366, 0.4, 1, kCorners);
  const ControlPointFit f = fit_control_points(points_of(truth, kCorners));
  EXPECT_NEAR(f.georef.rotation, truth.rotation, 1e-8);
  EXPECT_NEAR(f.georef.scale, 1, 1e-9);
  EXPECT_NEAR(f.georef.tx, truth.tx, 0.01);  // the fit's TM sits at the mean fix, mm from truth's
  EXPECT_NEAR(f.georef.ty, truth.ty, 0.01);
  EXPECT_EQ(f.scale, f.georef.scale);
  ASSERT_EQ(f.residuals.size(), kCorners.size());
  for (double r : f.residuals) EXPECT_LT(r, 1e-6);
  EXPECT_LT(f.rms, 1e-6);
  // The fitted georeference places every map point where the true one does, far from
  // the points too.
  const GeoTransform a(truth), b(f.georef);
  for (const Point p : {Point{0, 0}, Point{2080, 2070}, Point{5000, -3000}})
    EXPECT_LT(geodesic_distance(a.to_wgs84(p), b.to_wgs84(p)), 1e-4) << p.x << "," << p.y;
}

TEST(ControlPointFit, RecoversScaleAndAnySignOfRotation) {
  const MapGeoref truth = truth_around(-33.9, 151.2, -2.5, 1.02, kCorners);
  const ControlPointFit f = fit_control_points(points_of(truth, kCorners));
  EXPECT_NEAR(f.georef.rotation, -2.5, 1e-8);
  EXPECT_NEAR(f.scale, 1.02, 1e-9);
  EXPECT_LT(f.rms, 1e-6);
}

TEST(ControlPointFit, TwoPointsFitExactly) {
  const std::vector<Point> two{{0, 0}, {100, 50}};
  const MapGeoref truth = truth_around(52.0, 4.3, 1.0, 1, two);
  const ControlPointFit f = fit_control_points(points_of(truth, two));
  EXPECT_NEAR(f.georef.rotation, 1.0, 1e-8);
  EXPECT_NEAR(f.scale, 1, 1e-9);
  EXPECT_LT(f.rms, 1e-6);
}

TEST(ControlPointFit, NoiseShowsUpAsTheRms) {
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<double> u(-300, 300);
  std::normal_distribution<double> noise(0, 0.05);
  std::vector<Point> pts;
  for (int i = 0; i < 400; ++i) pts.push_back({u(rng), u(rng)});
  const MapGeoref truth = truth_around(45.76, 3.11, 0.3, 1, pts);
  std::vector<ControlPoint> cps = points_of(truth, pts);
  for (ControlPoint& c : cps) c.map = {c.map.x + noise(rng), c.map.y + noise(rng)};
  const ControlPointFit f = fit_control_points(cps);
  // Isotropic noise of 0.05 m per axis: residual rms 0.05 sqrt(2 (1 - 4 / 800)) = 0.0705 m.
  EXPECT_NEAR(f.rms, 0.0705, 0.0705 * 0.1);
  EXPECT_NEAR(f.georef.rotation, 0.3, 1e-3);
  EXPECT_NEAR(f.scale, 1, 1e-3);
}

// ../shared/maps/gis/README.md, dxf-openindoor-clermont: the plan in centimetres; a map
// imported from it is in metres.
std::vector<ControlPoint> dxf_points() {
  return {{{10762.7211865239 / 100, 4732.17310712035 / 100}, {3.11171115, 45.75836725}},
          {{21216.987615174 / 100, 4693.1816899378 / 100}, {3.11118275, 45.75924865}},
          {{23826.8469081387 / 100, 12604.5563252596 / 100}, {3.11011255, 45.7591626}}};
}

TEST(ControlPointFit, DxfGroundControlPoints) {
  const std::vector<ControlPoint> cps = dxf_points();
  const ControlPointFit f = fit_control_points(cps);
  std::printf("DXF floor: rms %.4f m, scale %.6f, rotation %.6f rad; residuals", f.rms, f.scale, f.georef.rotation);
  for (double r : f.residuals) std::printf(" %.4f", r);
  std::printf(" m\n");
  // Each residual is the ground distance between where the fit puts the point and its fix.
  const GeoTransform t(f.georef);
  double sq = 0;
  ASSERT_EQ(f.residuals.size(), 3u);
  for (size_t i = 0; i < cps.size(); ++i) {
    const double d = geodesic_distance(t.to_wgs84(cps[i].map), cps[i].fix);
    EXPECT_NEAR(f.residuals[i], d, 1e-6) << "point " << i + 1;
    sq += d * d;
  }
  EXPECT_NEAR(f.rms, std::sqrt(sq / 3), 1e-6);
  // A plan in metres: scale 1 within the CLI's tolerance. The three points are no exact
  // similarity of each other (their pairwise distances on the ground and on the plan
  // differ by -0.1 % to +1.6 %, which the source's 3-point affine transform absorbs), so
  // the best similarity leaves residuals of about a metre; none is a blunder.
  EXPECT_LT(std::abs(f.scale - 1), kScaleTolerance);
  EXPECT_LT(f.rms, 1.0);
  for (double r : f.residuals) EXPECT_LT(r, 1.5);
}

// Least squares: no small change of any parameter lowers the sum of the squared ground
// distances (PROJ's geodesic) between the fitted positions and the fixes.
TEST(ControlPointFit, DxfFitIsTheLeastSquaresMinimum) {
  const std::vector<ControlPoint> cps = dxf_points();
  const ControlPointFit f = fit_control_points(cps);
  auto cost = [&](const MapGeoref& g) {
    const GeoTransform t(g);
    double sq = 0;
    for (const ControlPoint& c : cps) sq += std::pow(geodesic_distance(t.to_wgs84(c.map), c.fix), 2);
    return sq;
  };
  const double best = cost(f.georef);
  EXPECT_NEAR(best, 3 * f.rms * f.rms, 1e-6);
  for (int param = 0; param < 4; ++param)
    for (double step : {-1e-3, 1e-3}) {
      MapGeoref g = f.georef;
      double* p[] = {&g.tx, &g.ty, &g.rotation, &g.scale};
      *p[param] += param < 2 ? step * 100 : step * 1e-2;  // 10 cm; 1e-5 rad, 1e-5
      EXPECT_GT(cost(g), best) << "parameter " << param << " step " << step;
    }
}

TEST(ControlPointFit, DxfInCentimetresIsAScaleOfOneHundredth) {
  std::vector<ControlPoint> cps = dxf_points();
  for (ControlPoint& c : cps) c.map = {c.map.x * 100, c.map.y * 100};
  const ControlPointFit f = fit_control_points(cps);
  EXPECT_NEAR(f.scale, fit_control_points(dxf_points()).scale / 100, 1e-9);
}

std::string message_of(const std::vector<ControlPoint>& cps) {
  try {
    fit_control_points(cps);
  } catch (const BadInput& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ControlPointFit, RefusesTooFewOrDegeneratePointsNamingThem) {
  const ControlPoint a{{0, 0}, {3.11, 45.76}};
  EXPECT_NE(message_of({}).find("at least 2"), std::string::npos);
  EXPECT_NE(message_of({a}).find("at least 2, got 1"), std::string::npos);
  EXPECT_NE(message_of({a, {{0, 0}, {3.12, 45.76}}}).find("distinct map positions"), std::string::npos);
  EXPECT_NE(message_of({a, {{10, 0}, {3.11, 45.76}}}).find("distinct fixes"), std::string::npos);
  EXPECT_NE(message_of({a, {{10, 0}, {3.11, 95}}}).find("control point 2: lat"), std::string::npos);
  EXPECT_NE(message_of({a, {{10, 0}, {-181, 45}}}).find("control point 2: lon"), std::string::npos);
  EXPECT_NE(message_of({{{NAN, 0}, {3.11, 45.76}}, a}).find("control point 1: x, y"), std::string::npos);
}

TEST(ControlPointFit, AveragesAcrossTheAntimeridian) {
  const std::vector<Point> two{{0, 0}, {1000, 0}};
  const ControlPointFit f = fit_control_points({{two[0], {179.995, -16.8}}, {two[1], {-179.9955, -16.8}}});
  // The two fixes are about 1 km apart across 180 deg, not a world apart.
  EXPECT_NEAR(f.scale, geodesic_distance({179.995, -16.8}, {-179.9955, -16.8}) / 1000, 1e-6);
  EXPECT_LT(f.rms, 1e-6);
}

}  // namespace
}  // namespace fleetmap
