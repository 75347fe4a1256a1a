#pragma once
// `--json` of the list commands that are not about robots (`map list`): the table's
// columns as one JSON array, numbers as numbers, what is not set as null, so scripts
// and the API read the same fields the operator sees.
#include <vector>

#include <nlohmann/json.hpp>

#include "protocol/map_store.h"

namespace fleetmap {

// [{name, id, obstacles, segments, border: [mx1, my1, mx4, my4], source, imported_at,
//   georef: {crs, tx, ty, rotation, scale} | null}]
nlohmann::json maps_json(const std::vector<MapInfo>& maps);

}  // namespace fleetmap
