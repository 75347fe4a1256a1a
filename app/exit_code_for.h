#pragma once
// Which exit code an exception ends a program with (README "Exit codes"), by its class
// (common/core/error.h), and the one line a person reads about it.
#include <exception>
#include <string>

namespace fleetmap {

//   CLI::ParseError                          64 (help and --version: 0)
//   UsageError                               64
//   BadInput (MapFormatError, ...)           2
//   std::invalid_argument                    2: a value a library function refuses
//   NoPath                                   3
//   NotFound (MapNotFound, MapExists, ...)   4
//   LocalizationFailed                       5
//   Failure, IoError, DbError, mysqlpp, any other exception: 1
int exit_code_for(const std::exception& e);

// "database error: ..." for MySQL++'s exceptions (their what() does not say it is the
// database), what() otherwise.
std::string error_message(const std::exception& e);

}  // namespace fleetmap
