#pragma once
// Tasks created or changed since a moment (tasks.updated_at, sql/10_schema.sql): what the
// web feed pushes to the console (server/web/http/fleet_feed.h) between two polls.
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "protocol/fleet_store.h"

namespace fleetmap {

// The database's clock, as the session's time zone writes a TIMESTAMP(6)
// ('2026-12-02 04:10:08.123456'): the first `since` of a feed.
std::string database_now(mysqlpp::Connection& c);

// Tasks whose updated_at is after since (same text form) minus lookback_us, oldest change
// first, at most limit; times as the session's time zone shows them. The look-back
// catches a transaction that stamped its rows before another one's but committed after
// it; the caller drops what it has seen already.
std::vector<TaskInfo> tasks_updated_since(mysqlpp::Connection& c, const std::string& since, long long lookback_us = 0,
                                          size_t limit = 1000);

}  // namespace fleetmap
