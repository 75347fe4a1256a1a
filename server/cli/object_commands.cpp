#include "server/cli/object_commands.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/geometry/number_format.h"
#include "common/io/scene_geojson.h"
#include "server/cli/gis_export.h"
#include "protocol/map_store.h"
#include "protocol/scene_store.h"
#include "app/exit_codes.h"
#include "common/core/error.h"
#include "server/cli/command.h"
#include "server/cli/gis_publish.h"
#include "server/cli/map_source.h"

namespace fleetmap {
namespace {

std::string read_text(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError("cannot read '" + file + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void check_point(double x, double y) {
  if (!std::isfinite(x) || !std::isfinite(y)) throw BadInput("expected finite coordinates X Y");
}

// --json of 'objects list' and 'near': the table's columns, numbers as numbers, '-' as null.
void print_objects_json(const std::vector<ObjectRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const ObjectRow& o : rows) {
    nlohmann::json observed;  // null unless a robot saw it
    if (o.source == "observed") observed = {{"robot", o.robot}, {"label", o.label}};
    out.push_back({{"key", o.key}, {"tag", o.tag}, {"class", o.tag_class}, {"dynamic", o.dynamic},
                   {"source", o.source}, {"observed", observed}, {"seen_at", o.seen_at},
                   {"expires_at", o.expires_at.empty() ? nlohmann::json() : nlohmann::json(o.expires_at)},
                   {"elements", o.elements}, {"distance", o.distance ? nlohmann::json(*o.distance) : nlohmann::json()}});
  }
  std::cout << out.dump() << std::endl;
}

// One object per line, tab-separated under a header: what 'objects list' and 'near' print.
void print_objects(const std::vector<ObjectRow>& rows, bool json = false) {
  if (json) return print_objects_json(rows);
  std::printf("key\ttag\tclass\tdynamic\tsource\tseen_at\texpires_at\telements\tdistance\n");
  for (const ObjectRow& o : rows) {
    const std::string source = o.source == "observed" ? "observed by " + o.robot + " (" + o.label + ")" : o.source;
    std::printf("%s\t%s\t%s\t%s\t%s\t%s\t%s\t%zu\t%s\n", o.key.c_str(), o.tag.c_str(), o.tag_class.c_str(),
                o.dynamic ? "yes" : "no", source.c_str(), o.seen_at.c_str(),
                o.expires_at.empty() ? "-" : o.expires_at.c_str(), o.elements,
                o.distance ? format_number(*o.distance).c_str() : "-");
  }
}

// MAP KEY: one object or avoided area of a stored map (remove).
struct SceneKeyArgs {
  std::string map, key;
};

// objects import MAP FILE: a GeoJSON scene into a stored map, one transaction.
struct ObjectsImportArgs {
  std::string map, file;
  SceneImportOptions options;
};

int run_objects_import(const ObjectsImportArgs& a, CliContext& ctx) {
  if (auto e = check_map_name(a.map)) throw BadInput(*e);
  const std::string text = read_text(a.file);
  SceneStore store(ctx.connection());
  SceneReadOptions read;
  read.check_tags = !a.options.add_tags;
  if (read.check_tags)
    for (const TagInfo& t : store.tags()) read.known_tags.insert(t.tag);
  Scene scene;
  try {
    scene = read_scene_geojson(text, read);
  } catch (const SceneFormatError& e) {
    throw FileFormatError(a.file + ": " + e.what());
  }
  const SceneImportReport r = store.import(a.map, scene, a.options);
  std::printf("imported into '%s': %zu objects (%zu elements), %zu avoided areas%s\n", a.map.c_str(), r.objects,
              r.elements, r.avoided, r.bounds ? ", bounds" : "");
  if (a.options.replace)
    std::printf("replaced: %zu objects, %zu avoided areas\n", r.replaced_objects, r.replaced_avoided);
  for (const std::string& t : r.tags_added) std::printf("tag added: %s (obstacle)\n", t.c_str());
  publish_gis_layers(ctx.connection(), a.map);
  return exit_code::kOk;
}

void add_objects_import(CLI::App& objects, CliContext& ctx) {
  auto a = std::make_shared<ObjectsImportArgs>();
  auto* cmd = objects.add_subcommand(
      "import", "store a GeoJSON scene (objects, avoided areas, bounds) into a stored map, in one transaction; "
                "a malformed file is refused with the feature and field at fault and nothing is stored");
  cmd->add_option("MAP", a->map, "name of a stored map")->required();
  cmd->add_option("FILE", a->file, "GeoJSON FeatureCollection, e.g. maps/example-room.geojson")->required();
  cmd->add_flag("--replace", a->options.replace,
                "first delete the map's imported objects, avoided areas and bounds (robots' observations stay); "
                "without it, a key already stored is an error");
  cmd->add_flag("--add-tags", a->options.add_tags, "tags not in the vocabulary are added with class 'obstacle' "
                                                   "(without it they are an error)");
  run_with(*cmd, a, ctx, run_objects_import);
}

// objects export MAP [--format geojson|gpkg|fgb|DRIVER] [--crs map|wgs84|base] [-o FILE]
struct ObjectsExportArgs {
  std::string map, out, format = "geojson";
  GisExportArgs gis;
};

int run_objects_export(const ObjectsExportArgs& a, CliContext& ctx) {
  const MapInfo info = MapStore(ctx.connection()).info(a.map);
  const Scene scene = SceneStore(ctx.connection()).load(a.map);
  if (a.format == "geojson") {
    write_output(write_scene_geojson(scene, geojson_frame(a.gis, a.map, info.georef)), a.out);
  } else {
    OgrExport e(a.out, ogr_export_options(a.gis, a.format, a.out, a.map, info.georef));
    e.add_scene(scene);
    finish_ogr_export(e, a.out);
  }
  return exit_code::kOk;
}

void add_objects_export(CLI::App& objects, CliContext& ctx) {
  auto a = std::make_shared<ObjectsExportArgs>();
  auto* cmd = objects.add_subcommand(
      "export", "write a map's imported objects, avoided areas and bounds as GeoJSON (with --crs map: what import "
                "reads) or GIS layers (robots' observations are not part of it)");
  cmd->add_option("MAP", a->map, "name of a stored map")->required();
  cmd->add_option("--format", a->format, "geojson, gpkg, fgb or a GDAL vector driver's short name")
      ->capture_default_str();
  cmd->add_option("-o,--output", a->out, "output file (default: standard output; GDAL formats need one)");
  add_gis_export_options(cmd, a->gis);
  run_with(*cmd, a, ctx, run_objects_export);
}

// objects list MAP [--tag T] [--within X Y R]
struct ObjectsListArgs {
  std::string map, tag;
  std::vector<double> within;
  bool json = false;
};

int run_objects_list(const ObjectsListArgs& a, CliContext& ctx) {
  ObjectFilter f;
  f.tag = a.tag;
  if (!a.within.empty()) {
    check_point(a.within[0], a.within[1]);
    if (!(a.within[2] >= 0) || !std::isfinite(a.within[2]))
      throw BadInput("expected a radius R >= 0 in --within X Y R");
    f.centre = Point{a.within[0], a.within[1]};
    f.radius = a.within[2];
  }
  print_objects(SceneStore(ctx.connection()).list(a.map, f), a.json);
  return exit_code::kOk;
}

void add_objects_list(CLI::App& objects, CliContext& ctx) {
  auto a = std::make_shared<ObjectsListArgs>();
  auto* cmd = objects.add_subcommand(
      "list", "live objects of a map (imported, and observations not expired), tab-separated: by key, or "
              "nearest first with --within");
  cmd->add_option("MAP", a->map, "name of a stored map")->required();
  cmd->add_option("--tag", a->tag, "only objects with this tag");
  cmd->add_option("--within", a->within, "X Y R: only objects whose footprint comes within R metres of (X, Y)")
      ->expected(3)
      ->allow_extra_args(false);
  cmd->add_flag("--json", a->json, "a JSON array instead of the table");
  run_with(*cmd, a, ctx, run_objects_list);
}

// objects near MAP X Y --tag T [-k N]
struct ObjectsNearArgs {
  std::string map, tag;
  double x = 0, y = 0;
  int k = 1;
  bool json = false;
};

int run_objects_near(const ObjectsNearArgs& a, CliContext& ctx) {
  check_point(a.x, a.y);
  print_objects(SceneStore(ctx.connection()).near(a.map, {a.x, a.y}, a.tag, static_cast<size_t>(a.k)), a.json);
  return exit_code::kOk;
}

void add_objects_near(CLI::App& objects, CliContext& ctx) {
  auto a = std::make_shared<ObjectsNearArgs>();
  auto* cmd = objects.add_subcommand(
      "near", "the k live objects with a tag nearest (X, Y), by distance to their footprints (0 inside), "
              "nearest first, tab-separated");
  cmd->add_option("MAP", a->map, "name of a stored map")->required();
  cmd->add_option("X", a->x, "x (m)")->required();
  cmd->add_option("Y", a->y, "y (m)")->required();
  cmd->add_option("--tag", a->tag, "tag of the objects sought, e.g. door")->required();
  cmd->add_option("-k", a->k, "how many")->check(CLI::PositiveNumber)->capture_default_str();
  cmd->add_flag("--json", a->json, "a JSON array instead of the table");
  run_with(*cmd, a, ctx, run_objects_near);
}

// objects remove MAP KEY
int run_objects_remove(const SceneKeyArgs& a, CliContext& ctx) {
  if (!SceneStore(ctx.connection()).remove_object(a.map, a.key))
    throw NotFound("map '" + a.map + "' has no object '" + a.key + "' (fleetmap objects list " + a.map + ")");
  std::printf("object '%s' removed from '%s'\n", a.key.c_str(), a.map.c_str());
  return exit_code::kOk;
}

void add_objects_remove(CLI::App& objects, CliContext& ctx) {
  auto a = std::make_shared<SceneKeyArgs>();
  auto* cmd = objects.add_subcommand(
      "remove", "delete one object of a stored map (imported or observed), with its elements; the robots' maps "
                "and plans no longer show it");
  cmd->add_option("MAP", a->map, "name of a stored map")->required();
  cmd->add_option("KEY", a->key, "the object's key (objects list)")->required();
  run_with(*cmd, a, ctx, run_objects_remove);
}

void add_objects(CLI::App& app, CliContext& ctx) {
  auto* objects = app.add_subcommand("objects", "the semantic layer: objects with tags and footprints on a stored map");
  objects->require_subcommand(1);
  objects->footer("Exit codes: 0 ok, 1 failure (database, I/O), 2 malformed file or argument, "
                  "4 unknown map, an object key that exists (import without --replace) or no such key (remove), "
                  "64 usage.");
  add_objects_import(*objects, ctx);
  add_objects_export(*objects, ctx);
  add_objects_list(*objects, ctx);
  add_objects_near(*objects, ctx);
  add_objects_remove(*objects, ctx);
}

// tags list
struct TagsListArgs {};

int run_tags_list(const TagsListArgs&, CliContext& ctx) {
  for (const TagInfo& t : SceneStore(ctx.connection()).tags())
    std::printf("%s\t%s\t%s\n", t.tag.c_str(), t.tag_class.c_str(), t.description.c_str());
  return exit_code::kOk;
}

void add_tags_list(CLI::App& tags, CliContext& ctx) {
  auto* cmd = tags.add_subcommand("list", "every tag, tab-separated: tag, class, description");
  run_with(*cmd, std::make_shared<TagsListArgs>(), ctx, run_tags_list);
}

// tags set TAG CLASS [--description D]
struct TagsSetArgs {
  std::string tag, tag_class;
  std::optional<std::string> description;  // kept when not given
};

int run_tags_set(const TagsSetArgs& a, CliContext& ctx) {
  const bool added = SceneStore(ctx.connection()).set_tag(a.tag, a.tag_class, a.description);
  std::printf("%s tag '%s' (%s)\n", added ? "added" : "set", a.tag.c_str(), a.tag_class.c_str());
  return exit_code::kOk;
}

void add_tags_set(CLI::App& tags, CliContext& ctx) {
  auto a = std::make_shared<TagsSetArgs>();
  auto* cmd = tags.add_subcommand("set", "add a tag, or change its class (and description)");
  cmd->add_option("TAG", a->tag, "the tag (no ':')")->required();
  cmd->add_option("CLASS", a->tag_class, "obstacle, landmark, interactable or dynamic")->required();
  cmd->add_option("--description", a->description, "what the tag means (kept when not given)");
  run_with(*cmd, a, ctx, run_tags_set);
}

// tags import FILE: a tag table.
struct TagsImportArgs {
  std::string file;
};

int run_tags_import(const TagsImportArgs& a, CliContext& ctx) {
  std::vector<TagInfo> table;
  try {
    table = read_tag_table_json(read_text(a.file));
  } catch (const SceneFormatError& e) {
    throw FileFormatError(a.file + ": " + e.what());
  }
  SceneStore store(ctx.connection());
  size_t added = 0;
  for (const TagInfo& t : table) added += store.set_tag(t.tag, t.tag_class, t.description);
  std::printf("%zu tags: %zu added, %zu set\n", table.size(), added, table.size() - added);
  return exit_code::kOk;
}

void add_tags_import(CLI::App& tags, CliContext& ctx) {
  auto a = std::make_shared<TagsImportArgs>();
  auto* cmd = tags.add_subcommand("import", "add or update the tags of a tag table (JSON array of "
                                            "{tag, class, description}, e.g. maps/example-room.tags.json)");
  cmd->add_option("FILE", a->file, "tag table")->required();
  run_with(*cmd, a, ctx, run_tags_import);
}

void add_tags(CLI::App& app, CliContext& ctx) {
  auto* tags = app.add_subcommand("tags", "the tag vocabulary: each tag's class (obstacle, landmark, interactable, "
                                          "dynamic) and description");
  tags->require_subcommand(1);
  add_tags_list(*tags, ctx);
  add_tags_set(*tags, ctx);
  add_tags_import(*tags, ctx);
}

// avoid add MAP --wkt 'POLYGON((...))' [--id KEY]: prints the key.
struct AvoidAddArgs {
  std::string map, wkt, key;
};

int run_avoid_add(const AvoidAddArgs& a, CliContext& ctx) {
  std::printf("%s\n", SceneStore(ctx.connection()).add_avoided_area(a.map, a.wkt, a.key).c_str());
  publish_gis_layers(ctx.connection(), a.map);
  return exit_code::kOk;
}

void add_avoid_add(CLI::App& avoid, CliContext& ctx) {
  auto a = std::make_shared<AvoidAddArgs>();
  auto* cmd = avoid.add_subcommand("add", "add an avoided area to a stored map; prints its key");
  cmd->add_option("MAP", a->map, "name of a stored map")->required();
  cmd->add_option("--wkt", a->wkt, "the area as WKT, e.g. 'POLYGON((0 0, 2 0, 2 1, 0 1, 0 0))' (one ring)")
      ->type_name("WKT")
      ->required();
  cmd->add_option("--id", a->key, "its key (default: avoid-N)");
  run_with(*cmd, a, ctx, run_avoid_add);
}

// avoid list MAP
struct AvoidListArgs {
  std::string map;
  bool json = false;
};

int run_avoid_list(const AvoidListArgs& a, CliContext& ctx) {
  if (a.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const AvoidedArea& area : SceneStore(ctx.connection()).avoided_areas(a.map))
      out.push_back({{"key", area.id}, {"wkt", polygon_to_wkt(area.area)}});
    std::cout << out.dump() << std::endl;
    return exit_code::kOk;
  }
  for (const AvoidedArea& area : SceneStore(ctx.connection()).avoided_areas(a.map))
    std::printf("%s\t%s\n", area.id.c_str(), polygon_to_wkt(area.area).c_str());
  return exit_code::kOk;
}

void add_avoid_list(CLI::App& avoid, CliContext& ctx) {
  auto a = std::make_shared<AvoidListArgs>();
  auto* cmd = avoid.add_subcommand("list", "a map's avoided areas, tab-separated: key, WKT");
  cmd->add_option("MAP", a->map, "name of a stored map")->required();
  cmd->add_flag("--json", a->json, "a JSON array of {key, wkt}");
  run_with(*cmd, a, ctx, run_avoid_list);
}

// avoid at MAP X Y
struct AvoidAtArgs {
  std::string map;
  double x = 0, y = 0;
};

int run_avoid_at(const AvoidAtArgs& a, CliContext& ctx) {
  check_point(a.x, a.y);
  for (const std::string& k : SceneStore(ctx.connection()).avoided_areas_containing(a.map, {a.x, a.y}))
    std::printf("%s\n", k.c_str());
  return exit_code::kOk;
}

void add_avoid_at(CLI::App& avoid, CliContext& ctx) {
  auto a = std::make_shared<AvoidAtArgs>();
  auto* cmd = avoid.add_subcommand("at", "keys of the avoided areas that contain (X, Y), outline included; "
                                         "nothing printed when none");
  cmd->add_option("MAP", a->map, "name of a stored map")->required();
  cmd->add_option("X", a->x, "x (m)")->required();
  cmd->add_option("Y", a->y, "y (m)")->required();
  run_with(*cmd, a, ctx, run_avoid_at);
}

// avoid remove MAP KEY
int run_avoid_remove(const SceneKeyArgs& a, CliContext& ctx) {
  if (!SceneStore(ctx.connection()).remove_avoided_area(a.map, a.key))
    throw NotFound("map '" + a.map + "' has no avoided area '" + a.key + "' (fleetmap avoid list " + a.map + ")");
  std::printf("avoided area '%s' removed from '%s'\n", a.key.c_str(), a.map.c_str());
  return exit_code::kOk;
}

void add_avoid_remove(CLI::App& avoid, CliContext& ctx) {
  auto a = std::make_shared<SceneKeyArgs>();
  auto* cmd = avoid.add_subcommand("remove", "delete one avoided area of a stored map; robots may enter it again");
  cmd->add_option("MAP", a->map, "name of a stored map")->required();
  cmd->add_option("KEY", a->key, "the area's key (avoid list)")->required();
  run_with(*cmd, a, ctx, run_avoid_remove);
}

void add_avoid(CLI::App& app, CliContext& ctx) {
  auto* avoid = app.add_subcommand("avoid", "avoided areas: polygons no robot may enter (columns, keep-out zones)");
  avoid->require_subcommand(1);
  avoid->footer("Exit codes: 0 ok, 1 failure, 2 malformed polygon or argument, 4 unknown map, key exists (add) or "
                "no such key (remove), 64 usage.");
  add_avoid_add(*avoid, ctx);
  add_avoid_list(*avoid, ctx);
  add_avoid_at(*avoid, ctx);
  add_avoid_remove(*avoid, ctx);
}

}  // namespace

void add_object_commands(CLI::App& app, CliContext& ctx) {
  add_objects(app, ctx);
  add_tags(app, ctx);
  add_avoid(app, ctx);
}

}  // namespace fleetmap
