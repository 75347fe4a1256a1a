#include "common/gis/import_rules.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "common/core/error.h"

namespace fleetmap {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& source, const std::string& where, const std::string& what) {
  throw FileFormatError(source + ": " + where + ": " + what);
}

void only_keys(const json& j, const std::set<std::string>& allowed, const std::string& source,
               const std::string& where) {
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!allowed.count(it.key()))
      fail(source, where + "." + it.key(), "expected one of the documented fields (docs/gis-import.md), got an unknown one");
}

std::string get_string(const json& j, const char* k, const std::string& source, const std::string& where) {
  if (!j.contains(k)) return {};
  if (!j[k].is_string()) fail(source, where + "." + k, "expected a string, got " + j[k].dump());
  return j[k].get<std::string>();
}

double get_number(const json& j, const char* k, double dflt, const std::string& source, const std::string& where,
                  bool positive = true) {
  if (!j.contains(k)) return dflt;
  if (!j[k].is_number()) fail(source, where + "." + k, "expected a number, got " + j[k].dump());
  const double v = j[k].get<double>();
  if (positive && !(v > 0)) fail(source, where + "." + k, "expected a number > 0, got " + j[k].dump());
  return v;
}

FeatureAction parse_action(const std::string& s, const std::string& source, const std::string& where) {
  if (s == "skip") return FeatureAction::Skip;
  if (s == "closed") return FeatureAction::Closed;
  if (s == "open") return FeatureAction::Open;
  if (s == "stairs") return FeatureAction::Stairs;
  if (s == "object") return FeatureAction::Object;
  fail(source, where + ".action", "expected skip, closed, open, stairs or object, got \"" + s + "\"");
}

FeatureRule parse_rule(const json& j, const std::string& source, const std::string& where) {
  if (!j.is_object()) fail(source, where, "expected an object, got " + j.dump());
  only_keys(j,
            {"name", "layer", "geometry", "key", "values", "action", "height", "in_out", "free_space", "tag",
             "object_size", "object_height", "step_height", "step_depth", "stairs_width"},
            source, where);
  FeatureRule r;
  r.layer = get_string(j, "layer", source, where);
  r.geometry = get_string(j, "geometry", source, where);
  if (!r.geometry.empty() && r.geometry != "point" && r.geometry != "line" && r.geometry != "polygon")
    fail(source, where + ".geometry", "expected point, line or polygon, got \"" + r.geometry + "\"");
  r.key = get_string(j, "key", source, where);
  if (j.contains("values")) {
    const json& v = j["values"];
    if (!v.is_array()) fail(source, where + ".values", "expected an array of strings, got " + v.dump());
    for (const json& s : v) {
      if (!s.is_string()) fail(source, where + ".values", "expected an array of strings, got " + v.dump());
      if (s.get<std::string>() != "*") r.values.push_back(s.get<std::string>());
    }
    if (r.key.empty() && !r.values.empty()) fail(source, where + ".values", "expected a key beside values, got none");
  }
  if (!j.contains("action")) fail(source, where + ".action", "expected skip, closed, open, stairs or object, got none");
  r.action = parse_action(get_string(j, "action", source, where), source, where);
  if (j.contains("height")) {
    const json& h = j["height"];
    const std::string hw = where + ".height";
    if (!h.is_object()) fail(source, hw, "expected an object, got " + h.dump());
    only_keys(h, {"attribute", "levels_attribute", "level_height", "default"}, source, hw);
    r.height.attribute = get_string(h, "attribute", source, hw);
    r.height.levels_attribute = get_string(h, "levels_attribute", source, hw);
    r.height.level_height = get_number(h, "level_height", r.height.level_height, source, hw);
    r.height.default_height = get_number(h, "default", r.height.default_height, source, hw);
  }
  if (j.contains("in_out")) {
    if (!j["in_out"].is_number_integer() || (j["in_out"] != 0 && j["in_out"] != 1))
      fail(source, where + ".in_out", "expected 0 (indoor) or 1 (outdoor), got " + j["in_out"].dump());
    r.in_out = j["in_out"].get<int>();
  }
  const std::string fs = get_string(j, "free_space", source, where);
  if (!fs.empty() && fs != "inside" && fs != "outside")
    fail(source, where + ".free_space", "expected inside or outside, got \"" + fs + "\"");
  r.free_space_inside = fs == "inside";
  r.tag = get_string(j, "tag", source, where);
  r.object_size = get_number(j, "object_size", r.object_size, source, where);
  if (j.contains("object_height")) r.object_height = get_number(j, "object_height", 0, source, where);
  r.step_height = get_number(j, "step_height", r.step_height, source, where);
  r.step_depth = get_number(j, "step_depth", r.step_depth, source, where);
  r.stairs_width = get_number(j, "stairs_width", r.stairs_width, source, where);
  r.name = get_string(j, "name", source, where);
  if (r.name.empty()) {
    r.name = r.key.empty() ? (r.geometry.empty() ? "any" : r.geometry) : r.key;
    if (!r.key.empty()) {
      std::string v;
      for (const std::string& s : r.values) v += (v.empty() ? "" : "|") + s;
      r.name += "=" + (v.empty() ? "*" : v);
    }
  }
  return r;
}

