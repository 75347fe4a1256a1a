#pragma once
// The root of fleetmap's exceptions, one subclass per meaning. Every program maps the
// meaning to its exit code (app/exit_code_for.h, README "Exit codes"); the layers
// below only say what went wrong, never how a program ends. Lowest layer: no other
// fleetmap include.
#include <stdexcept>
#include <string>

namespace fleetmap {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Malformed input: a map, scene or graph file, a parameter value, a setting.
class BadInput : public Error {
 public:
  using Error::Error;
};

// Malformed input whose message starts with where it is ("file:line: ..." or
// "file: where: ..."), so programs print it as is, for editors to jump to.
class FileFormatError : public BadInput {
 public:
  using BadInput::BadInput;
};

// No such map, robot, graph, node or object; or one exists that must not.
class NotFound : public Error {
 public:
  using Error::Error;
};

// Planning found no path (or no reachable goal).
class NoPath : public Error {
 public:
  using Error::Error;
};

// What the user cannot fix by changing the input: database unreachable, internal error.
class Failure : public Error {
 public:
  using Error::Error;
};

// A file that cannot be opened, read or written.
class IoError : public Failure {
 public:
  using Failure::Failure;
};

// A command line that does not say what to do (beyond what the option parser checks).
class UsageError : public Error {
 public:
  using Error::Error;
};

// A robot that could not find where it is on its map (global localization, SPEC 6).
class LocalizationFailed : public Error {
 public:
  using Error::Error;
};

}  // namespace fleetmap
