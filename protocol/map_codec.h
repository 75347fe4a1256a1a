#pragma once
// SetMap payloads (SPEC 5.4): the seed text, or the same text in MariaDB's COMPRESS()
// format (4-byte little-endian length, then a zlib stream; empty text -> empty), so that
// `SELECT UNCOMPRESS(payload) FROM sa` shows the map to an inspector.
#include <string>
#include <string_view>

#include "common/map/map.h"
#include "common/map/map_validation.h"
#include "protocol/params.h"

namespace fleetmap {

std::string mariadb_compress(std::string_view text);
// Throws std::invalid_argument on a truncated or corrupt blob, or a length over max_bytes.
std::string mariadb_uncompress(std::string_view blob, size_t max_bytes = 256u << 20);

std::string encode_map(const Map& m, MapEncoding e);
// A window's payload is read with MapKind::Window. Throws MapFormatError / invalid_argument.
Map decode_map(std::string_view payload, MapEncoding e, MapKind kind);

SetMapParams set_map_params(const Map& m, MapEncoding e);

}  // namespace fleetmap
