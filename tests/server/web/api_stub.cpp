// Tests only, until the api branch is merged: the API library's three functions, so that
// fleetmap-web and the transport's tests link (tests/CMakeLists.txt builds this as
// fleetmap_web_api only when server/web/api/ has no sources). Three of the API's write
// routes, answering 501, so that the transport's checks in front of them (session, CSRF,
// role, body) can be tested; errors as api.h describes them, in short.
#include <mysql++/mysql++.h>

#include "app/exit_code_for.h"
#include "common/core/error.h"
#include "server/web/api/api.h"

namespace fleetmap::web {

const char* to_string(WebRole r) { return r == WebRole::Operator ? "operator" : "inspector"; }

std::vector<Route> api_routes() {
  auto not_here = [](const ApiRequest&, ApiContext&) -> ApiResponse {
    throw ApiError(501, "not_implemented", "the API routes are not built in (tests/server/web/api_stub.cpp)", 1);
  };
  return {{"POST", "/api/robots/{name}/goal", true, "Assign a goal", not_here},
          {"POST", "/api/robots/{name}/pose", true, "Set the initial pose", not_here},
          {"POST", "/api/robots/{name}/abort", true, "Abort the open task", not_here}};
}

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
