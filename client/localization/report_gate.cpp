#include "client/localization/report_gate.h"

#include <stdexcept>
#include <string>

namespace fleetmap::localization {

ReportGate::ReportGate(int updates) : updates_(updates) {
  if (updates < 1) throw std::invalid_argument("ReportGate: expected 1 or more updates, got " + std::to_string(updates));
}

bool ReportGate::update(bool settled) {
  streak_ = settled ? streak_ + 1 : 0;
  return streak_ >= updates_;
}

}  // namespace fleetmap::localization
