#include "server/cli/object_commands.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <set>
#include <sstream>

#include "common/geometry/number_format.h"
#include "common/io/scene_geojson.h"
#include "protocol/map_store.h"
#include "protocol/scene_store.h"
#include "app/exit_codes.h"
#include "server/cli/map_source.h"

namespace fleetmap {
namespace {

// Runs a command body (which returns its exit code) and turns the semantic layer's errors
// into exit codes here; anything else goes on to main's handlers.
void guarded(int* exit_code, const std::function<int()>& body) {
  try {
    *exit_code = body();
  } catch (const MapNotFound& e) {
    std::cerr << "fleetmap: " << e.what() << "\n";
    *exit_code = exit_code::kNotFound;
  } catch (const SceneKeyExists& e) {
    std::cerr << "fleetmap: " << e.what() << "\n";
    *exit_code = exit_code::kNotFound;
  }
}

std::string read_text(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read '" + file + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void check_point(double x, double y) {
  if (!std::isfinite(x) || !std::isfinite(y)) throw std::invalid_argument("expected finite coordinates X Y");
}

// One object per line, tab-separated under a header: what 'objects list' and 'near' print.
void print_objects(const std::vector<ObjectRow>& rows) {
  std::printf("key\ttag\tclass\tdynamic\tsource\tseen_at\texpires_at\telements\tdistance\n");
  for (const ObjectRow& o : rows) {
    const std::string source = o.source == "observed" ? "observed by " + o.robot + " (" + o.label + ")" : o.source;
    std::printf("%s\t%s\t%s\t%s\t%s\t%s\t%s\t%zu\t%s\n", o.key.c_str(), o.tag.c_str(), o.tag_class.c_str(),
                o.dynamic ? "yes" : "no", source.c_str(), o.seen_at.c_str(),
                o.expires_at.empty() ? "-" : o.expires_at.c_str(), o.elements,
                o.distance ? format_number(*o.distance).c_str() : "-");
  }
}

void add_objects(CLI::App& app, CliContext& ctx, int* exit_code) {
  auto* objects = app.add_subcommand("objects", "the semantic layer: objects with tags and footprints on a stored map");
  objects->require_subcommand(1);
  objects->footer("Exit codes: 0 ok, 1 failure (database, I/O), 2 malformed file or argument, "
                  "4 unknown map, or an object key that exists (import without --replace), 64 usage.");

  {
    auto map = std::make_shared<std::string>(), file = std::make_shared<std::string>();
    auto opt = std::make_shared<SceneImportOptions>();
    auto* cmd = objects->add_subcommand(
        "import", "store a GeoJSON scene (objects, avoided areas, bounds) into a stored map, in one transaction; "
                  "a malformed file is refused with the feature and field at fault and nothing is stored");
    cmd->add_option("MAP", *map, "name of a stored map")->required();
    cmd->add_option("FILE", *file, "GeoJSON FeatureCollection, e.g. maps/example-room.geojson")->required();
    cmd->add_flag("--replace", opt->replace,
                  "first delete the map's imported objects, avoided areas and bounds (robots' observations stay); "
                  "without it, a key already stored is an error");
    cmd->add_flag("--add-tags", opt->add_tags, "tags not in the vocabulary are added with class 'obstacle' "
                                               "(without it they are an error)");
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        if (auto e = check_map_name(*map)) throw std::invalid_argument(*e);
        const std::string text = read_text(*file);
        SceneStore store(ctx.connection());
        SceneReadOptions read;
        read.check_tags = !opt->add_tags;
        if (read.check_tags)
          for (const TagInfo& t : store.tags()) read.known_tags.insert(t.tag);
        Scene scene;
        try {
          scene = read_scene_geojson(text, read);
        } catch (const SceneFormatError& e) {
          std::cerr << *file << ": " << e.what() << "\n";
          return exit_code::kBadInput;
        }
        const SceneImportReport r = store.import(*map, scene, *opt);
        std::printf("imported into '%s': %zu objects (%zu elements), %zu avoided areas%s\n", map->c_str(), r.objects,
                    r.elements, r.avoided, r.bounds ? ", bounds" : "");
        if (opt->replace)
          std::printf("replaced: %zu objects, %zu avoided areas\n", r.replaced_objects, r.replaced_avoided);
        for (const std::string& t : r.tags_added) std::printf("tag added: %s (obstacle)\n", t.c_str());
        return exit_code::kOk;
      });
    });
  }

  {
    auto map = std::make_shared<std::string>(), out = std::make_shared<std::string>();
    auto* cmd = objects->add_subcommand(
        "export", "write a map's imported objects, avoided areas and bounds as GeoJSON (what import reads; "
                  "robots' observations are not part of it)");
    cmd->add_option("MAP", *map, "name of a stored map")->required();
    cmd->add_option("-o,--output", *out, "output file (default: standard output)");
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        write_output(write_scene_geojson(SceneStore(ctx.connection()).load(*map)), *out);
        return exit_code::kOk;
      });
    });
  }

  {
    auto map = std::make_shared<std::string>(), tag = std::make_shared<std::string>();
    auto within = std::make_shared<std::vector<double>>();
    auto* cmd = objects->add_subcommand(
        "list", "live objects of a map (imported, and observations not expired), tab-separated: by key, or "
                "nearest first with --within");
    cmd->add_option("MAP", *map, "name of a stored map")->required();
    cmd->add_option("--tag", *tag, "only objects with this tag");
    cmd->add_option("--within", *within, "X Y R: only objects whose footprint comes within R metres of (X, Y)")
        ->expected(3)
        ->allow_extra_args(false);
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        ObjectFilter f;
        f.tag = *tag;
        if (!within->empty()) {
          check_point((*within)[0], (*within)[1]);
          if (!((*within)[2] >= 0) || !std::isfinite((*within)[2]))
            throw std::invalid_argument("expected a radius R >= 0 in --within X Y R");
          f.centre = Point{(*within)[0], (*within)[1]};
          f.radius = (*within)[2];
        }
        print_objects(SceneStore(ctx.connection()).list(*map, f));
        return exit_code::kOk;
      });
    });
  }

  {
    auto map = std::make_shared<std::string>(), tag = std::make_shared<std::string>();
    auto xy = std::make_shared<std::array<double, 2>>();
    auto k = std::make_shared<int>(1);
    auto* cmd = objects->add_subcommand(
        "near", "the k live objects with a tag nearest (X, Y), by distance to their footprints (0 inside), "
                "nearest first, tab-separated");
    cmd->add_option("MAP", *map, "name of a stored map")->required();
    cmd->add_option("X", (*xy)[0], "x (m)")->required();
    cmd->add_option("Y", (*xy)[1], "y (m)")->required();
    cmd->add_option("--tag", *tag, "tag of the objects sought, e.g. door")->required();
    cmd->add_option("-k", *k, "how many")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        check_point((*xy)[0], (*xy)[1]);
        print_objects(SceneStore(ctx.connection()).near(*map, {(*xy)[0], (*xy)[1]}, *tag, static_cast<size_t>(*k)));
        return exit_code::kOk;
      });
    });
  }
}

