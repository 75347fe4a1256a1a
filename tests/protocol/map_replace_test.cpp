// The --drop list and the kept/dropped lines of a replace (protocol/map_replace.h); the
// database side is tests/integration/map_replace_test.cpp.
#include "protocol/map_replace.h"

#include <gtest/gtest.h>

namespace fleetmap {
namespace {

TEST(MapDrop, WordsSetTheirFlagAndAllSetsEvery) {
  EXPECT_EQ(parse_map_drop({}), MapDrop{});
  EXPECT_FALSE(parse_map_drop({}).any());
  const MapDrop some = parse_map_drop({"objects", "georef"});
  EXPECT_TRUE(some.objects && some.georef);
  EXPECT_FALSE(some.areas || some.bounds || some.topology);
  EXPECT_EQ(parse_map_drop({"areas", "all"}), (MapDrop{true, true, true, true, true}));
  for (const char* w : kMapDropWords) EXPECT_TRUE(parse_map_drop({w}).any()) << w;
}

TEST(MapDrop, UnknownWordIsNamed) {
  try {
    parse_map_drop({"objects", "robots"});
    FAIL() << "no exception";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("got 'robots'"), std::string::npos) << e.what();
  }
}

TEST(MapDependents, DescribedOneLinePerKindPresent) {
  EXPECT_TRUE(describe(MapDependents{}).empty());
  MapDependents d;
  d.robots = 1;
  d.objects = 3;
  d.bounds = true;
  d.topology = true;
  d.topo_nodes = 1;
  d.topo_edges = 0;
  d.georef = "EPSG:26910";
  const std::vector<std::string> want = {"1 robot (stay assigned)", "3 objects", "bounds", "topology (1 node, 0 edges)",
                                         "georeference (EPSG:26910)"};
  EXPECT_EQ(describe(d), want);
}

TEST(MapWouldStrand, ListsTwentyAndCountsTheRest) {
  std::vector<StrandedDependent> s;
  for (int i = 0; i < 23; ++i) s.push_back({"robot r" + std::to_string(i), "outside the border"});
  const MapWouldStrand e("campus", s);
  const std::string m = e.what();
  EXPECT_NE(m.find("replacing map 'campus' would strand 23 dependents"), std::string::npos) << m;
  EXPECT_NE(m.find("\n  robot r19: outside the border\n"), std::string::npos) << m;
  EXPECT_EQ(m.find("robot r20:"), std::string::npos) << m;
  EXPECT_NE(m.find("... and 3 more"), std::string::npos) << m;
  EXPECT_EQ(e.stranded().size(), 23u);
}

}  // namespace
}  // namespace fleetmap
