#include "protocol/map_codec.h"

#include <stdexcept>

#include <zlib.h>

#include "common/io/seed_format.h"

namespace fleetmap {

std::string mariadb_compress(std::string_view text) {
  if (text.empty()) return {};
  uLongf bound = compressBound(static_cast<uLong>(text.size()));
  std::string out(4 + bound, '\0');
  const uint32_t n = static_cast<uint32_t>(text.size());
  for (int i = 0; i < 4; ++i) out[i] = static_cast<char>((n >> (8 * i)) & 0xFF);
  if (compress2(reinterpret_cast<Bytef*>(out.data() + 4), &bound, reinterpret_cast<const Bytef*>(text.data()),
                static_cast<uLong>(text.size()), Z_BEST_SPEED) != Z_OK)
    throw std::runtime_error("zlib compress failed");
  out.resize(4 + bound);
  return out;
}

std::string mariadb_uncompress(std::string_view blob, size_t max_bytes) {
  if (blob.empty()) return {};
  if (blob.size() < 5) throw std::invalid_argument("expected a COMPRESS() blob, got " + std::to_string(blob.size()) + " bytes");
  uint32_t n = 0;
  for (int i = 0; i < 4; ++i) n |= static_cast<uint32_t>(static_cast<unsigned char>(blob[i])) << (8 * i);
  if (n > max_bytes) throw std::invalid_argument("expected an uncompressed size <= " + std::to_string(max_bytes));
  std::string out(n, '\0');
  uLongf len = n;
  if (uncompress(reinterpret_cast<Bytef*>(out.data()), &len, reinterpret_cast<const Bytef*>(blob.data() + 4),
                 static_cast<uLong>(blob.size() - 4)) != Z_OK || len != n)
    throw std::invalid_argument("expected a valid zlib stream in the COMPRESS() blob");
  return out;
}

std::string encode_map(const Map& m, MapEncoding e) {
  std::string text = write_seed(m);
  return e == MapEncoding::Seed ? text : mariadb_compress(text);
}

Map decode_map(std::string_view payload, MapEncoding e, MapKind kind) {
  if (e == MapEncoding::Seed) return read_seed(payload, "SetMap", kind);
  return read_seed(mariadb_uncompress(payload), "SetMap", kind);
}

SetMapParams set_map_params(const Map& m, MapEncoding e) {
  SetMapParams p;
  p.border[0] = m.border.mx1;
  p.border[1] = m.border.my1;
  p.border[2] = m.border.mx4;
  p.border[3] = m.border.my4;
  p.obstacles = m.obstacles.size();
  p.segments = m.segment_count();
  p.encoding = e;
  return p;
}

}  // namespace fleetmap
