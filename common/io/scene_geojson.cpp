#include "common/io/scene_geojson.h"

#include <cmath>
#include <map>

#include <nlohmann/json.hpp>

#include "common/map/map_validation.h"
#include "common/geometry/number_format.h"

namespace fleetmap {
namespace {

using Json = nlohmann::json;

std::string describe(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return j.get<bool>() ? "true" : "false";
    case Json::value_t::string: return j.dump();
    case Json::value_t::array: return "an array of " + std::to_string(j.size());
    case Json::value_t::object: return "an object";
    case Json::value_t::discarded: return "nothing";
    default: return "the number " + j.dump();
  }
}

// Reads one feature (or the document, index -1); every error names index and field.
class Reader {
 public:
  explicit Reader(int index, std::string_view item = "feature") : index_(index), item_(item) {}

  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    throw SceneFormatError(index_, field, message, item_);
  }

  const Json& member(const Json& obj, const std::string& key, const std::string& field) const {
    auto it = obj.find(key);
    if (it == obj.end()) fail(field, "expected a member \"" + key + "\", got none");
    return *it;
  }

  const Json& array(const Json& j, const std::string& field) const {
    if (!j.is_array()) fail(field, "expected an array, got " + describe(j));
    return j;
  }

  std::string text(const Json& j, const std::string& field, std::string_view what) const {
    if (!j.is_string()) fail(field, "expected a string, got " + describe(j));
    std::string s = j.get<std::string>();
    if (s.empty()) fail(field, "expected a non-empty " + std::string(what) + ", got \"\"");
    // Tags and ids become segment semantics (scene_laser.h) and database text.
    if (auto e = check_text(s, what)) fail(field, *e);
    return s;
  }

  double number(const Json& j, const std::string& field, double limit) const {
    if (!j.is_number()) fail(field, "expected a number, got " + describe(j));
    const double v = j.get<double>();
    if (!std::isfinite(v) || std::fabs(v) > limit)
      fail(field, "expected a finite number of magnitude at most " + format_number(limit) + ", got " + j.dump());
    return v;
  }

  Point position(const Json& j, const std::string& field) const {
    if (!j.is_array() || j.size() != 2)
      fail(field, "expected a position [x, y] (heights go in properties.z), got " + describe(j));
    return {number(j[0], field + "[0]", kMaxCoordinate), number(j[1], field + "[1]", kMaxCoordinate)};
  }

  // A GeoJSON linear ring: closed in the file, stored without the repeated point.
  Polygon ring(const Json& j, const std::string& field) const {
    array(j, field);
    if (j.size() < 4) fail(field, "expected a closed ring of at least 4 positions, got " + std::to_string(j.size()));
    Polygon ring;
    for (size_t i = 0; i < j.size(); ++i) ring.push_back(position(j[i], field + "[" + std::to_string(i) + "]"));
    if (ring.front() != ring.back())
      fail(field, "expected a closed ring (last position equal to the first), got " + j.front().dump() + " and " +
                      j.back().dump());
    ring.pop_back();
    if (auto e = polygon_problem(ring)) fail(field, *e);
    return ring;
  }

  // A Polygon's coordinates: the outer ring only.
  Polygon polygon(const Json& j, const std::string& field) const {
    array(j, field);
    if (j.size() != 1)
      fail(field, "expected 1 ring (holes are not supported), got " + std::to_string(j.size()));
    return ring(j[0], field + "[0]");
  }

  // Polygon or MultiPolygon: one footprint per polygon.
  std::vector<Polygon> footprints(const Json& feature, bool multi_allowed) const {
    const Json& g = member(feature, "geometry", "geometry");
    if (!g.is_object()) fail("geometry", "expected a Polygon or MultiPolygon object, got " + describe(g));
    const Json& type = member(g, "type", "geometry.type");
    const Json& coords = member(g, "coordinates", "geometry.coordinates");
    if (type == "Polygon") return {polygon(coords, "geometry.coordinates")};
    if (type == "MultiPolygon" && multi_allowed) {
      array(coords, "geometry.coordinates");
      if (coords.empty()) fail("geometry.coordinates", "expected at least 1 polygon, got 0");
      std::vector<Polygon> out;
      for (size_t i = 0; i < coords.size(); ++i)
        out.push_back(polygon(coords[i], "geometry.coordinates[" + std::to_string(i) + "]"));
      return out;
    }
    fail("geometry.type", std::string("expected ") + (multi_allowed ? "\"Polygon\" or \"MultiPolygon\"" : "\"Polygon\"") +
                              ", got " + describe(type));
  }

