#include <mysql++/mysql++.h>

#include "app/exit_code_for.h"
#include "app/exit_codes.h"
#include "common/core/error.h"
#include "server/core/goal_check.h"
#include "server/web/api/api.h"

namespace fleetmap::web {
namespace {

// MariaDB's "access denied" family: the signed-in person's grants refuse the statement
// (an inspector's write, SPEC 4), the account or its password is refused, or a role is
// not theirs. The database decides what each may do; the API only reports it.
bool access_denied(unsigned errnum) {
  switch (errnum) {
    case 1044:  // ER_DBACCESS_DENIED_ERROR
    case 1045:  // ER_ACCESS_DENIED_ERROR
    case 1142:  // ER_TABLEACCESS_DENIED_ERROR
    case 1143:  // ER_COLUMNACCESS_DENIED_ERROR
    case 1370:  // ER_PROCACCESS_DENIED_ERROR
      return true;
    default:
      return false;
  }
}

std::optional<unsigned> database_errnum(const std::exception& e) {
  if (auto* q = dynamic_cast<const mysqlpp::BadQuery*>(&e)) return static_cast<unsigned>(q->errnum());
  if (auto* c = dynamic_cast<const mysqlpp::ConnectionFailed*>(&e)) return static_cast<unsigned>(c->errnum());
  return std::nullopt;
}

ApiResponse make(int status, const std::string& code, int exit_code, const std::string& message) {
  ApiResponse r;
  r.status = status;
  r.body = {{"error", {{"status", status}, {"code", code}, {"exit_code", exit_code}, {"message", message}}}};
  return r;
}

}  // namespace

const char* to_string(WebRole r) {
  switch (r) {
    case WebRole::Operator:
      return "operator";
    case WebRole::Inspector:
      return "inspector";
  }
  return "inspector";
}

ApiResponse error_response(const std::exception& e) {
  if (auto* a = dynamic_cast<const ApiError*>(&e)) return make(a->status(), a->code(), a->exit_code(), a->what());
  const int exit_code = exit_code_for(e);
  const std::string message = error_message(e);
  if (dynamic_cast<const BadInput*>(&e) || dynamic_cast<const std::invalid_argument*>(&e))
    return make(400, "bad_input", exit_code, message);
  if (dynamic_cast<const NotFound*>(&e)) return make(404, "not_found", exit_code, message);
  if (dynamic_cast<const GoalRefused*>(&e)) return make(422, "goal_refused", exit_code, message);
  if (dynamic_cast<const NoPath*>(&e)) return make(422, "no_path", exit_code, message);
  if (auto errnum = database_errnum(e); errnum && access_denied(*errnum))
    return make(403, "forbidden", exit_code, message);
  return make(500, "internal", exit_code, message);
}

}  // namespace fleetmap::web
