#include "common/gis/ogr_source.h"

#include <cpl_conv.h>
#include <cpl_vsi.h>

#include <atomic>
#include <fstream>
#include <sstream>

#include "common/core/error.h"

namespace fleetmap {

bool ends_with_ci(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i]) return false;
  return true;
}

namespace {

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.pop_back();
  size_t i = 0;
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
  return s.substr(i);
}

}  // namespace

std::string osm_config_text(const std::vector<std::string>& keys) {
  const char* path = CPLFindFile("gdal", "osmconf.ini");
  if (!path) throw IoError("GDAL's osmconf.ini not found (GDAL_DATA)");
  std::ifstream in(path);
  if (!in) throw IoError(std::string(path) + ": cannot read GDAL's OSM configuration");
  std::ostringstream out;
  std::string line;
  bool header_done = false;
  while (std::getline(in, line)) {
    if (!header_done && !line.empty() && line[0] == '[') {
      out << "attribute_name_laundering=no\n";
      header_done = true;
    }
    if (line.rfind("attribute_name_laundering", 0) == 0) continue;
    if (line.rfind("attributes=", 0) == 0) {
      std::string attrs = trim(line.substr(11));
      std::string listed = "," + attrs + ",";
      for (const std::string& k : keys)
        if (listed.find("," + k + ",") == std::string::npos) {
          attrs += (attrs.empty() ? "" : ",") + k;
          listed += k + ",";
        }
      out << "attributes=" << attrs << "\n";
      continue;
    }
    out << line << "\n";
  }
  return out.str();
}

GDALDatasetUniquePtr open_ogr_source(const std::string& source, const std::vector<std::string>& keys) {
  GDALAllRegister();
  CPLStringList open_options;
  std::string conf;
  if (ends_with_ci(source, ".osm") || ends_with_ci(source, ".pbf")) {
    static std::atomic<int> serial{0};
    conf = "/vsimem/fleetmap_osmconf_" + std::to_string(serial++) + ".ini";
    const std::string text = osm_config_text(keys);
    VSILFILE* f = VSIFOpenL(conf.c_str(), "wb");
    if (!f) throw IoError("cannot write the OSM configuration in " + conf);
    VSIFWriteL(text.data(), 1, text.size(), f);
    VSIFCloseL(f);
    open_options.SetNameValue("CONFIG_FILE", conf.c_str());
  }
  CPLErrorReset();
  GDALDatasetUniquePtr ds(GDALDataset::Open(source.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr,
                                            open_options.List(), nullptr));
  // The driver has read its configuration when Open returns.
  if (!conf.empty()) VSIUnlink(conf.c_str());
  if (!ds) {
    const std::string why = CPLGetLastErrorMsg();
    throw FileFormatError(source + ": expected a vector source OGR can read, got " +
                          (why.empty() ? std::string("nothing OGR recognises") : why));
  }
  return ds;
}

double dxf_unit_scale(const std::string& path) {
  std::ifstream in(path);
  if (!in) return 1;
  std::string code, value;
  bool in_header = false;
  // A DXF file is a sequence of (group code line, value line) pairs.
  while (std::getline(in, code) && std::getline(in, value)) {
    code = trim(code);
    value = trim(value);
    if (code == "2" && value == "HEADER") in_header = true;
    if (code == "0" && value == "ENDSEC" && in_header) break;
    if (in_header && code == "9" && value == "$INSUNITS") {
      if (!std::getline(in, code) || !std::getline(in, value)) break;
      const int u = std::atoi(trim(value).c_str());
      switch (u) {
        case 0: return 1;
        case 1: return 0.0254;
        case 2: return 0.3048;
        case 4: return 0.001;
        case 5: return 0.01;
        case 6: return 1;
        case 14: return 0.1;
        default:
          throw BadInput(path + ": $INSUNITS: expected a drawing unit of 0, 1, 2, 4, 5, 6 or 14, got " +
                         std::to_string(u) + "; give the source a CRS with --crs");
      }
    }
  }
  return 1;
}

}  // namespace fleetmap
