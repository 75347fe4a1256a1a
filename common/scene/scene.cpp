#include "common/scene/scene.h"

namespace fleetmap {

// The classes of seed 002 section 3.2's semantic table that fleetmap acts on.
bool is_tag_class(const std::string& s) {
  return s == "obstacle" || s == "landmark" || s == "interactable" || s == "dynamic";
}

}  // namespace fleetmap
