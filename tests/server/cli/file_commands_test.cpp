// The fleetmap commands that work on a map file without any database (map check, plan,
// scan, map slice with --file), run as built. What they print is checked against facts
// computed here from the file's own lines or from plain geometry.
#include <cmath>
#include <regex>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "tests/server/cli/cli_run.h"

namespace fleetmap::test {
namespace {

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(trim(l));
  return out;
}

// Counted from the seed grammar (docs/map-format.md): every obstacle starts with an
// "obstacle;" line, and the border, each obstacle header and each segment end with "#".
struct SeedCounts {
  size_t obstacles = 0, segments = 0;
  double mx1 = 0, my1 = 0, mx4 = 0, my4 = 0;
};

SeedCounts count_seed(const std::string& text) {
  const std::vector<std::string> l = lines_of(text);
  SeedCounts c;
  size_t hashes = 0;
  for (const std::string& s : l) {
    c.obstacles += s == "obstacle;";
    hashes += s == "#";
  }
  c.segments = hashes - 1 - c.obstacles;
  std::sscanf(l.at(1).c_str(), "%lf;%lf;", &c.mx1, &c.my1);
  std::sscanf(l.at(2).c_str(), "%lf;%lf;", &c.mx4, &c.my4);
  return c;
}

// A 12 m square room (border -1..11) with a 2.5 m wall along x = 7 from y = 1 to 9 and a
// 0.5 m curb along y = 8 from x = 3 to 4, both open polygons (ST 2).
const char* kTinyMap =
    "border;\n-1;11;\n11;-1;\n#\n"
    "obstacle;\n1;2;1;wall;\n#\n7;1;\n7;9;\n2.5;0;wall;\n#\n"
    "obstacle;\n2;2;1;curb;\n#\n3;8;\n4;8;\n0.5;0;curb;\n#\n";

std::string tiny_map() {
  const std::string path = scratch_file("tiny.map");
  spit(path, kTinyMap);
  return path;
}

struct Pt {
  double x, y;
};

double distance_to_segment(Pt p, Pt a, Pt b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

TEST(MapCheckFile, CountsTheRealMapsLikeTheirOwnLines) {
  for (const char* file : {"maps/example-room.map", "maps/example-campus.map"}) {
    const std::string path = repo_path(file);
    const SeedCounts c = count_seed(slurp(path));
    ASSERT_GT(c.segments, 0u) << file;
    const CliResult r = run_cli("fleetmap", "map check " + path);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(: ok: (\d+) obstacles, (\d+) segments, border \(([-0-9.]+), ([-0-9.]+)\) to \(([-0-9.]+), ([-0-9.]+)\))")))
        << r.out;
    EXPECT_EQ(std::stoul(m[1]), c.obstacles) << file;
    EXPECT_EQ(std::stoul(m[2]), c.segments) << file;
    EXPECT_DOUBLE_EQ(std::stod(m[3]), c.mx1) << file;
    EXPECT_DOUBLE_EQ(std::stod(m[4]), c.my1) << file;
    EXPECT_DOUBLE_EQ(std::stod(m[5]), c.mx4) << file;
    EXPECT_DOUBLE_EQ(std::stod(m[6]), c.my4) << file;
  }
}

TEST(MapCheckFile, ByShapeTypeAddsUpToTheObstacles) {
  const std::string path = repo_path("maps/example-campus.map");
  const CliResult r = run_cli("fleetmap", "map check " + path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  size_t sum = 0, types = 0;
  const std::regex by_type(R"(\n  ST (\d) [a-z ]+: (\d+))");
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), by_type); it != std::sregex_iterator(); ++it) {
    sum += std::stoul((*it)[2]);
    ++types;
  }
  EXPECT_EQ(types, 6u) << r.out;  // docs/map-format.md: the campus uses every shape type
  EXPECT_EQ(sum, count_seed(slurp(path)).obstacles);
}

