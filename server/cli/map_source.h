#pragma once
// Where an operator command reads a map from (a stored map by name, or a map file: seed
// format, AMRL when the name ends with .vectormap.txt, without any database) and where
// it writes its output.
#include <string>

#include "common/map/map.h"
#include "common/scene/scene.h"
#include "app/cli_context.h"

namespace fleetmap {

bool is_amrl_file(const std::string& file);

// file empty: the stored map `name`; otherwise the file (a GIS file through OGR, by its
// name: common/gis/ogr_import.h). Throws MapNotFound, MapFormatError, BadInput.
Map load_map_source(const std::string& name, const std::string& file, CliContext& ctx);

// Where the objects of a command's map come from: a stored map's scene
// (SceneStore::load), or with --file an optional --objects F.geojson; --no-objects: none.
struct ObjectSource {
  std::string objects_file;  // --objects (only with --file)
  bool no_objects = false;   // --no-objects: the bare segments
};

// Adds --objects F.geojson and --no-objects to cmd.
void add_object_source_options(CLI::App& cmd, ObjectSource& source);

// The scene to add to the map (empty with --no-objects, or a file without --objects).
// Throws BadInput for --objects with a stored map or with --no-objects,
// SceneFormatError (a malformed file, named), MapNotFound.
Scene load_scene_source(const std::string& name, const std::string& file, const ObjectSource& source,
                        CliContext& ctx);

// The map as a laser at laser_height sees it: load_map_source plus the scene's elements
// seen at that height (common/slicing/scene_laser.h). *objects (if given) gets how many
// obstacles the objects added.
Map load_map_at_height(const std::string& name, const std::string& file, const ObjectSource& source,
                       double laser_height, CliContext& ctx, size_t* objects = nullptr);

// text to file, or to standard output when file is empty or "-"; throws IoError on a
// write error.
void write_output(const std::string& text, const std::string& file);

}  // namespace fleetmap
