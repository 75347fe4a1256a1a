// fleetmap scan: hand-computed ranges, the seed and fast methods agree, stored map = file.
#include <sstream>

#include <gtest/gtest.h>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

std::vector<std::pair<double, double>> parse(const std::string& out) {
  std::vector<std::pair<double, double>> v;
  std::istringstream in(out);
  double a, r;
  while (in >> a >> r) v.emplace_back(a, r);
  return v;
}

TEST(ScanCommand, HandComputedRanges) {
  const std::string file = source_path("maps/example-campus.map");
  // West from (25, 30): the library's east wall (x = 20, 12 m high) 5 m away.
  RunResult r = run("fleetmap", "scan --file " + file + " 25 30 3.141592653589793 --beams 1 --fov 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto v = parse(r.out);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NEAR(v[0].second, 5.0, 1e-6);
  // Three beams over 90 degrees north from (30, 10): the bench (0.45 m) passes under a laser
  // at 0.6 m and stops one at 0.3 m; beams at theta -45, theta, theta +45 degrees.
  r = run("fleetmap", "scan --file " + file + " 30 10 1.5707963267948966 --beams 3 --fov 90 --height 0.3");
  v = parse(r.out);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_NEAR(v[0].first, M_PI / 4, 1e-6);
  EXPECT_NEAR(v[2].first, 3 * M_PI / 4, 1e-6);
  EXPECT_NEAR(v[1].second, 4.0, 1e-6);  // the bench's middle vertex (30, 14)
  r = run("fleetmap", "scan --file " + file + " 30 10 1.5707963267948966 --beams 3 --fov 90 --height 0.6");
  v = parse(r.out);
  EXPECT_NEAR(v[1].second, 6.0, 1e-6);  // over the bench, onto the fountain (0.8 m) at y = 16
  // Nothing within RMAX: RMAX.
  r = run("fleetmap", "scan --file " + file + " 25 8 1.5707963267948966 --beams 1 --fov 0 --rmax 10");
  EXPECT_NEAR(parse(r.out).at(0).second, 10.0, 1e-9);
  EXPECT_EQ(run("fleetmap", "scan --file " + file + " 25 8 nan").exit_code, 2);
}

TEST(ScanCommand, SeedAndFastAgreeAndStoredEqualsFile) {
  ensure_example_map("scan_map");
  const std::string file = source_path("maps/example-campus.map");
  for (const char* pose : {"25 8 1.0", "45 17 1.5707963", "10 11 -2.0", "30 30 0.3"}) {
    RunResult fast = run("fleetmap", std::string("scan scan_map ") + pose + " --height 0.4");
    RunResult seed = run("fleetmap", "scan --file " + file + " " + pose + " --height 0.4 --method seed");
    ASSERT_EQ(fast.exit_code, 0) << fast.err;
    auto f = parse(fast.out), s = parse(seed.out);
    ASSERT_EQ(f.size(), 131u);
    ASSERT_EQ(s.size(), 131u);
    for (size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(f[i].second, s[i].second, 1e-6) << pose << " beam " << i;
  }
}

}  // namespace
}  // namespace fleetmap::test