void add_tags(CLI::App& app, CliContext& ctx, int* exit_code) {
  auto* tags = app.add_subcommand("tags", "the tag vocabulary: each tag's class (obstacle, landmark, interactable, "
                                          "dynamic) and description");
  tags->require_subcommand(1);
  {
    auto* cmd = tags->add_subcommand("list", "every tag, tab-separated: tag, class, description");
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        for (const TagInfo& t : SceneStore(ctx.connection()).tags())
          std::printf("%s\t%s\t%s\n", t.tag.c_str(), t.tag_class.c_str(), t.description.c_str());
        return exit_code::kOk;
      });
    });
  }
  {
    auto tag = std::make_shared<std::string>(), cls = std::make_shared<std::string>();
    auto description = std::make_shared<std::string>();
    auto* cmd = tags->add_subcommand("set", "add a tag, or change its class (and description)");
    cmd->add_option("TAG", *tag, "the tag (no ':')")->required();
    cmd->add_option("CLASS", *cls, "obstacle, landmark, interactable or dynamic")->required();
    auto* d = cmd->add_option("--description", *description, "what the tag means (kept when not given)");
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        const bool added = SceneStore(ctx.connection())
                               .set_tag(*tag, *cls, d->count() ? std::optional<std::string>(*description) : std::nullopt);
        std::printf("%s tag '%s' (%s)\n", added ? "added" : "set", tag->c_str(), cls->c_str());
        return exit_code::kOk;
      });
    });
  }
  {
    auto file = std::make_shared<std::string>();
    auto* cmd = tags->add_subcommand("import", "add or update the tags of a tag table (JSON array of "
                                               "{tag, class, description}, e.g. maps/example-room.tags.json)");
    cmd->add_option("FILE", *file, "tag table")->required();
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        std::vector<TagInfo> table;
        try {
          table = read_tag_table_json(read_text(*file));
        } catch (const SceneFormatError& e) {
          std::cerr << *file << ": " << e.what() << "\n";
          return exit_code::kBadInput;
        }
        SceneStore store(ctx.connection());
        size_t added = 0;
        for (const TagInfo& t : table) added += store.set_tag(t.tag, t.tag_class, t.description);
        std::printf("%zu tags: %zu added, %zu set\n", table.size(), added, table.size() - added);
        return exit_code::kOk;
      });
    });
  }
}

