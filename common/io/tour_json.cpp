#include "common/io/tour_json.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace fleetmap {
namespace {

[[noreturn]] void bad(const std::string& file, const std::string& where, const std::string& what) {
  throw TourFormatError(file + ": " + where + ": expected " + what);
}

}  // namespace

std::vector<TourWaypoint> read_tour_json(std::string_view text, const std::string& file) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    bad(file, "byte " + std::to_string(e.byte), "JSON (" + std::string(e.what()) + ")");
  }
  if (!j.is_array()) bad(file, "top level", "a list of waypoints");
  std::vector<TourWaypoint> tour;
  for (size_t i = 0; i < j.size(); ++i) {
    const std::string at = "[" + std::to_string(i) + "]";
    const nlohmann::json& w = j[i];
    if (!w.is_object()) bad(file, at, "an object {\"x\", \"y\", \"event\"?, \"name\"?}");
    TourWaypoint p;
    for (const char* k : {"x", "y"}) {
      auto it = w.find(k);
      if (it == w.end() || !it->is_number() || !std::isfinite(it->get<double>()))
        bad(file, at + "." + k, "a finite number");
    }
    p.p = {w.at("x").get<double>(), w.at("y").get<double>()};
    if (auto it = w.find("event"); it != w.end() && !it->is_null()) {
      const auto kind = it->is_string() ? tour_event_kind_from_string(it->get<std::string>()) : std::nullopt;
      if (!kind) bad(file, at + ".event", "corridor, room, door, crossing or place, got " + it->dump());
      p.event = kind;
    }
    if (auto it = w.find("name"); it != w.end() && !it->is_null()) {
      if (!it->is_string() || it->get<std::string>().empty()) bad(file, at + ".name", "a non-empty string");
      p.name = it->get<std::string>();
    }
    if (p.event == TourEventKind::Place && p.name.empty()) bad(file, at + ".name", "a name for a place");
    tour.push_back(std::move(p));
  }
  return tour;
}

std::vector<TourWaypoint> read_tour_json_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TourFormatError(path + ": cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return read_tour_json(s.str(), path);
}

std::string write_tour_json(const std::vector<TourWaypoint>& tour) {
  nlohmann::json j = nlohmann::json::array();
  for (const TourWaypoint& w : tour) {
    nlohmann::json o = {{"x", w.p.x}, {"y", w.p.y}};
    if (w.event) o["event"] = std::string(to_string(*w.event));
    if (!w.name.empty()) o["name"] = w.name;
    j.push_back(std::move(o));
  }
  return j.dump(1) + "\n";
}

}  // namespace fleetmap
