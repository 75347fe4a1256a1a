#include "protocol/write_batch.h"

#include "common/geometry/number_format.h"
#include "protocol/connection.h"

namespace fleetmap {
namespace {

std::string n(double v) { return format_number(v); }
std::string n(const std::optional<double>& v) { return v ? format_number(*v) : "NULL"; }

}  // namespace

void WriteBatch::add(RequestWrites&& w) {
  for (Answer& a : w.answers) answers_.push_back(std::move(a));
  for (PoseReport& p : w.poses) poses_.push_back(std::move(p));
  for (GpsReport& g : w.fixes) fixes_.push_back(std::move(g));
  w.clear();
}

void WriteBatch::robot(const RobotRow& r, const std::string& last_seen) {
  mysqlpp::Query q = c_.query();
  q << "UPDATE robots SET last_seen = GREATEST(COALESCE(last_seen, 0), " << mysqlpp::quote << last_seen
    << "), state = " << mysqlpp::quote << std::string(to_string(r.state));
  if (r.x && r.y) q << ", x = " << n(r.x) << ", y = " << n(r.y);
  if (r.theta) q << ", theta = " << n(r.theta);
  if (r.v) q << ", v = " << n(r.v);
  q << " WHERE id = " << r.id;
  robot_updates_.push_back(q.str());
}

std::vector<std::string> WriteBatch::statements() {
  std::vector<std::string> out;
  // Answers in the order they were added: ids grow in that order within one INSERT, and
  // each robot reads its answers by id (SPEC 5.3).
  if (!answers_.empty()) {
    mysqlpp::Query q = c_.query();
    q << "INSERT INTO sa (robot_id, db_user, request_id, op, params, payload, created_at) VALUES ";
    for (size_t i = 0; i < answers_.size(); ++i) {
      const Answer& a = answers_[i];
      q << (i ? "," : "") << "(" << a.robot_id << ", " << mysqlpp::quote << a.db_user << ", "
        << (a.request_id ? std::to_string(*a.request_id) : "NULL") << ", " << mysqlpp::quote << std::string(name(a.op))
        << ", "
        // replace: an error message may quote a robot's invalid UTF-8; it must not stop the answer.
        << mysqlpp::quote << a.params.dump(-1, ' ', false, Json::error_handler_t::replace) << ", ";
      if (a.payload) q << mysqlpp::quote << *a.payload;
      else q << "NULL";
      q << ", SYSDATE(6))";
    }
    out.push_back(q.str());
  }
  if (!poses_.empty()) {
    mysqlpp::Query q = c_.query();
    q << "INSERT INTO trajectories (robot_id, t, x, y, theta, v, w, pos) VALUES ";
    for (size_t i = 0; i < poses_.size(); ++i) {
      const SendPosParams& p = poses_[i].pose;
      q << (i ? "," : "") << "(" << poses_[i].robot_id << ", " << mysqlpp::quote << poses_[i].at << ", " << n(p.x)
        << ", " << n(p.y) << ", " << n(p.theta) << ", " << n(p.v) << ", " << n(p.w) << ", Point(" << n(p.x) << ", "
        << n(p.y) << "))";
    }
    out.push_back(q.str());
  }
  if (!fixes_.empty()) {
    mysqlpp::Query q = c_.query();
    q << "INSERT INTO gps_fixes (robot_id, t, lat, lon, x, y) VALUES ";
    for (size_t i = 0; i < fixes_.size(); ++i) {
      const GpsReport& g = fixes_[i];
      q << (i ? "," : "") << "(" << g.robot_id << ", " << mysqlpp::quote << g.at << ", " << n(g.fix.lat) << ", "
        << n(g.fix.lon) << ", " << (g.map_xy ? n(g.map_xy->x) : "NULL") << ", "
        << (g.map_xy ? n(g.map_xy->y) : "NULL") << ")";
    }
    out.push_back(q.str());
  }
  for (std::string& s : robot_updates_) out.push_back(std::move(s));
  if (!removed_.empty()) {
    std::string s = "DELETE FROM rr WHERE id IN (";
    for (size_t i = 0; i < removed_.size(); ++i) {
      if (i) s += ',';
      s += std::to_string(removed_[i]);
    }
    out.push_back(s + ")");
  }
  answers_.clear();
  poses_.clear();
  fixes_.clear();
  robot_updates_.clear();
  removed_.clear();
  return out;
}

void WriteBatch::flush(bool commit) {
  std::vector<std::string> all = statements();
  if (commit) all.push_back("COMMIT");
  if (all.empty()) return;
  if (!multi_) {
    for (const std::string& s : all) execute(c_, s);
    return;
  }
  std::string joined;
  for (const std::string& s : all) joined += (joined.empty() ? "" : ";\n") + s;
  mysqlpp::Query q = c_.query(joined);
  q.store();
  while (q.more_results()) q.store_next();
}

}  // namespace fleetmap