void add_avoid(CLI::App& app, CliContext& ctx, int* exit_code) {
  auto* avoid = app.add_subcommand("avoid", "avoided areas: polygons no robot may enter (columns, keep-out zones)");
  avoid->require_subcommand(1);
  avoid->footer("Exit codes: 0 ok, 1 failure, 2 malformed polygon or argument, 4 unknown map or key exists, 64 usage.");
  {
    auto map = std::make_shared<std::string>(), wkt = std::make_shared<std::string>(),
         key = std::make_shared<std::string>();
    auto* cmd = avoid->add_subcommand("add", "add an avoided area to a stored map; prints its key");
    cmd->add_option("MAP", *map, "name of a stored map")->required();
    cmd->add_option("--wkt", *wkt, "the area as WKT, e.g. 'POLYGON((0 0, 2 0, 2 1, 0 1, 0 0))' (one ring)")->required();
    cmd->add_option("--id", *key, "its key (default: avoid-N)");
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        std::printf("%s\n", SceneStore(ctx.connection()).add_avoided_area(*map, *wkt, *key).c_str());
        return exit_code::kOk;
      });
    });
  }
  {
    auto map = std::make_shared<std::string>();
    auto* cmd = avoid->add_subcommand("list", "a map's avoided areas, tab-separated: key, WKT");
    cmd->add_option("MAP", *map, "name of a stored map")->required();
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        for (const AvoidedArea& a : SceneStore(ctx.connection()).avoided_areas(*map))
          std::printf("%s\t%s\n", a.id.c_str(), polygon_to_wkt(a.area).c_str());
        return exit_code::kOk;
      });
    });
  }
  {
    auto map = std::make_shared<std::string>();
    auto xy = std::make_shared<std::array<double, 2>>();
    auto* cmd = avoid->add_subcommand("at", "keys of the avoided areas that contain (X, Y), outline included; "
                                            "nothing printed when none");
    cmd->add_option("MAP", *map, "name of a stored map")->required();
    cmd->add_option("X", (*xy)[0], "x (m)")->required();
    cmd->add_option("Y", (*xy)[1], "y (m)")->required();
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        check_point((*xy)[0], (*xy)[1]);
        for (const std::string& k : SceneStore(ctx.connection()).avoided_areas_containing(*map, {(*xy)[0], (*xy)[1]}))
          std::printf("%s\n", k.c_str());
        return exit_code::kOk;
      });
    });
  }
}

}  // namespace

void add_object_commands(CLI::App& app, CliContext& ctx, int* exit_code) {
  add_objects(app, ctx, exit_code);
  add_tags(app, ctx, exit_code);
  add_avoid(app, ctx, exit_code);
}

}  // namespace fleetmap
