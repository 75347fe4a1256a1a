#pragma once
// How long the position history is kept. A fleet appends its poses and GPS fixes all the
// time (200 robots at 3 Hz: 600 trajectory rows a second, 52 M a day), and SPEC 5 keeps
// them for the operator and the inspectors; a site that needs only the recent past lets
// the server delete the rest, so that the tables, the disk and the buffer pool stay
// bounded. Each pass deletes a bounded batch, so that it never holds locks on a large part
// of a table while robots write their poses.
#include <cstddef>

#include <mysql++/mysql++.h>

namespace fleetmap {

struct HistoryDeleted {
  size_t trajectory_rows = 0;
  size_t gps_fixes = 0;
};

// Deletes the trajectory rows and GPS fixes older than keep_s seconds (by their time t,
// against the database's clock), at most `batch` rows of each table. keep_s <= 0 (or
// beyond a thousand years) deletes nothing.
HistoryDeleted delete_history_before(mysqlpp::Connection& c, double keep_s, size_t batch = 5000);

}  // namespace fleetmap
