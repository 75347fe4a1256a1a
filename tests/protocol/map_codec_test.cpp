// SetMap payloads (SPEC 5.4): MariaDB's COMPRESS() format by hand (4-byte little-endian
// length, then a zlib stream; empty -> empty), round trips, broken blobs refused, the map
// encodings; and, for the record, bytes per square metre of a real campus map.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <zlib.h>

#include "common/io/amrl_import.h"
#include "common/map/map_window.h"
#include "common/io/seed_format.h"
#include "protocol/map_codec.h"

namespace fleetmap {
namespace {

std::filesystem::path repo_root() { return FLEETMAP_SOURCE_DIR; }

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + p.string());
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string example_text() { return slurp(repo_root() / "maps" / "example-campus.map"); }

uint32_t header_of(const std::string& blob) {
  uint32_t n = 0;
  for (int i = 0; i < 4; ++i) n |= static_cast<uint32_t>(static_cast<unsigned char>(blob[i])) << (8 * i);
  return n;
}

std::string random_bytes(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::string s(n, '\0');
  for (char& c : s) c = static_cast<char>(rng() & 0xFF);
  return s;
}

TEST(CodecMariadbCompress, EmptyIsEmptyBothWays) {
  EXPECT_EQ(mariadb_compress(""), "");
  EXPECT_EQ(mariadb_uncompress(""), "");
}

TEST(CodecMariadbCompress, OneByte) {
  const std::string blob = mariadb_compress("a");
  ASSERT_GE(blob.size(), 5u);
  EXPECT_EQ(blob.substr(0, 4), std::string("\x01\x00\x00\x00", 4));
  EXPECT_EQ(mariadb_uncompress(blob), "a");
  EXPECT_EQ(mariadb_uncompress(mariadb_compress(std::string(1, '\0'))), std::string(1, '\0'));
}

TEST(CodecMariadbCompress, LengthHeaderIsFourBytesLittleEndianThenAZlibStream) {
  for (size_t n : {size_t{1}, size_t{255}, size_t{256}, size_t{258}, size_t{65535}, size_t{70000}, size_t{0x01020304}}) {
    const std::string text(n, 'm');
    const std::string blob = mariadb_compress(text);
    ASSERT_GE(blob.size(), 6u) << n;
    EXPECT_EQ(static_cast<unsigned char>(blob[0]), n & 0xFF) << n;
    EXPECT_EQ(static_cast<unsigned char>(blob[1]), (n >> 8) & 0xFF) << n;
    EXPECT_EQ(static_cast<unsigned char>(blob[2]), (n >> 16) & 0xFF) << n;
    EXPECT_EQ(static_cast<unsigned char>(blob[3]), (n >> 24) & 0xFF) << n;
    EXPECT_EQ(header_of(blob), n);
    // A zlib header (RFC 1950): deflate, and CMF*256+FLG a multiple of 31.
    const unsigned cmf = static_cast<unsigned char>(blob[4]), flg = static_cast<unsigned char>(blob[5]);
    EXPECT_EQ(cmf & 0x0F, 8u) << n;
    EXPECT_EQ((cmf * 256 + flg) % 31, 0u) << n;
    // Plain zlib reads the rest back.
    std::string out(n, '\0');
    uLongf len = static_cast<uLongf>(n);
    ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(out.data()), &len, reinterpret_cast<const Bytef*>(blob.data() + 4),
                         static_cast<uLong>(blob.size() - 4)),
              Z_OK)
        << n;
    EXPECT_EQ(len, n);
    EXPECT_TRUE(out == text) << n;
    EXPECT_TRUE(mariadb_uncompress(blob) == text) << n;
  }
  // Hand-made blob: our reader accepts any zlib level, as MariaDB writes its own default.
  const std::string text = "hand made";
  uLongf bound = compressBound(static_cast<uLong>(text.size()));
  std::string z(bound, '\0');
  ASSERT_EQ(compress2(reinterpret_cast<Bytef*>(z.data()), &bound, reinterpret_cast<const Bytef*>(text.data()),
                      static_cast<uLong>(text.size()), Z_BEST_COMPRESSION),
            Z_OK);
  z.resize(bound);
  EXPECT_EQ(mariadb_uncompress(std::string("\x09\x00\x00\x00", 4) + z), text);
}

TEST(CodecMariadbCompress, RoundTrips) {
  const std::string map_text = example_text();
  ASSERT_GT(map_text.size(), 1000u);
  std::string all_bytes;
  for (int i = 0; i < 256; ++i) all_bytes += static_cast<char>(i);
  for (const std::string& t : {map_text, all_bytes, std::string("x'); DROP TABLE maps; --"), random_bytes(1 << 20, 7),
                               std::string(3u << 20, ' ')}) {
    const std::string blob = mariadb_compress(t);
    EXPECT_EQ(header_of(blob), t.size());
    EXPECT_TRUE(mariadb_uncompress(blob) == t) << t.size();
  }
  EXPECT_LT(mariadb_compress(map_text).size(), map_text.size() / 2);
}

