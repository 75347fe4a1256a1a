#pragma once
// After a map changes, its GIS layers follow (protocol/gis_layers.h, docs/gis-layers.md):
// the map frame's CRS from common/gis, the tables from protocol. The map change has
// been committed already, so a failure here is a warning on stderr, not the command's.
#include <string>

#include <mysql++/mysql++.h>

namespace fleetmap {

// Rebuilds map `name`'s layers (and drops those of maps that are gone).
void publish_gis_layers(mysqlpp::Connection& c, const std::string& name);
// Drops the layers of maps that are gone (after map delete).
void withdraw_gis_layers(mysqlpp::Connection& c);

}  // namespace fleetmap