TEST(MapCheckFile, AMalformedLineIsNamedWithItsNumber) {
  // The wall's height (line 10 of the tiny map) must be a number.
  std::string text = kTinyMap;
  ASSERT_EQ(lines_of(text).at(9), "2.5;0;wall;");
  text.replace(text.find("2.5;0;wall;"), 11, "high;0;wall;");
  const std::string bad = scratch_file("bad-height.map");
  spit(bad, text);
  for (const std::string& cmd : {"map check " + bad, "plan --file " + bad + " 2 5 9 5", "scan --file " + bad + " 2 5 0",
                                 "map slice --file " + bad + " --height 1"}) {
    const CliResult r = run_cli("fleetmap", cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd;
    EXPECT_EQ(r.err.rfind(bad + ":10: ", 0), 0u) << cmd << ": " << r.err;
  }
}

TEST(ScanFile, RangeToAWallAtAKnownDistance) {
  const std::string map = tiny_map();
  // From (2, 5) along +x the wall at x = 7 is 5 m away.
  CliResult r = run_cli("fleetmap", "scan --file " + map + " 2 5 0 --beams 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  double angle = -1, range = -1;
  ASSERT_EQ(std::sscanf(r.out.c_str(), "%lf %lf", &angle, &range), 2) << r.out;
  EXPECT_NEAR(angle, 0, 1e-9);
  EXPECT_NEAR(range, 5.0, 1e-6);
  // A laser above the wall's 2.5 m sees nothing: RMAX.
  r = run_cli("fleetmap", "scan --file " + map + " 2 5 0 --beams 1 --height 3 --rmax 15");
  ASSERT_EQ(std::sscanf(r.out.c_str(), "%lf %lf", &angle, &range), 2) << r.out;
  EXPECT_NEAR(range, 15.0, 1e-9);
}

TEST(ScanFile, TheCurbStopsOnlyALowLaser) {
  const std::string map = tiny_map();
  // From (3.5, 5) straight up (+y) the 0.5 m curb at y = 8 is 3 m away.
  for (auto [height, want] : {std::pair{"0.3", 3.0}, std::pair{"0.5", 3.0}, std::pair{"1", 15.0}}) {
    const CliResult r = run_cli("fleetmap", "scan --file " + map + " 3.5 5 1.5707963267948966 --beams 1 --height " +
                                                std::string(height));
    double angle = 0, range = -1;
    ASSERT_EQ(std::sscanf(r.out.c_str(), "%lf %lf", &angle, &range), 2) << r.out << r.err;
    EXPECT_NEAR(range, want, 1e-6) << "laser at " << height << " m";
  }
}

TEST(ScanFile, OneLinePerBeamEvenlyOverTheFieldOfView) {
  const CliResult r = run_cli("fleetmap", "scan --file " + tiny_map() + " 2 5 0.5 --beams 5 --fov 90");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> l = lines_of(r.out);
  ASSERT_EQ(l.size(), 5u) << r.out;
  for (size_t i = 0; i < l.size(); ++i) {
    double angle = 0, range = 0;
    ASSERT_EQ(std::sscanf(l[i].c_str(), "%lf %lf", &angle, &range), 2);
    EXPECT_NEAR(angle, 0.5 - M_PI / 4 + i * M_PI / 8, 1e-6) << i;
  }
}

TEST(PlanFile, GoesAroundTheWallFromStartToGoal) {
  const CliResult r = run_cli("fleetmap", "plan --file " + tiny_map() + " 2 5 9 5 --radius 0.3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<Pt> path;
  double length = -1;
  for (const std::string& l : lines_of(r.out)) {
    Pt p{};
    if (std::sscanf(l.c_str(), "length %lf", &length) == 1) continue;
    ASSERT_EQ(std::sscanf(l.c_str(), "%lf %lf", &p.x, &p.y), 2) << l;
    path.push_back(p);
  }
  ASSERT_GE(path.size(), 3u) << r.out;
  EXPECT_NEAR(path.front().x, 2, 1e-3);
  EXPECT_NEAR(path.front().y, 5, 1e-3);
  EXPECT_NEAR(path.back().x, 9, 1e-3);
  EXPECT_NEAR(path.back().y, 5, 1e-3);
  double sum = 0;
  for (size_t i = 1; i < path.size(); ++i) {
    sum += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
    // Where the path crosses x = 7 it is past one of the wall's ends (y 1..9).
    if ((path[i - 1].x - 7) * (path[i].x - 7) <= 0 && path[i].x != path[i - 1].x) {
      const double t = (7 - path[i - 1].x) / (path[i].x - path[i - 1].x);
      const double y = path[i - 1].y + t * (path[i].y - path[i - 1].y);
      EXPECT_TRUE(y < 1 || y > 9) << "crosses the wall at y " << y;
    }
  }
  for (const Pt& p : path) EXPECT_GE(distance_to_segment(p, {7, 1}, {7, 9}), 0.3 - 2e-3) << p.x << " " << p.y;
  EXPECT_NEAR(length, sum, 0.01);  // waypoints are printed to the millimetre
  // No shorter than the straight lines by the wall's nearer end (7, 1).
  EXPECT_GE(length, std::hypot(5, 4) + std::hypot(2, 4) - 1e-6);
}

TEST(PlanFile, AGoalOnTheWallIsNoPath) {
  const CliResult r = run_cli("fleetmap", "plan --file " + tiny_map() + " 2 5 7 5");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("goal (7.000, 5.000) is blocked"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST(SliceFile, KeepsWhatIsAsHighAsTheLaser) {
  const std::string map = tiny_map();
  // At 1 m the 0.5 m curb goes, the 2.5 m wall stays; at 0.5 m both stay (h >= hL).
  for (auto [height, obstacles] : {std::pair{"1", 1u}, std::pair{"0.5", 2u}, std::pair{"3", 0u}}) {
    const std::string out = scratch_file(std::string("slice-") + height + ".map");
    const CliResult r = run_cli("fleetmap", "map slice --file " + map + " --height " + height + " -o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const SeedCounts c = count_seed(slurp(out));
    EXPECT_EQ(c.obstacles, obstacles) << "at " << height;
    EXPECT_EQ(c.segments, obstacles) << "at " << height;  // one segment each
    EXPECT_DOUBLE_EQ(c.mx1, -1);  // the border stays
    EXPECT_DOUBLE_EQ(c.my4, -1);
    EXPECT_NE(r.err.find(std::to_string(obstacles) + " of 2 obstacles"), std::string::npos) << r.err;
  }
}

TEST(SliceFile, NeitherNameNorFileIsBadInput) {
  const CliResult r = run_cli("fleetmap", "map slice --height 1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("expected a stored map NAME or --file F"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fleetmap::test