TEST(CodecMariadbUncompress, TooShortBlobsAreRefused) {
  for (size_t n = 1; n < 5; ++n)
    EXPECT_THROW(mariadb_uncompress(std::string(n, '\x01')), std::invalid_argument) << n;
}

TEST(CodecMariadbUncompress, TruncatedBlobsAreRefused) {
  const std::string blob = mariadb_compress(example_text());
  for (size_t keep : {size_t{5}, size_t{6}, blob.size() / 2, blob.size() - 4, blob.size() - 1})
    EXPECT_THROW(mariadb_uncompress(blob.substr(0, keep)), std::invalid_argument) << keep << " of " << blob.size();
  // Only the header.
  EXPECT_THROW(mariadb_uncompress(blob.substr(0, 4)), std::invalid_argument);
}

TEST(CodecMariadbUncompress, CorruptBlobsAreRefused) {
  const std::string text = example_text();
  const std::string blob = mariadb_compress(text);
  // Not a zlib stream at all.
  EXPECT_THROW(mariadb_uncompress(std::string("\x05\x00\x00\x00hello", 9)), std::invalid_argument);
  EXPECT_THROW(mariadb_uncompress(std::string(4, '\x10') + random_bytes(100, 3)), std::invalid_argument);
  // A flipped byte in the zlib header, the deflate data, and the Adler-32 trailer.
  for (size_t at : {size_t{4}, size_t{5}, blob.size() / 2, blob.size() - 2}) {
    std::string bad = blob;
    bad[at] = static_cast<char>(bad[at] ^ 0x5A);
    EXPECT_THROW(mariadb_uncompress(bad), std::invalid_argument) << "byte " << at;
  }
  // A header that does not match the stream's length, either way.
  for (long delta : {-1L, +1L, -100L, +100L}) {
    std::string bad = blob;
    const uint32_t n = static_cast<uint32_t>(static_cast<long>(text.size()) + delta);
    for (int i = 0; i < 4; ++i) bad[i] = static_cast<char>((n >> (8 * i)) & 0xFF);
    EXPECT_THROW(mariadb_uncompress(bad), std::invalid_argument) << "length " << delta;
  }
}

TEST(CodecMariadbUncompress, LengthHeaderOverTheLimitIsRefusedBeforeAllocating) {
  // 4 GiB - 1 announced: refused by the default limit (256 MiB), nothing allocated.
  std::string blob = mariadb_compress("small");
  blob[0] = blob[1] = blob[2] = blob[3] = '\xFF';
  EXPECT_THROW(mariadb_uncompress(blob), std::invalid_argument);
  // 256 MiB + 1 announced.
  const uint32_t over = (256u << 20) + 1;
  for (int i = 0; i < 4; ++i) blob[i] = static_cast<char>((over >> (8 * i)) & 0xFF);
  EXPECT_THROW(mariadb_uncompress(blob), std::invalid_argument);
  // An explicit limit: exactly the size passes, one byte less does not.
  const std::string text(1000, 'z');
  const std::string ok = mariadb_compress(text);
  EXPECT_EQ(mariadb_uncompress(ok, 1000), text);
  EXPECT_THROW(mariadb_uncompress(ok, 999), std::invalid_argument);
  try {
    mariadb_uncompress(ok, 999);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("999"), std::string::npos) << e.what();
  }
}

TEST(CodecMapPayload, BothEncodingsRoundTripTheExampleMap) {
  const std::string text = example_text();
  const Map m = read_seed(text, "example-campus.map");
  EXPECT_EQ(encode_map(m, MapEncoding::Seed), write_seed(m));
  for (MapEncoding e : {MapEncoding::Seed, MapEncoding::SeedCompress}) {
    const std::string payload = encode_map(m, e);
    EXPECT_EQ(decode_map(payload, e, MapKind::Whole), m) << name(e);
  }
  // The compressed payload is the seed text in COMPRESS() form.
  EXPECT_EQ(mariadb_uncompress(encode_map(m, MapEncoding::SeedCompress)), write_seed(m));
  // A window is read as a window (its cut obstacles are accepted).
  const Map w = clip_map(m, window_rect(m.border, {20, 30}, 10, 8));
  for (MapEncoding e : {MapEncoding::Seed, MapEncoding::SeedCompress})
    EXPECT_EQ(decode_map(encode_map(w, e), e, MapKind::Window), w) << name(e);
}