  // properties.z: one [zmin, zmax] (or null: 2D) per polygon.
  std::vector<std::optional<HeightRange>> heights(const Json& z, size_t polygons) const {
    std::vector<std::optional<HeightRange>> out(polygons);
    if (z.is_null()) return out;
    array(z, "properties.z");
    if (z.size() != polygons)
      fail("properties.z", "expected " + std::to_string(polygons) + (polygons == 1 ? " range" : " ranges") +
                               ", one per polygon, got " + std::to_string(z.size()));
    for (size_t i = 0; i < polygons; ++i) {
      const std::string field = "properties.z[" + std::to_string(i) + "]";
      if (z[i].is_null()) continue;
      if (!z[i].is_array() || z[i].size() != 2) fail(field, "expected [zmin, zmax] or null, got " + describe(z[i]));
      const double lo = number(z[i][0], field + "[0]", kMaxHeight), hi = number(z[i][1], field + "[1]", kMaxHeight);
      if (lo < 0) fail(field, "expected zmin >= 0 (metres above the floor), got " + format_number(lo));
      if (!(lo < hi)) fail(field, "expected zmin < zmax, got [" + format_number(lo) + ", " + format_number(hi) + "]");
      out[i] = HeightRange{lo, hi};
    }
    return out;
  }

 private:
  int index_;
  std::string_view item_;
};

bool present(const Json& props, const char* key) { return props.contains(key) && !props[key].is_null(); }

struct Pending {  // a feature read, before ids are given
  int index;
  bool avoid;
  std::optional<std::string> id;
  EnvObject object;
  Polygon area;
};

void read_feature(const Json& f, int index, const SceneReadOptions& options, Scene& scene, std::vector<Pending>& pending,
                  int& bounds_feature) {
  const Reader r(index);
  if (!f.is_object()) r.fail("", "expected a Feature object, got " + describe(f));
  const Json& type = r.member(f, "type", "type");
  if (type != "Feature") r.fail("type", "expected \"Feature\", got " + describe(type));
  static const Json kNoProperties = Json::object();
  const Json& props = f.contains("properties") && !f["properties"].is_null() ? f["properties"] : kNoProperties;
  if (!props.is_object()) r.fail("properties", "expected an object or null, got " + describe(props));

  std::string kind = "object";
  if (present(props, "kind")) {
    if (!props["kind"].is_string() || (props["kind"] != "object" && props["kind"] != "avoid" && props["kind"] != "bounds"))
      r.fail("properties.kind", "expected \"object\", \"avoid\" or \"bounds\", got " + describe(props["kind"]));
    kind = props["kind"].get<std::string>();
  }
  if (kind != "object")
    for (const char* key : {"tag", "z", "dynamic"})
      if (present(props, key))
        r.fail(std::string("properties.") + key, "expected no " + std::string(key) + " on a feature of kind \"" + kind +
                                                     "\" (only objects have one), got " + describe(props[key]));
  if (kind == "bounds") {
    if (present(props, "id")) r.fail("properties.id", "expected no id on the bounds, got " + describe(props["id"]));
    if (bounds_feature >= 0)
      r.fail("properties.kind", "expected at most one bounds feature, got a second (the first is feature " +
                                    std::to_string(bounds_feature) + ")");
    scene.bounds = r.footprints(f, false).front();
    bounds_feature = index;
    return;
  }

  Pending p{index, kind == "avoid", std::nullopt, {}, {}};
  if (present(props, "id")) p.id = r.text(props["id"], "properties.id", "id");
  if (p.avoid) {
    p.area = r.footprints(f, false).front();
    pending.push_back(std::move(p));
    return;
  }
  if (!present(props, "tag")) r.fail("properties.tag", "expected the object's tag, got none");
  p.object.tag = r.text(props["tag"], "properties.tag", "tag");
  if (p.object.tag.find(':') != std::string::npos)
    r.fail("properties.tag", "expected a tag without ':' (it separates tag and id in segment semantics), got \"" +
                                 p.object.tag + "\"");
  if (options.check_tags && !options.known_tags.contains(p.object.tag))
    r.fail("properties.tag", "expected a tag of the semantic table, got unknown \"" + p.object.tag + "\"");
  if (present(props, "dynamic")) {
    if (!props["dynamic"].is_boolean()) r.fail("properties.dynamic", "expected true or false, got " + describe(props["dynamic"]));
    p.object.dynamic = props["dynamic"].get<bool>();
  }
  std::vector<Polygon> fps = r.footprints(f, true);
  const auto z = r.heights(props.contains("z") ? props["z"] : Json(), fps.size());
  for (size_t i = 0; i < fps.size(); ++i) p.object.elements.push_back({std::move(fps[i]), z[i]});
  pending.push_back(std::move(p));
}

