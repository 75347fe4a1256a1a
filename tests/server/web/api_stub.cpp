// Tests only, until the api branch is merged: the API library's three functions, so that
// fleetmap-web and the transport's tests link (tests/CMakeLists.txt builds this as
// fleetmap_web_api only when server/web/api/ has no sources). No routes; errors as
// api.h describes them, in short.
#include <mysql++/mysql++.h>

#include "app/exit_code_for.h"
#include "common/core/error.h"
#include "server/web/api/api.h"

namespace fleetmap::web {

const char* to_string(WebRole r) { return r == WebRole::Operator ? "operator" : "inspector"; }

std::vector<Route> api_routes() { return {}; }

ApiResponse error_response(const std::exception& e) {
  int status = 500;
  std::string code = "internal";
  int exit_code = exit_code_for(e);
  if (auto* a = dynamic_cast<const ApiError*>(&e)) {
    status = a->status();
    code = a->code();
    exit_code = a->exit_code();
  } else if (dynamic_cast<const BadInput*>(&e) || dynamic_cast<const std::invalid_argument*>(&e)) {
    status = 400;
    code = "bad_input";
  } else if (dynamic_cast<const NotFound*>(&e)) {
    status = 404;
    code = "not_found";
  }
  ApiResponse r;
  r.status = status;
  r.body = {{"error", {{"status", status}, {"code", code}, {"exit_code", exit_code}, {"message", error_message(e)}}}};
  return r;
}

}  // namespace fleetmap::web
