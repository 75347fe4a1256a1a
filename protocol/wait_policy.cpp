#include "protocol/wait_policy.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fleetmap {

double WaitPolicy::answer_gap_ms(double waited_ms) const {
  return std::clamp(backoff * std::max(0.0, waited_ms), min_ms, std::max(min_ms, max_ms));
}

void WaitPolicy::apply(const std::map<std::string, std::string>& settings) {
  const std::map<std::string, double WaitPolicy::*> keys = {
      {"wait_first_poll_ms", &WaitPolicy::first_poll_ms}, {"wait_min_ms", &WaitPolicy::min_ms},
      {"wait_max_ms", &WaitPolicy::max_ms},               {"wait_backoff", &WaitPolicy::backoff},
      {"wait_idle_ms", &WaitPolicy::idle_ms}};
  WaitPolicy p = *this;
  for (const auto& [k, v] : settings) {
    const auto it = keys.find(k);
    if (it == keys.end()) continue;
    size_t used = 0;
    double d = NAN;
    try {
      d = std::stod(v, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != v.size() || !std::isfinite(d) || d < 0)
      throw std::invalid_argument(k + ": expected a non-negative number, got '" + v + "'");
    p.*(it->second) = d;
  }
  if (p.min_ms > p.max_ms)
    throw std::invalid_argument("wait_min_ms (" + std::to_string(p.min_ms) + ") is above wait_max_ms (" +
                                std::to_string(p.max_ms) + ")");
  *this = p;
}

}  // namespace fleetmap