FeatureRule rule(std::string key, std::vector<std::string> values, FeatureAction action) {
  FeatureRule r;
  r.key = std::move(key);
  r.values = std::move(values);
  r.action = action;
  std::string v;
  for (const std::string& s : r.values) v += (v.empty() ? "" : "|") + s;
  r.name = r.key + "=" + (v.empty() ? "*" : v);
  return r;
}

}  // namespace

ImportRules parse_import_rules(const std::string& json_text, const std::string& source) {
  json j;
  try {
    j = json::parse(json_text);
  } catch (const json::parse_error& e) {
    throw FileFormatError(source + ": expected JSON rules (docs/gis-import.md), got: " + e.what());
  }
  if (!j.is_object()) fail(source, "top level", "expected an object, got " + j.dump().substr(0, 40));
  only_keys(j, {"layers", "rules", "curve_step_degrees", "margin"}, source, "top level");
  ImportRules r;
  if (j.contains("layers")) {
    if (!j["layers"].is_array()) fail(source, "layers", "expected an array of layer names, got " + j["layers"].dump());
    for (const json& l : j["layers"]) {
      if (!l.is_string()) fail(source, "layers", "expected an array of layer names, got " + j["layers"].dump());
      r.layers.push_back(l.get<std::string>());
    }
  }
  r.curve_step_degrees = get_number(j, "curve_step_degrees", r.curve_step_degrees, source, "top level");
  r.margin = get_number(j, "margin", r.margin, source, "top level");
  if (!j.contains("rules") || !j["rules"].is_array() || j["rules"].empty())
    fail(source, "rules", "expected a non-empty array of rules, got " + (j.contains("rules") ? j["rules"].dump() : "none"));
  for (size_t i = 0; i < j["rules"].size(); ++i)
    r.rules.push_back(parse_rule(j["rules"][i], source, "rules[" + std::to_string(i) + "]"));
  return r;
}

ImportRules read_import_rules(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open the rules file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_import_rules(ss.str(), path);
}

// seed 001 section III and the OSM wiki's tags. Order matters: the first rule wins, so
// indoor mapping comes before the building outline it lies in.
ImportRules osm_default_rules() {
  ImportRules r;
  {
    FeatureRule room = rule("indoor", {"room", "corridor", "area"}, FeatureAction::Closed);
    room.in_out = 0;
    room.free_space_inside = true;
    room.height = {"height", "", 3, 3};
    r.rules.push_back(room);
    FeatureRule door = rule("indoor", {"door"}, FeatureAction::Object);
    door.tag = "door";
    r.rules.push_back(door);
  }
  {
    FeatureRule b = rule("building", {}, FeatureAction::Closed);
    b.geometry = "polygon";
    b.tag = "building";
    b.height = {"height", "building:levels", 3, 6};
    r.rules.push_back(b);
  }
  {
    FeatureRule w = rule("barrier", {"wall", "fence", "retaining_wall", "city_wall", "hedge", "guard_rail",
                                     "handrail", "railing", "kerb", "jersey_barrier"},
                         FeatureAction::Open);
    w.geometry = "line";
    w.height = {"height", "", 3, 1.5};
    r.rules.push_back(w);
    FeatureRule wa = w;
    wa.geometry = "polygon";
    r.rules.push_back(wa);
  }
  {
    FeatureRule s = rule("highway", {"steps"}, FeatureAction::Stairs);
    s.geometry = "line";
    s.tag = "steps";
    r.rules.push_back(s);
  }
  {
    FeatureRule o = rule("amenity", {"bench", "waste_basket", "bicycle_parking", "drinking_water", "vending_machine",
                                     "post_box", "recycling", "bbq", "telephone", "fountain", "shelter"},
                         FeatureAction::Object);
    o.geometry = "point";
    o.object_height = 1.0;
    r.rules.push_back(o);
    FeatureRule bo = rule("barrier", {"bollard", "block", "gate", "lift_gate", "stile", "kissing_gate"},
                          FeatureAction::Object);
    bo.geometry = "point";
    bo.object_size = 0.3;
    r.rules.push_back(bo);
    FeatureRule e = rule("entrance", {}, FeatureAction::Object);
    e.geometry = "point";
    e.tag = "entrance";
    e.object_size = 1.0;
    e.object_height = 2.0;
    r.rules.push_back(e);
    FeatureRule d = rule("door", {}, FeatureAction::Object);
    d.geometry = "point";
    d.tag = "door";
    d.object_size = 1.0;
    d.object_height = 2.0;
    r.rules.push_back(d);
  }
  return r;
}

ImportRules plain_default_rules() {
  ImportRules r;
  FeatureRule poly;
  poly.name = "polygon";
  poly.geometry = "polygon";
  poly.action = FeatureAction::Closed;
  poly.height = {"height", "levels", 3, 3};
  r.rules.push_back(poly);
  FeatureRule line = poly;
  line.name = "line";
  line.geometry = "line";
  line.action = FeatureAction::Open;
  r.rules.push_back(line);
  FeatureRule point;
  point.name = "point";
  point.geometry = "point";
  point.action = FeatureAction::Object;
  r.rules.push_back(point);
  return r;
}

std::vector<std::string> rule_keys(const ImportRules& rules) {
  std::vector<std::string> keys;
  auto add = [&](const std::string& k) {
    if (!k.empty() && std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
  };
  for (const FeatureRule& r : rules.rules) {
    add(r.key);
    add(r.height.attribute);
    add(r.height.levels_attribute);
  }
  add("incline");
  add("width");
  return keys;
}

}  // namespace fleetmap
