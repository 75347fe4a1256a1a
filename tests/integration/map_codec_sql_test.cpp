// Our COMPRESS() format against MariaDB's own (SPEC 5.4): `SELECT UNCOMPRESS(x)` of our
// mariadb_compress output gives the text back, and our mariadb_uncompress reads what
// `SELECT COMPRESS(...)` wrote. Binary travels as HEX()/UNHEX() so that no client-side
// escaping or character set is involved.
#include <cstdio>
#include <iostream>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <zlib.h>

#include "common/io/seed_format.h"
#include "protocol/map_codec.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

std::string to_hex(const std::string& s) {
  static const char* d = "0123456789ABCDEF";
  std::string h;
  h.reserve(s.size() * 2);
  for (unsigned char c : s) {
    h += d[c >> 4];
    h += d[c & 15];
  }
  return h;
}

std::string from_hex(const std::string& h) {
  std::string s;
  for (size_t i = 0; i + 1 < h.size(); i += 2) s += static_cast<char>(std::stoi(h.substr(i, 2), nullptr, 16));
  return s;
}

// One string value from the administrator's connection (NULL -> "<NULL>").
std::string value(mysqlpp::Connection& c, const std::string& sql) {
  mysqlpp::Query q = c.query(sql);
  mysqlpp::StoreQueryResult r = q.store();
  if (r.empty()) return "<no row>";
  if (r[0][0].is_null()) return "<NULL>";
  return std::string(r[0][0].data(), r[0][0].length());
}

// MariaDB's UNCOMPRESS() of blob, and COMPRESS() of text.
std::string sql_uncompress(mysqlpp::Connection& c, const std::string& blob) {
  const std::string h = value(c, "SELECT HEX(UNCOMPRESS(UNHEX('" + to_hex(blob) + "')))");
  return h == "<NULL>" ? h : from_hex(h);
}
std::string sql_compress(mysqlpp::Connection& c, const std::string& text) {
  return from_hex(value(c, "SELECT HEX(COMPRESS(UNHEX('" + to_hex(text) + "')))"));
}

std::vector<std::pair<std::string, std::string>> samples() {
  std::string all_bytes;
  for (int i = 0; i < 256; ++i) all_bytes += static_cast<char>(i);
  std::mt19937 rng(11);
  std::string noise(200000, '\0');
  for (char& ch : noise) ch = static_cast<char>(rng() & 0xFF);
  return {
      {"one byte", "a"},
      {"a NUL", std::string(1, '\0')},
      {"example map", read_file(source_path("maps/example-campus.map"))},
      {"all byte values", all_bytes},
      {"quotes", "x'); DROP TABLE maps; -- \" \\ %"},
      {"200 kB of noise", noise},
      {"1 MB of spaces", std::string(1 << 20, ' ')},
  };
}

TEST(MapCodecSql, MariadbUncompressesOurCompress) {
  auto c = admin();
  for (const auto& [what, text] : samples()) {
    const std::string blob = mariadb_compress(text);
    EXPECT_TRUE(sql_uncompress(*c, blob) == text) << what;
    EXPECT_EQ(value(*c, "SELECT UNCOMPRESSED_LENGTH(UNHEX('" + to_hex(blob) + "'))"), std::to_string(text.size()))
        << what;
  }
  // The empty text is the empty blob, and MariaDB agrees.
  EXPECT_EQ(mariadb_compress(""), "");
  EXPECT_EQ(value(*c, "SELECT HEX(UNCOMPRESS(''))"), "");
}

TEST(MapCodecSql, WeUncompressMariadbCompress) {
  auto c = admin();
  for (const auto& [what, text] : samples()) {
    const std::string blob = sql_compress(*c, text);
    ASSERT_GE(blob.size(), 5u) << what;
    EXPECT_TRUE(mariadb_uncompress(blob) == text) << what;
  }
  EXPECT_EQ(sql_compress(*c, ""), "");
  EXPECT_EQ(mariadb_uncompress(sql_compress(*c, "")), "");
}

TEST(MapCodecSql, MariadbsTrailingDotAfterASpaceIsRead) {
  // MariaDB appends '.' to a COMPRESS() result whose last byte is a space (so that a CHAR
  // column would not strip it). The last byte is the low byte of the Adler-32 checksum:
  // find a text whose checksum ends in 0x20.
  std::string text;
  for (int i = 1; i < 10000; ++i) {
    const std::string t = "obstacle;" + std::string(i, 'a');
    if ((adler32(adler32(0, nullptr, 0), reinterpret_cast<const Bytef*>(t.data()), static_cast<uInt>(t.size())) &
         0xFF) == 0x20) {
      text = t;
      break;
    }
  }
  ASSERT_FALSE(text.empty());
  auto c = admin();
  const std::string blob = sql_compress(*c, text);
  ASSERT_FALSE(blob.empty());
  EXPECT_EQ(blob.back(), '.') << "MariaDB no longer pads; the case below is then moot";
  EXPECT_EQ(mariadb_uncompress(blob), text);
  // Our own blob ends in the space; MariaDB reads it too.
  const std::string ours = mariadb_compress(text);
  EXPECT_EQ(ours.back(), ' ');
  EXPECT_EQ(sql_uncompress(*c, ours), text);
}

TEST(MapCodecSql, MariadbRefusesWhatWeRefuse) {
  auto c = admin();
  std::string blob = mariadb_compress(read_file(source_path("maps/example-campus.map")));
  blob.resize(blob.size() / 2);
  EXPECT_THROW(mariadb_uncompress(blob), std::invalid_argument);
  EXPECT_EQ(sql_uncompress(*c, blob), "<NULL>");  // MariaDB: NULL and a warning
}

// Informational: the SetMap payload a robot really gets on Ready for the UT campus (AMRL
// import through the CLI, whole map: it is under max_full_map_segments), in both
// encodings, per square metre of the map's border. No assertion on the figures.
TEST(MapCodecSql, SetMapBytesPerSquareMetreOnTheWire) {
  RunResult imp = run("fleetmap", "map import " + real_map("UT_Campus.vectormap.txt") + " --name codec_ut --replace");
  ASSERT_EQ(imp.exit_code, 0) << imp.err;
  const std::string pw = add_robot("codec_r", "codec_ut");
  ServerProcess server("--alive-period 10", "codec_server.log");
  SqlRobot robot("codec_r", pw);
  char line[256];
  for (const char* enc : {"seed", "seed+compress"}) {
    robot.send("Ready", std::string(R"({"magic": 1, "encoding": ")") + enc + "\"}");
    auto a = robot.receive(2, std::chrono::seconds(30));
    ASSERT_EQ(a.size(), 2u) << server.log().substr(0, 5000);
    ASSERT_EQ(a[1].op, "SetMap");
    ASSERT_TRUE(a[1].payload);
    const auto b = a[1].params["border"];
    const double area = (b[2].get<double>() - b[0].get<double>()) * (b[1].get<double>() - b[3].get<double>());
    const size_t segments = a[1].params["segments"].get<size_t>();
    EXPECT_EQ(segments, 1533u);
    const Map m = decode_map(*a[1].payload, *parse_map_encoding(enc), MapKind::Whole);
    EXPECT_EQ(m.segment_count(), segments);
    std::snprintf(line, sizeof line, "UT_Campus on the wire (Ready, %s): %zu bytes / %.0f m^2 = %.4f bytes/m^2, %zu segments\n",
                  enc, a[1].payload->size(), area, a[1].payload->size() / area, segments);
    std::cout << line;
  }
  run("fleetmap", "robot remove codec_r");
}

}  // namespace
}  // namespace fleetmap::test
