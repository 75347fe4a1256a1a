#include "app/config_number.h"

#include <cmath>
#include <stdexcept>

namespace fleetmap {
namespace {

// The value as a double when all of it is one, else NaN.
double parse_all(const std::string& v) {
  size_t used = 0;
  double d = NAN;
  try {
    d = std::stod(v, &used);
  } catch (const std::exception&) {
    return NAN;
  }
  return used == v.size() ? d : NAN;
}

std::string whole_text(double d) { return std::to_string(static_cast<long long>(d)); }

}  // namespace

double config_number(const std::string& section, const std::string& key, const std::string& v, bool zero_ok) {
  const double d = parse_all(v);
  if (!std::isfinite(d) || d < 0 || (d == 0 && !zero_ok))
    throw std::invalid_argument(section + " " + key + ": expected a " + (zero_ok ? "non-negative" : "positive") +
                                " number, got '" + v + "'");
  return d;
}

size_t config_whole(const std::string& section, const std::string& key, const std::string& v, double least,
                    double most) {
  const double d = parse_all(v);
  if (!std::isfinite(d) || d != std::floor(d) || d < least || d > most) {
    const std::string range = least == 1 && most >= 1e15 ? "a positive whole number"
                              : least == 1              ? "a positive whole number up to " + whole_text(most)
                                                        : "a whole number from " + whole_text(least) + " to " + whole_text(most);
    throw std::invalid_argument(section + " " + key + ": expected " + range + ", got '" + v + "'");
  }
  return static_cast<size_t>(d);
}

}  // namespace fleetmap
