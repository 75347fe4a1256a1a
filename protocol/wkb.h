#pragma once
// Geometries read back from MariaDB as ST_AsBinary (WKB): exact doubles, unlike ST_AsText.
#include <mysql++/mysql++.h>

#include "common/geometry/polygon.h"

namespace fleetmap {

// A WKB polygon's outer ring, without its closing vertex. Throws DbError when the bytes
// are not a little-endian WKB polygon.
Polygon polygon_from_wkb(const mysqlpp::String& wkb);

}  // namespace fleetmap
