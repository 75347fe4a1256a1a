#pragma once
// How often a robot looks into sa_mine (SPEC 5.1: answers are read by polling). Every
// poll is a statement on the one database the fleet shares, so the policy is a trade:
// latency (an answer is seen up to one poll interval late) against mariadbd CPU (a
// fleet of pollers, and polls that grow as the server slows down: a feedback loop).
//   * an answer is due (a request sent that has answers): the first look first_poll_ms
//     after the INSERT, then every backoff x the time already waited, kept within
//     [min_ms, max_ms]: the error stays a fixed fraction of the latency, and a slow
//     server does not see a storm of polls;
//   * nothing is due: a look every idle_ms, for what the server pushes (SetPosEnd, Abort).
// The defaults were chosen by measurement (docs/benchmarks.md "Robot waiting policy").
// RobotClient (client/robot_client.h) and fleetmap-loadgen (bench/loadgen.cpp) use it.
#include <map>
#include <string>

namespace fleetmap {

struct WaitPolicy {
  double first_poll_ms = 1;  // after the request's INSERT
  double min_ms = 1;         // shortest gap between two polls while an answer is due
  double max_ms = 50;        // longest
  double backoff = 0.1;      // gap = backoff x time waited so far, within [min_ms, max_ms]
  double idle_ms = 1000;     // nothing due: pushed operations are seen this late at most

  // The gap before the next poll when the oldest due answer has waited waited_ms.
  double answer_gap_ms(double waited_ms) const;

  // "key = value" settings (wait_first_poll_ms, wait_min_ms, wait_max_ms, wait_backoff,
  // wait_idle_ms); other keys are left for the caller. Throws std::invalid_argument naming
  // a bad value, or min_ms > max_ms.
  void apply(const std::map<std::string, std::string>& settings);
};

}  // namespace fleetmap