// Explicit ids are unique over objects and avoided areas; the others get "<tag>-<n>" or
// "avoid-<n>", n = 1, 2, ... in file order, skipping ids the file uses.
void assign_ids(std::vector<Pending>& pending, Scene& scene) {
  std::map<std::string, int> taken;  // id -> feature
  for (const Pending& p : pending) {
    if (!p.id) continue;
    auto [it, fresh] = taken.emplace(*p.id, p.index);
    if (!fresh)
      Reader(p.index).fail("properties.id", "expected a unique id, got \"" + *p.id + "\" again (first in feature " +
                                                std::to_string(it->second) + ")");
  }
  std::map<std::string, int> counters;  // prefix -> last n tried
  for (Pending& p : pending) {
    if (!p.id) {
      const std::string prefix = p.avoid ? "avoid" : p.object.tag;
      int& n = counters[prefix];
      do p.id = prefix + "-" + std::to_string(++n);
      while (taken.contains(*p.id));
      taken.emplace(*p.id, p.index);
    }
    if (p.avoid) {
      scene.avoided.push_back({*p.id, std::move(p.area)});
    } else {
      p.object.id = *p.id;
      scene.objects.push_back(std::move(p.object));
    }
  }
}

Json parse(const std::string& text, std::string_view item) {
  try {
    return Json::parse(text);
  } catch (const Json::exception& e) {  // parse_error, or out_of_range for 1e999
    throw SceneFormatError(-1, "", std::string("expected JSON, got: ") + e.what(), item);
  }
}

// --- writer ------------------------------------------------------------------------

std::string num(double v, const std::string& where) {
  if (!std::isfinite(v)) throw std::invalid_argument("scene GeoJSON: expected finite numbers in " + where + ", got " + format_number(v));
  return format_number(v);
}

std::string str(const std::string& s, const std::string& where) {
  try {
    return Json(s).dump();
  } catch (const Json::type_error& e) {
    throw std::invalid_argument("scene GeoJSON: expected UTF-8 text in " + where + ", got: " + e.what());
  }
}

// One polygon's coordinates, the ring closed again as GeoJSON wants.
std::string polygon_text(const Polygon& ring, const OutputFrame& f, const std::string& where) {
  if (ring.empty()) throw std::invalid_argument("scene GeoJSON: expected a polygon with vertices in " + where + ", got none");
  std::string out = "[[";
  for (size_t i = 0; i <= ring.size(); ++i) {
    const Point p = f.apply(ring[i % ring.size()]);
    out += std::string(i ? ",[" : "[") + num(p.x, where) + "," + num(p.y, where) + "]";
  }
  return out + "]]";
}

std::string feature_text(const std::string& props, const std::vector<const Polygon*>& polys, bool multi,
                         const OutputFrame& f, const std::string& where) {
  std::string coords;
  for (const Polygon* p : polys) {
    if (!coords.empty()) coords += ",";
    coords += polygon_text(*p, f, where);
  }
  if (multi) coords = "[" + coords + "]";
  return "{\"type\":\"Feature\",\"properties\":{" + props + "},\"geometry\":{\"type\":\"" +
         (multi ? "MultiPolygon" : "Polygon") + "\",\"coordinates\":" + coords + "}}";
}

}  // namespace

SceneFormatError::SceneFormatError(int feature, std::string field, const std::string& message, std::string_view item)
    : BadInput((feature < 0 ? std::string("document") : std::string(item) + " " + std::to_string(feature)) +
                         (field.empty() ? "" : " (" + field + ")") + ": " + message),
      feature_(feature),
      field_(std::move(field)) {}

Scene read_scene_geojson(const std::string& text, const SceneReadOptions& options) {
  const Json doc = parse(text, "feature");
  const Reader r(-1);
  if (!doc.is_object()) r.fail("", "expected a FeatureCollection object, got " + describe(doc));
  const Json& type = r.member(doc, "type", "type");
  if (type != "FeatureCollection") r.fail("type", "expected \"FeatureCollection\", got " + describe(type));
  // An export in WGS 84 (write_scene_geojson with another frame) read as metres would
  // put the objects near the map origin, silently.
  if (doc.contains("fleetmap") && doc["fleetmap"].is_object() && doc["fleetmap"].contains("frame") &&
      doc["fleetmap"]["frame"] != "map")
    r.fail("fleetmap.frame", "expected \"map\" (map-frame metres), got " + describe(doc["fleetmap"]["frame"]));
  const Json& features = r.array(r.member(doc, "features", "features"), "features");

  Scene scene;
  std::vector<Pending> pending;
  int bounds_feature = -1;
  for (size_t i = 0; i < features.size(); ++i)
    read_feature(features[i], static_cast<int>(i), options, scene, pending, bounds_feature);
  assign_ids(pending, scene);
  return scene;
}