TEST(CodecMapPayload, BrokenPayloadsAreRefused) {
  const Map m = read_seed(example_text());
  std::string z = encode_map(m, MapEncoding::SeedCompress);
  z.resize(z.size() - 3);
  EXPECT_THROW(decode_map(z, MapEncoding::SeedCompress, MapKind::Whole), std::invalid_argument);
  EXPECT_THROW(decode_map("border;\n0;1;\n", MapEncoding::Seed, MapKind::Whole), MapFormatError);
  // The seed text sent as if it were compressed, and the other way round.
  EXPECT_ANY_THROW(decode_map(encode_map(m, MapEncoding::Seed), MapEncoding::SeedCompress, MapKind::Whole));
  EXPECT_ANY_THROW(decode_map(encode_map(m, MapEncoding::SeedCompress), MapEncoding::Seed, MapKind::Whole));
}

TEST(CodecMapPayload, SetMapParamsDescribeTheMap) {
  const Map m = read_seed(example_text());
  for (MapEncoding e : {MapEncoding::Seed, MapEncoding::SeedCompress}) {
    const SetMapParams p = set_map_params(m, e);
    EXPECT_EQ(p.border[0], m.border.mx1);
    EXPECT_EQ(p.border[1], m.border.my1);
    EXPECT_EQ(p.border[2], m.border.mx4);
    EXPECT_EQ(p.border[3], m.border.my4);
    EXPECT_EQ(p.obstacles, m.obstacles.size());
    EXPECT_EQ(p.segments, m.segment_count());
    EXPECT_EQ(p.encoding, e);
    EXPECT_EQ(encode(p)["encoding"], std::string(name(e)));
  }
  EXPECT_EQ(encode(set_map_params(m, MapEncoding::Seed))["border"], Json::parse("[0, 40, 60, 0]"));
}

// Informational (no assertion on the figures): SetMap payload size per square metre of
// map for both encodings, on the UT campus (AMRL import, default options; area = border).
TEST(CodecMapPayloadDensity, UtCampusBytesPerSquareMetre) {
  const std::filesystem::path file = std::filesystem::path(FLEETMAP_REAL_MAPS) / "UT_Campus.vectormap.txt";
  ASSERT_TRUE(std::filesystem::exists(file)) << file;
  AmrlReport rep;
  const Map m = read_amrl_file(file.string(), AmrlOptions{}, &rep);
  const double width = m.border.mx4 - m.border.mx1, height = m.border.my1 - m.border.my4;
  const double area = width * height;
  ASSERT_GT(area, 0);
  const std::string seed = encode_map(m, MapEncoding::Seed);
  const std::string comp = encode_map(m, MapEncoding::SeedCompress);
  EXPECT_EQ(decode_map(comp, MapEncoding::SeedCompress, MapKind::Whole), m);

  char line[512];
  std::snprintf(line, sizeof line,
                "UT_Campus: %zu obstacles, %zu segments, border %.1f m x %.1f m = %.0f m^2\n"
                "  whole map, seed          : %9zu bytes = %.4f bytes/m^2 (%.1f bytes/segment)\n"
                "  whole map, seed+compress : %9zu bytes = %.4f bytes/m^2 (%.1f bytes/segment, ratio %.2f)\n",
                m.obstacles.size(), m.segment_count(), width, height, area, seed.size(), seed.size() / area,
                static_cast<double>(seed.size()) / m.segment_count(), comp.size(), comp.size() / area,
                static_cast<double>(comp.size()) / m.segment_count(), static_cast<double>(comp.size()) / seed.size());
  std::cout << line;
  RecordProperty("ut_campus_area_m2", std::to_string(area));
  RecordProperty("seed_bytes_per_m2", std::to_string(seed.size() / area));
  RecordProperty("seed_compress_bytes_per_m2", std::to_string(comp.size() / area));

  // The 100 m x 100 m windows a robot gets on Ready for a large map (server default
  // ready_window_m), averaged over a 5 x 5 grid of centres inside the border.
  size_t ws = 0, wc = 0;
  double warea = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const Point c{m.border.mx1 + width * (i + 0.5) / 5, m.border.my4 + height * (j + 0.5) / 5};
      const Rect r = window_rect(m.border, c, 100, 100);
      const Map w = clip_map(m, r);
      ws += encode_map(w, MapEncoding::Seed).size();
      wc += encode_map(w, MapEncoding::SeedCompress).size();
      warea += (r.xmax - r.xmin) * (r.ymax - r.ymin);
    }
  std::snprintf(line, sizeof line,
                "  100 m windows (25), seed          : %.4f bytes/m^2\n"
                "  100 m windows (25), seed+compress : %.4f bytes/m^2\n",
                ws / warea, wc / warea);
  std::cout << line;
}

}  // namespace
}  // namespace fleetmap
