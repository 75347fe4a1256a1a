#pragma once
// What every fuzz target shares: a property that fails is a finding, reported like a
// crash so that libFuzzer keeps the input (abort() is what it watches for).
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace fleetmap::fuzz {

[[noreturn]] inline void finding(std::string_view what) {
  std::fprintf(stderr, "fuzz finding: %.*s\n", static_cast<int>(what.size()), what.data());
  std::abort();
}

inline void check(bool ok, std::string_view what) {
  if (!ok) finding(what);
}

}  // namespace fleetmap::fuzz