std::string write_scene_geojson(const Scene& scene, const OutputFrame& frame) {
  // Coordinates are map-frame metres unless the frame says otherwise (RFC 7946 section 4
  // allows them by prior arrangement); the "fleetmap" member says which to whoever
  // opens the file.
  std::string out = "{\"type\":\"FeatureCollection\",\"fleetmap\":{\"frame\":" + str(frame.name, "the frame") +
                    ",\"units\":" + str(frame.units, "the frame") + "},\"features\":[";
  const char* sep = "\n";
  if (scene.bounds) {
    out += sep + feature_text("\"kind\":\"bounds\"", {&*scene.bounds}, false, frame, "the bounds");
    sep = ",\n";
  }
  for (const EnvObject& o : scene.objects) {
    const std::string where = "object " + o.id;
    if (o.elements.empty()) throw std::invalid_argument("scene GeoJSON: expected at least one element in " + where + ", got none");
    std::string props = "\"kind\":\"object\",\"id\":" + str(o.id, where) + ",\"tag\":" + str(o.tag, where);
    std::vector<const Polygon*> polys;
    std::string z;
    bool any_z = false;
    for (const Element& e : o.elements) {
      polys.push_back(&e.footprint);
      z += z.empty() ? "[" : ",";
      if (e.z) {
        z += "[";
        z += num(e.z->zmin, where) + "," + num(e.z->zmax, where) + "]";
      } else {
        z += "null";
      }
      any_z = any_z || e.z.has_value();
    }
    if (any_z) props += ",\"z\":" + z + "]";
    props += std::string(",\"dynamic\":") + (o.dynamic ? "true" : "false");
    out += sep + feature_text(props, polys, polys.size() > 1, frame, where);
    sep = ",\n";
  }
  for (const AvoidedArea& a : scene.avoided) {
    const std::string where = "avoided area " + a.id;
    out += sep + feature_text("\"kind\":\"avoid\",\"id\":" + str(a.id, where), {&a.area}, false, frame, where);
    sep = ",\n";
  }
  return out + "\n]}\n";
}

std::vector<TagInfo> read_tag_table_json(const std::string& text) {
  const Json doc = parse(text, "entry");
  if (!doc.is_array()) throw SceneFormatError(-1, "", "expected an array of {\"tag\", \"class\", \"description\"}, got " + describe(doc), "entry");
  std::vector<TagInfo> out;
  std::map<std::string, size_t> seen;
  for (size_t i = 0; i < doc.size(); ++i) {
    const Json& e = doc[i];
    const Reader r(static_cast<int>(i), "entry");
    if (!e.is_object()) r.fail("", "expected an object, got " + describe(e));
    TagInfo t;
    t.tag = r.text(r.member(e, "tag", "tag"), "tag", "tag");
    if (t.tag.find(':') != std::string::npos) r.fail("tag", "expected a tag without ':', got \"" + t.tag + "\"");
    const Json& c = r.member(e, "class", "class");
    if (!c.is_string() || !is_tag_class(c.get<std::string>()))
      r.fail("class", "expected \"obstacle\", \"landmark\", \"interactable\" or \"dynamic\", got " + describe(c));
    t.tag_class = c.get<std::string>();
    if (e.contains("description") && !e["description"].is_null()) {
      if (!e["description"].is_string()) r.fail("description", "expected a string, got " + describe(e["description"]));
      t.description = e["description"].get<std::string>();
      if (auto m = check_text(t.description, "description", true)) r.fail("description", *m);
    }
    if (auto [it, fresh] = seen.emplace(t.tag, i); !fresh)
      r.fail("tag", "expected a unique tag, got \"" + t.tag + "\" again (first in entry " + std::to_string(it->second) + ")");
    out.push_back(std::move(t));
  }
  return out;
}

std::string write_tag_table_json(const std::vector<TagInfo>& tags) {
  std::string out = "[";
  for (size_t i = 0; i < tags.size(); ++i) {
    const std::string where = "tag " + tags[i].tag;
    out += (i ? ",\n" : "\n") + std::string("{\"tag\":") + str(tags[i].tag, where) + ",\"class\":" +
           str(tags[i].tag_class, where) + ",\"description\":" + str(tags[i].description, where) + "}";
  }
  return out + "\n]\n";
}

}  // namespace fleetmap
