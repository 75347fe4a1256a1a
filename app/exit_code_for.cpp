#include "app/exit_code_for.h"

#include <stdexcept>

#include <CLI/CLI.hpp>
#include <mysql++/mysql++.h>

#include "app/exit_codes.h"
#include "common/core/error.h"

namespace fleetmap {

int exit_code_for(const std::exception& e) {
  if (auto* p = dynamic_cast<const CLI::ParseError*>(&e))
    return p->get_exit_code() == 0 ? exit_code::kOk : exit_code::kUsage;
  if (dynamic_cast<const UsageError*>(&e)) return exit_code::kUsage;
  if (dynamic_cast<const BadInput*>(&e)) return exit_code::kBadInput;
  if (dynamic_cast<const std::invalid_argument*>(&e)) return exit_code::kBadInput;
  if (dynamic_cast<const NoPath*>(&e)) return exit_code::kNoPath;
  if (dynamic_cast<const NotFound*>(&e)) return exit_code::kNotFound;
  if (dynamic_cast<const LocalizationFailed*>(&e)) return exit_code::kLocalizationFailed;
  return exit_code::kFailure;
}

std::string error_message(const std::exception& e) {
  if (dynamic_cast<const mysqlpp::Exception*>(&e)) return std::string("database error: ") + e.what();
  return e.what();
}

}  // namespace fleetmap
