#pragma once
// What PROJ calls a CRS, for people: "NAD83 / UTM zone 10N" for "EPSG:26910", "unknown"
// for a PROJ string that names none. `map georef NAME` prints it beside the definition.
#include <string>

namespace fleetmap {

// Throws BadInput naming the definition when PROJ cannot read it.
std::string crs_name(const std::string& definition);

}  // namespace fleetmap
