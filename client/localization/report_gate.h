#pragma once
// When a global localization may report its pose. A cloud can converge on a wrong place
// for a scan or two, mostly among people, before the next scans spread it again or the
// verdict (ambiguity.h) finds the look-alike; a robot that reports the pose then drives
// on a place 40-350 m away. So the pose is reported only once the cloud has converged,
// with no look-alike place, on `updates` scans in a row (docs/localization.md, "A pose
// reported only once it holds": 3 cut the wrong reports after a kidnap from 11 to 2 in
// 48, at two more scans each).
//
//   ReportGate gate;
//   for (...) { filter.update(scan); if (gate.update(settled(filter))) report(); }
namespace fleetmap::localization {

class ReportGate {
 public:
  explicit ReportGate(int updates = 3);

  // One update: whether the cloud has converged with no look-alike place. Returns
  // whether the pose may be reported now.
  bool update(bool settled);
  void reset() { streak_ = 0; }
  int updates() const { return updates_; }

 private:
  int updates_;
  int streak_ = 0;
};

}  // namespace fleetmap::localization
