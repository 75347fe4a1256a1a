#include "server/daemon/housekeeping.h"

#include <spdlog/spdlog.h>

#include "protocol/connection.h"
#include "protocol/history_retention.h"
#include "protocol/request_queue.h"
#include "protocol/scene_store.h"
#include "protocol/task_lifecycle.h"

namespace fleetmap {

PushAction push_action(const TaskRow& task) {
  if (!is_open(task.state)) return PushAction::None;
  if (task.abort_requested && !task.abort_answer_id) return task.answer_id ? PushAction::SendAbort : PushAction::AbortUnsent;
  if (!task.answer_id) return PushAction::SendGoal;
  return PushAction::None;
}

double lost_after_s(const ServerConfig& config) { return config.alive_period_s * config.lost_after_periods; }

std::optional<HousekeepingSchedule::Pass> HousekeepingSchedule::due(Clock::time_point now) {
  if (next_ && now < *next_) return std::nullopt;
  next_ = now + period_;
  return Pass{passes_++ % expiry_every_ == 0};
}

size_t Housekeeping::run(const HousekeepingSchedule::Pass& pass) {
  const size_t pushed = push_operations();
  mark_lost_robots();
  // Work on no robot: the first share alone does it, so that partitioned servers on
  // several Galera nodes do not conflict over the same rows.
  if (config_.partition.index == 0) {
    drop_orphan_requests();
    if (pass.expire_observations) {
      SceneStore(c_).expire_observations();
      delete_history_before(c_, config_.history_keep_s);
    }
  }
  return pushed;
}

size_t Housekeeping::drop_orphan_requests() {
  // Requests from accounts that are no robot (inserted by hand by an administrator):
  // nobody can read an answer; drop them so they do not sit at the head of the queue.
  // Housekeeping, not every batch: the scan grows with the queue.
  mysqlpp::Query q = c_.query("SELECT id FROM rr WHERE db_user NOT IN (SELECT db_user FROM robots) LIMIT 100");
  std::vector<unsigned long long> orphans;
  for (const mysqlpp::Row& r : q.store()) orphans.push_back(std::stoull(std::string(r[0])));
  if (orphans.empty()) return 0;
  spdlog::warn("dropping {} request(s) from accounts that are no robot", orphans.size());
  RequestQueue(c_).remove(orphans);
  return orphans.size();
}

size_t Housekeeping::push_operations() {
  RobotStore robots(c_);
  RequestQueue queue(c_);
  size_t pushed = 0;
  // Only this server's share (robot_partition.h): another server claims the others.
  for (unsigned id : robots.robots_with_pushes(config_.batch_robots, config_.partition.count, config_.partition.index)) {
    Transaction tx(c_);
    std::optional<RobotRow> robot = robots.claim(id);
    if (!robot) continue;  // another worker or server holds it
    std::optional<TaskRow> task = robots.open_task(id);
    if (!task) continue;
    switch (push_action(*task)) {
      case PushAction::None: break;
      case PushAction::AbortUnsent:
        robots.set_task_state(task->id, task_transition(task->state, TaskEvent::AbortedUnsent).next());
        ++pushed;
        break;
      case PushAction::SendAbort: {
        const auto sa_id =
            queue.insert({id, robot->db_user, std::nullopt, AnswerOp::Abort, encode_abort(task->reason), std::nullopt});
        robots.set_task_abort_answer(task->id, sa_id);
        spdlog::info("pushed Abort of task {} to {}", task->id, robot->db_user);
        ++pushed;
        break;
      }
      case PushAction::SendGoal: {
        const auto sa_id = queue.insert({id, robot->db_user, std::nullopt, AnswerOp::SetPosEnd,
                                         encode(SetPoseParams{task->goal_x, task->goal_y, std::nullopt}), std::nullopt});
        robots.set_task_answer(task->id, sa_id);
        spdlog::info("pushed SetPosEnd of task {} ({}, {}) to {}", task->id, task->goal_x, task->goal_y,
                     robot->db_user);
        ++pushed;
        break;
      }
    }
    tx.commit();
  }
  return pushed;
}

size_t Housekeeping::mark_lost_robots() {
  RobotStore robots(c_);
  size_t lost = 0;
  const double silent_s = lost_after_s(config_);
  for (unsigned id : robots.silent_robots(silent_s, config_.batch_robots, config_.partition.count, config_.partition.index)) {
    Transaction tx(c_);
    std::optional<RobotRow> robot = robots.claim(id);
    if (!robot) continue;
    robots.set_state(id, RobotState::Lost);
    while (auto task = robots.open_task(id))
      robots.set_task_state(task->id, task_transition(task->state, TaskEvent::RobotLost).next(), "robot lost");
    tx.commit();
    spdlog::warn("robot {} is lost (silent for more than {:.1f} s)", robot->db_user, silent_s);
    ++lost;
  }
  return lost;
}

}  // namespace fleetmap
