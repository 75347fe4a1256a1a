#pragma once
// Exit codes of the fleetmap programs (README "Exit codes"). Which exception ends a
// program with which code: app/exit_code_for.h.
namespace fleetmap::exit_code {
inline constexpr int kOk = 0;
inline constexpr int kFailure = 1;             // database unreachable, I/O error, internal error
inline constexpr int kBadInput = 2;            // malformed map file or parameter value
inline constexpr int kNoPath = 3;              // planning found no path
inline constexpr int kNotFound = 4;            // no such map / robot, or it already exists
inline constexpr int kLocalizationFailed = 5;  // fleetmap-robot: global localization failed
inline constexpr int kUsage = 64;              // wrong command line (EX_USAGE)
}  // namespace fleetmap::exit_code
