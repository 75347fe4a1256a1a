#include "common/gis/crs_name.h"

#include <proj.h>

#include "common/core/error.h"

namespace fleetmap {

std::string crs_name(const std::string& definition) {
  PJ_CONTEXT* ctx = proj_context_create();
  proj_log_level(ctx, PJ_LOG_NONE);
  PJ* crs = proj_create(ctx, definition.c_str());
  if (!crs) {
    const int e = proj_context_errno(ctx);
    const std::string why = e ? proj_context_errno_string(ctx, e) : "unknown PROJ error";
    proj_context_destroy(ctx);
    throw BadInput("CRS '" + definition + "': " + why);
  }
  const char* name = proj_get_name(crs);
  std::string out = name && *name ? name : "unnamed";
  proj_destroy(crs);
  proj_context_destroy(ctx);
  return out;
}

}  // namespace fleetmap
