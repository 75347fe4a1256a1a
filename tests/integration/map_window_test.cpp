// The window query behind GetMap: a spatial-index lookup whose result equals the
// brute-force clip of common/ on random windows of both real maps.
#include <random>

#include <gtest/gtest.h>

#include "common/io/amrl_import.h"
#include "common/map/map_window.h"
#include "common/io/seed_format.h"
#include "protocol/connection.h"
#include "protocol/map_store.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

class MapWindow : public ::testing::TestWithParam<std::string> {};

TEST_P(MapWindow, EqualsBruteForceClipOnRandomWindows) {
  const std::string file = GetParam();
  const std::string name = "win_" + file.substr(0, file.find('.'));
  const Map model = read_amrl_file(real_map(file), AmrlOptions{});
  auto c = connect_as(Role::Operator);
  MapStore store(*c);
  store.import(model, name, file, true);

  std::mt19937 rng(20261128);
  const Rect b = model.border.rect();
  std::uniform_real_distribution<double> ux(b.xmin - 5, b.xmax + 5), uy(b.ymin - 5, b.ymax + 5), us(0.5, 60);
  size_t non_empty = 0, cut = 0;
  for (int i = 0; i < 200; ++i) {
    const Point centre{ux(rng), uy(rng)};
    const double w = us(rng), h = us(rng);
    const Rect r = window_rect(model.border, centre, w, h);
    const Map expected = clip_map(model, r);
    const Map got = store.window(name, r);
    ASSERT_EQ(got, expected) << "window " << i << " centre " << centre.x << "," << centre.y << " size " << w << "x" << h;
    non_empty += !expected.obstacles.empty();
    for (const Obstacle& o : expected.obstacles)
      for (const Segment& s : o.segments) cut += !(s.a.x > r.xmin && s.a.x < r.xmax && s.b.x > r.xmin && s.b.x < r.xmax &&
                                                   s.a.y > r.ymin && s.a.y < r.ymax && s.b.y > r.ymin && s.b.y < r.ymax);
  }
  // The comparison means something only if windows hold segments and some were cut.
  EXPECT_GT(non_empty, 50u);
  EXPECT_GT(cut, 20u);
}

TEST_P(MapWindow, UsesTheSpatialIndex) {
  const std::string file = GetParam();
  const std::string name = "win_" + file.substr(0, file.find('.'));
  auto c = connect_as(Role::Operator);
  MapStore store(*c);
  store.import(read_amrl_file(real_map(file), AmrlOptions{}), name, file, true);
  EXPECT_EQ(store.window_index(name, Rect{-10, -10, 10, 10}), "sx_segments_geom");
}

INSTANTIATE_TEST_SUITE_P(RealMaps, MapWindow, ::testing::Values("GDC1.vectormap.txt", "UT_Campus.vectormap.txt"),
                         [](const auto& info) { return info.param.substr(0, info.param.find('.')); });

TEST(WindowCommand, PrintsThePartialMapInSeedFormat) {
  ASSERT_EQ(run("fleetmap", "map import " + source_path("maps/example-campus.map") + " --name win_example --replace")
                .exit_code,
            0);
  const Map whole = read_seed_file(source_path("maps/example-campus.map"));
  RunResult r = run("fleetmap", "window win_example 20 15 16 10");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Map part = read_seed(r.out, "window", MapKind::Window);
  EXPECT_EQ(part, clip_map(whole, window_rect(whole.border, {20, 15}, 16, 10)));
  EXPECT_EQ(part.border.rect(), intersection(Rect{12, 10, 28, 20}, whole.border.rect()));
  EXPECT_EQ(run("fleetmap", "window win_example 20 15 0 10").exit_code, 2);
  EXPECT_EQ(run("fleetmap", "window win_example 20 15 nan 10").exit_code, 2);
  EXPECT_EQ(run("fleetmap", "window no_such_map 0 0 1 1").exit_code, 4);
}

}  // namespace
}  // namespace fleetmap::test
