// Map import/export through the real `fleetmap` program and a real MariaDB.
#include <gtest/gtest.h>

#include "common/io/amrl_import.h"
#include "common/io/seed_format.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

long long segments_of(const std::string& name) {
  return scalar("SELECT COUNT(*) FROM segments s JOIN maps m ON m.id = s.map_id WHERE m.name = '" + name + "'");
}

// Everything a failed import could have touched, summed into one fingerprint.
std::string db_fingerprint() {
  auto c = admin();
  mysqlpp::Query q = c->query(
      "SELECT (SELECT COUNT(*) FROM maps), (SELECT COUNT(*) FROM obstacles), (SELECT COUNT(*) FROM segments),"
      " (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', map_id, obstacle_ord, ord, ax, ay, bx, `by`, h, semantic))), 0)"
      "  FROM segments), (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', id, name, mx1, my1))), 0) FROM maps)");
  mysqlpp::StoreQueryResult r = q.store();
  std::string s;
  for (size_t i = 0; i < r.num_fields(); ++i) s += std::string(r[0][i]) + "/";
  return s;
}

TEST(MapImport, RealMapsStoreEveryNonZeroSegment) {
  const struct {
    std::string file, name;
    long long segments, zero;
  } cases[] = {{"GDC1.vectormap.txt", "it_gdc1", 1289, 0}, {"UT_Campus.vectormap.txt", "it_campus", 1533, 51}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    RunResult r = run("fleetmap", "map import " + real_map(c.file) + " --name " + c.name + " --replace");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find(std::to_string(c.zero) + " zero-length lines skipped"), std::string::npos) << r.err;
    EXPECT_EQ(segments_of(c.name), c.segments);
    // Geometry and columns agree, and every segment is in the spatial index's table.
    EXPECT_EQ(scalar("SELECT COUNT(*) FROM segments s JOIN maps m ON m.id = s.map_id WHERE m.name = '" + c.name +
                     "' AND ST_X(ST_StartPoint(s.geom)) = s.ax AND ST_Y(ST_EndPoint(s.geom)) = s.`by`"),
              c.segments);

    // Export gives them back: the same model as the importer read from the file.
    const std::string out = temp_path(c.name + ".map");
    RunResult e = run("fleetmap", "map export " + c.name + " -o " + out);
    ASSERT_EQ(e.exit_code, 0) << e.err;
    const Map exported = read_seed_file(out);
    const Map original = read_amrl_file(real_map(c.file), AmrlOptions{});
    EXPECT_EQ(exported, original);
    EXPECT_EQ(exported.segment_count(), static_cast<size_t>(c.segments));
  }
}

TEST(MapImport, ExampleMapRoundTripsByteForByte) {
  const std::string file = source_path("maps/example-campus.map");
  RunResult r = run("fleetmap", "map import " + file + " --name it_example --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  RunResult e = run("fleetmap", "map export it_example");
  ASSERT_EQ(e.exit_code, 0) << e.err;
  EXPECT_EQ(e.out, read_file(file));
}

TEST(MapImport, MalformedFileAtLineNChangesNothing) {
  ASSERT_EQ(run("fleetmap", "map import " + real_map("GDC1.vectormap.txt") + " --name it_keep --replace").exit_code, 0);
  // A valid prefix of many obstacles, then an error at a known line.
  const Map good = read_amrl_file(real_map("GDC1.vectormap.txt"), AmrlOptions{});
  std::string text = write_seed(good);
  const size_t lines_before = static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
  text += "obstacle;\n99999;1;4;broken;\n#\n1;2;\n3;oops;\n";
  const std::string bad = temp_path("bad.map");
  write_file(bad, text);

  const std::string before = db_fingerprint();
  for (const char* args : {"--name it_new", "--name it_keep --replace"}) {
    SCOPED_TRACE(args);
    RunResult r = run("fleetmap", "map import " + bad + " " + args);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(bad + ":" + std::to_string(lines_before + 5) + ": expected a number for by"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(db_fingerprint(), before);
  }
  EXPECT_EQ(segments_of("it_keep"), 1289);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM maps WHERE name = 'it_new'"), 0);
}

TEST(MapImport, ExistingNameNeedsReplace) {
  ASSERT_EQ(run("fleetmap", "map import " + real_map("GDC1.vectormap.txt") + " --name it_dup --replace").exit_code, 0);
  const std::string before = db_fingerprint();
  RunResult r = run("fleetmap", "map import " + source_path("maps/example-campus.map") + " --name it_dup");
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("--replace"), std::string::npos) << r.err;
  EXPECT_EQ(db_fingerprint(), before);
  // With --replace the old segments are gone, not merged.
  ASSERT_EQ(run("fleetmap", "map import " + source_path("maps/example-campus.map") + " --name it_dup --replace").exit_code,
            0);
  EXPECT_EQ(segments_of("it_dup"),
            static_cast<long long>(read_seed_file(source_path("maps/example-campus.map")).segment_count()));
}

TEST(MapImport, DeleteRemovesEveryRowAndUnknownNamesFail) {
  ASSERT_EQ(run("fleetmap", "map import " + real_map("GDC1.vectormap.txt") + " --name it_del --replace").exit_code, 0);
  const long long id = scalar("SELECT id FROM maps WHERE name = 'it_del'");
  ASSERT_EQ(run("fleetmap", "map delete it_del").exit_code, 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM segments WHERE map_id = " + std::to_string(id)), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM obstacles WHERE map_id = " + std::to_string(id)), 0);
  EXPECT_EQ(run("fleetmap", "map delete it_del").exit_code, 4);
  EXPECT_EQ(run("fleetmap", "map export it_del").exit_code, 4);
}

TEST(MapImport, NamesAreQuotedNotInterpreted) {
  // A name outside the allowed alphabet is refused before any SQL runs.
  RunResult r = run("fleetmap", "map import " + real_map("GDC1.vectormap.txt") + " --name \"x'; DROP TABLE maps; --\"");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("expected a map name"), std::string::npos) << r.err;
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM information_schema.tables WHERE table_schema = DATABASE() AND table_name = 'maps'"), 1);
  // Semantic strings go through quoting: quotes and backslashes survive unchanged.
  const std::string text =
      "border;\n0;10;\n10;0;\n#\nobstacle;\n1;2;1;it's a \\\"wall\\\", ') OR 1=1 -- x;\n#\n1;1;\n2;2;\n"
      "1;0;o'hara\\\\;\n#\n";
  write_file(temp_path("quotes.map"), text);
  ASSERT_EQ(run("fleetmap", "map import " + temp_path("quotes.map") + " --name it_quotes --replace").exit_code, 0);
  RunResult e = run("fleetmap", "map export it_quotes");
  EXPECT_EQ(e.out, text);
}

TEST(MapImport, CheckValidatesWithoutTheDatabase) {
  RunResult ok = run("fleetmap", "map check " + source_path("maps/example-campus.map"));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("ST 5 stairs: "), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("ST 6 ramp: "), std::string::npos) << ok.out;
  write_file(temp_path("check.map"), "border;\n0;10;\n10;0;\n#\nobstacle;\n1;9;1;x;\n#\n");
  RunResult bad = run("fleetmap", "--host 192.0.2.1 map check " + temp_path("check.map"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("check.map:6: expected shape type ST in 1..6"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace fleetmap::test
