#include "protocol/tour_store.h"

#include "common/geometry/number_format.h"

namespace fleetmap {
namespace {

std::string n(double v) { return format_number(v); }

}  // namespace

void TourStore::record(unsigned robot_id, std::optional<unsigned> map_id, const std::string& tour, const TourEvent& e,
                       const std::string& at) {
  mysqlpp::Query q = c_.query();
  q << "INSERT INTO tour_events (robot_id, map_id, tour, kind, name, x, y, theta, t) VALUES (" << robot_id << ", "
    << (map_id ? std::to_string(*map_id) : "NULL") << ", " << mysqlpp::quote << tour << ", " << mysqlpp::quote
    << std::string(to_string(e.kind)) << ", ";
  if (e.name.empty()) q << "NULL";
  else q << mysqlpp::quote << e.name;
  q << ", " << n(e.pose.x) << ", " << n(e.pose.y) << ", " << n(e.pose.theta) << ", " << mysqlpp::quote << at << ")";
  q.execute();
}

std::vector<TourEvent> TourStore::load(unsigned robot_id, const std::string& tour) {
  mysqlpp::Query q = c_.query();
  q << "SELECT kind, name, x, y, theta, UNIX_TIMESTAMP(t) FROM tour_events WHERE robot_id = " << robot_id
    << " AND tour = " << mysqlpp::quote << tour << " ORDER BY id";
  std::vector<TourEvent> events;
  for (const mysqlpp::Row& r : q.store()) {
    TourEvent e;
    // The column is an ENUM of exactly these words.
    e.kind = tour_event_kind_from_string(std::string(r[0].data(), r[0].length())).value_or(TourEventKind::Crossing);
    if (!r[1].is_null()) e.name = std::string(r[1].data(), r[1].length());
    e.pose = {double(r[2]), double(r[3]), double(r[4])};
    e.t = double(r[5]);
    events.push_back(std::move(e));
  }
  return events;
}

std::vector<TourSummary> TourStore::tours(unsigned robot_id) {
  mysqlpp::Query q = c_.query();
  q << "SELECT tour, COUNT(*), MIN(t), MAX(t) FROM tour_events WHERE robot_id = " << robot_id
    << " GROUP BY tour ORDER BY tour";
  std::vector<TourSummary> out;
  for (const mysqlpp::Row& r : q.store())
    out.push_back({std::string(r[0].data(), r[0].length()), static_cast<size_t>(r[1]), std::string(r[2].data(), r[2].length()),
                   std::string(r[3].data(), r[3].length())});
  return out;
}

}  // namespace fleetmap
