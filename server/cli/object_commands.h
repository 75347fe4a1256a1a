#pragma once
// Operator commands on the semantic layer (docs/semantic-layer.md, protocol/scene_store.h):
//   objects import MAP FILE [--replace] [--add-tags]   GeoJSON scene into a stored map
//   objects export MAP [-o FILE]                        the map's imported scene as GeoJSON
//   objects list MAP [--tag T] [--within X Y R]         live objects (imported and observed)
//   objects near MAP X Y --tag T [-k N]                 k nearest by distance to the footprint
//   tags list | tags set TAG CLASS [--description D] | tags import FILE
//   avoid add MAP --wkt 'POLYGON((...))' [--id KEY] | avoid list MAP | avoid at MAP X Y
// Exit codes (exit_codes.h): 2 malformed file or argument (a GeoJSON error names the
// feature and the field), 4 unknown map, or a key that exists (import without --replace).
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

// Adds the "objects", "tags" and "avoid" subcommands to app.
void add_object_commands(CLI::App& app, CliContext& ctx);

}  // namespace fleetmap
