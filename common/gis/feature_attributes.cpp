#include "common/gis/feature_attributes.h"

#include <ogrsf_frmts.h>

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

namespace fleetmap {

std::string feature_attribute(const OGRFeature& f, const std::string& key) {
  if (key.empty()) return {};
  int i = f.GetFieldIndex(key.c_str());
  if (i < 0) {
    std::string laundered = key;
    for (char& c : laundered)
      if (c == ':') c = '_';
    i = f.GetFieldIndex(laundered.c_str());
  }
  if (i < 0 || !f.IsFieldSetAndNotNull(i)) return {};
  return f.GetFieldAsString(i);
}

std::string feature_semantic(const OGRFeature& f, const std::string& layer) {
  nlohmann::ordered_json j;
  j["layer"] = layer;
  j["fid"] = static_cast<long long>(f.GetFID());
  for (int i = 0; i < f.GetFieldCount(); ++i) {
    if (!f.IsFieldSetAndNotNull(i)) continue;
    const OGRFieldDefn* d = f.GetFieldDefnRef(i);
    switch (d->GetType()) {
      case OFTInteger:
        j[d->GetNameRef()] = f.GetFieldAsInteger(i);
        break;
      case OFTInteger64:
        j[d->GetNameRef()] = static_cast<long long>(f.GetFieldAsInteger64(i));
        break;
      case OFTReal:
        if (std::isfinite(f.GetFieldAsDouble(i))) j[d->GetNameRef()] = f.GetFieldAsDouble(i);
        break;
      default: {
        const std::string v = f.GetFieldAsString(i);
        if (!v.empty()) j[d->GetNameRef()] = v;
      }
    }
  }
  const std::string dumped = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(dumped.size());
  for (char c : dumped) {
    // Inside a JSON text these three occur only in strings, where an escape is the same
    // character to every JSON reader.
    if (c == ';') out += "\\u003b";
    else if (c == '#') out += "\\u0023";
    else if (c == '%') out += "\\u0025";
    else out += c;
  }
  return out;
}

std::optional<double> parse_length(const std::string& text) {
  const char* s = text.c_str();
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  if (end == s || !std::isfinite(v) || !(v > 0)) return std::nullopt;
  std::string unit(end);
  while (!unit.empty() && unit.front() == ' ') unit.erase(0, 1);
  while (!unit.empty() && unit.back() == ' ') unit.pop_back();
  if (unit.empty() || unit == "m") return v;
  if (unit == "ft" || unit == "'") return v * 0.3048;
  return std::nullopt;
}

std::string short_semantic(const std::string& text, size_t max_bytes) {
  std::string s = text;
  for (char& c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == ';' || c == '#' || c == '%' || c == ':' || u < 0x20 || u == 0x7F) c = '_';
  }
  if (s.size() > max_bytes) {
    size_t n = max_bytes;
    while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;  // not inside a UTF-8 sequence
    s.resize(n);
  }
  return s;
}

}  // namespace fleetmap
