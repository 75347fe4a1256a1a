// Scene GeoJSON and the tag table (common/io/scene_geojson.h) from any bytes: the
// readers return a scene / table or throw SceneFormatError. "Export writes what import
// reads": write -> read -> write gives the same text.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/io/scene_geojson.h"
#include "fuzz/fuzz_check.h"

using namespace fleetmap;

namespace {

void scene(const std::string& text) {
  Scene s;
  try {
    s = read_scene_geojson(text);
  } catch (const SceneFormatError&) {
    return;
  }
  const std::string once = write_scene_geojson(s);
  Scene again;
  try {
    again = read_scene_geojson(once);
  } catch (const SceneFormatError& e) {
    fuzz::finding(std::string("write_scene_geojson wrote a scene read_scene_geojson refuses: ") + e.what());
  }
  fuzz::check(write_scene_geojson(again) == once, "scene GeoJSON differs after write -> read -> write");
}

void tag_table(const std::string& text) {
  std::vector<TagInfo> tags;
  try {
    tags = read_tag_table_json(text);
  } catch (const SceneFormatError&) {
    return;
  }
  const std::string once = write_tag_table_json(tags);
  std::vector<TagInfo> again;
  try {
    again = read_tag_table_json(once);
  } catch (const SceneFormatError& e) {
    fuzz::finding(std::string("write_tag_table_json wrote a table read_tag_table_json refuses: ") + e.what());
  }
  fuzz::check(write_tag_table_json(again) == once, "tag table differs after write -> read -> write");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  scene(text);
  tag_table(text);
  return 0;
}
