#include "server/cli/map_source.h"

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "common/core/error.h"
#include "common/gis/ogr_import.h"
#include "common/io/read_map_file.h"
#include "common/io/scene_geojson.h"
#include "common/slicing/scene_laser.h"
#include "protocol/map_store.h"
#include "protocol/scene_store.h"

namespace fleetmap {

bool is_amrl_file(const std::string& file) { return map_file_format(file) == MapFileFormat::Amrl; }

Map load_map_source(const std::string& name, const std::string& file, CliContext& ctx) {
  if (file.empty()) return MapStore(ctx.connection()).load(name);
  // A GIS file with the built-in rules (docs/gis-import.md); its objects are not loaded.
  if (is_ogr_source(file)) return import_ogr(file).map;
  return read_map_file(file);
}

void add_object_source_options(CLI::App& cmd, ObjectSource& source) {
  cmd.add_option("--objects", source.objects_file,
                 "with --file: the map's objects (GeoJSON, docs/semantic-layer.md); a stored map's come from the "
                 "database");
  cmd.add_flag("--no-objects", source.no_objects, "the bare segments, without the map's objects");
}

Scene load_scene_source(const std::string& name, const std::string& file, const ObjectSource& source,
                        CliContext& ctx) {
  if (!source.objects_file.empty() && source.no_objects)
    throw BadInput("expected --objects F or --no-objects, not both");
  if (!source.objects_file.empty() && file.empty())
    throw BadInput("expected --objects only with --file: a stored map's objects are in the database");
  if (source.no_objects) return {};
  if (!file.empty()) {
    if (source.objects_file.empty()) return {};
    std::ifstream in(source.objects_file, std::ios::binary);
    if (!in) throw IoError("cannot read '" + source.objects_file + "'");
    std::ostringstream text;
    text << in.rdbuf();
    try {
      return read_scene_geojson(text.str());
    } catch (const SceneFormatError& e) {
      throw FileFormatError(source.objects_file + ": " + e.what());
    }
  }
  return SceneStore(ctx.connection()).load(name);
}

Map load_map_at_height(const std::string& name, const std::string& file, const ObjectSource& source,
                       double laser_height, CliContext& ctx, size_t* objects) {
  const Scene scene = load_scene_source(name, file, source, ctx);  // argument errors first
  const Map map = load_map_source(name, file, ctx);
  Map seen = with_objects_at_height(map, scene, laser_height);
  if (objects) *objects = seen.obstacles.size() - map.obstacles.size();
  return seen;
}

void write_output(const std::string& text, const std::string& file) {
  if (file.empty() || file == "-") {
    std::cout << text;
    return;
  }
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw IoError("cannot write '" + file + "'");
}

}  // namespace fleetmap
