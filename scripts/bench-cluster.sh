#!/usr/bin/env bash
# Throughput of the fleet on 1, 2 and 3 Galera nodes beside the floor of the same run, and
# partitioned servers beside "every server write through one node" (docs/galera.md "What is
# measured"). The same robots and workload in every phase: galera_robot_fleet, each robot
# sending bursts of 3 requests and waiting for their answers (a closed loop, as in
# scripts/chaos-cluster.sh). The phases, in this order on one machine:
#
#   floor     a standalone instance (no wsrep, same buffers), 1 server, every robot on it
#   1 node    node 1 bootstrapped alone (wsrep on, cluster size 1), 1 server: wsrep's own cost
#   2 nodes   node 2 joined; servers 0/2 on node 1 and 1/2 on node 2; robots spread on 1-2
#   3 nodes   node 3 joined; servers 0/3, 1/3, 2/3, one per node; robots spread on 1-3
#   one-writer 3  3 nodes; servers 0/3, 1/3, 2/3 all on node 1; robots spread on 1-3
#   one-writer 1  3 nodes; one server (0/1) on node 1; robots spread on 1-3
#   all on node 1 3 nodes; one server and every robot on node 1 (nodes 2-3 only replicate)
#   shared 3  3 nodes; 3 servers all claiming every robot, one per node (--no-shared: skip)
#
# After the floor and each cluster size, with the servers stopped, the certification cost:
# --commits single-row INSERTs (autocommit) in one client session on node 1 (the floor's
# instance for the floor); each row stores SYSDATE(6), so the gap between two rows is one
# commit's round trip (the cluster certifies and replicates it before it returns).
#
# Prints one table: answered/s, its ratio to the floor, p50/p99 answer latency, the servers'
# 1213 retries, the robots' 1213 retries and reconnects, the commit p50/p99 and the load
# average. Exit 1 if a phase lost, doubled or reordered an answer.
#
#   scripts/bench-cluster.sh [--robots N] [--phase-seconds S] [--commits N] [--no-shared] [--keep]
#
# Settings (environment): FLEETMAP_CLUSTER_HOME (default <checkout>/build/bench-cluster),
# FLEETMAP_CLUSTER_PORT (scripts/cluster.sh), FLEETMAP_BENCH_PORT (the floor's instance;
# default cluster port + 400), FLEETMAP_BIN (default <checkout>/build/bin, with fleetmap,
# fleetmap-server and galera_robot_fleet). --keep leaves the cluster running.
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BIN="${FLEETMAP_BIN:-$ROOT/build/bin}"
CL="$ROOT/scripts/cluster.sh"
# shellcheck source=scripts/cluster-fleet.sh
. "$ROOT/scripts/cluster-fleet.sh"
ROBOTS=20 PHASE_S=12 COMMITS=300 SHARED=1 KEEP=0
while [ $# -gt 0 ]; do
  case "$1" in
    --robots) ROBOTS="$2"; shift 2 ;;
    --phase-seconds) PHASE_S="$2"; shift 2 ;;
    --commits) COMMITS="$2"; shift 2 ;;
    --no-shared) SHARED=0; shift ;;
    --keep) KEEP=1; shift ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "bench-cluster.sh: unknown option '$1' (--robots N, --phase-seconds S, --commits N, --no-shared, --keep)" >&2; exit 64 ;;
  esac
done
positive_int bench-cluster.sh --robots "$ROBOTS"
positive_int bench-cluster.sh --phase-seconds "$PHASE_S"
positive_int bench-cluster.sh --commits "$COMMITS"
need_bins bench-cluster.sh fleetmap fleetmap-server galera_robot_fleet

cluster_env "$ROOT/build/bench-cluster"
FLOOR_PORT="${FLEETMAP_BENCH_PORT:-$((P + 400))}"
FLOOR_HOME="$FLEETMAP_CLUSTER_HOME/floor"
W="$FLEETMAP_CLUSTER_HOME/bench"
RC=0

# The floor's instance: the cluster nodes' settings without wsrep (scripts/cluster.sh).
floor_db() {
  FLEETMAP_HOME="$FLOOR_HOME" FLEETMAP_PORT="$FLOOR_PORT" \
    FLEETMAP_MYSQLD_ARGS="--binlog-format=ROW --innodb-autoinc-lock-mode=2 $FLEETMAP_CLUSTER_MYSQLD_ARGS" \
    bash "$ROOT/scripts/db.sh" "$@"
}
target_conf() { if [ "$1" = floor ]; then echo "$FLOOR_HOME/fleetmap.conf"; else conf "$1"; fi; }
target_sql() { local t="$1"; shift; if [ "$t" = floor ]; then floor_db sql "$@"; else bash "$CL" sql "$t" "$@"; fi; }
cleanup() {
  fleet_stop
  servers_stop
  floor_db stop >/dev/null 2>&1 || true
  [ "$KEEP" = 1 ] || bash "$CL" stop >/dev/null 2>&1 || true
}
trap cleanup EXIT

declare -a ROWS=()
FLOOR_RPS=""
load1() { awk '{print $1}' /proc/loadavg; }

# run_phase NAME NODES HOSTS TARGET:PARTITION...: the servers (TARGET: floor or a node),
# then the fleet for PHASE_S seconds; one row of the table.
run_phase() {
  local name="$1" nodes="$2" hosts="$3"; shift 3
  local k=0 spec logs=()
  step "$name: servers $*; robots on $hosts; ${PHASE_S} s"
  for spec in "$@"; do
    k=$((k + 1))
    server_start "$name-$k" "$(target_conf "${spec%%:*}")" "${spec#*:}"
    logs+=("$W/server-$name-$k.log")
  done
  local rc=0
  FLEET_LOG_LEVEL=debug fleet "$name" "$hosts" "$PHASE_S" || rc=$?
  local load; load="$(load1)"
  servers_stop
  [ "$rc" = 0 ] || { echo "FAIL: $name: lost, doubled or reordered answers (exit $rc), see $W/$name.err" >&2; RC=1; }
  local rps; rps="$(field "$name" throughput_rps)"
  [ "$name" = floor ] && FLOOR_RPS="$rps"
  # A robot's 1213: its statement rolled back and sent again (client/robot_client.cpp).
  local robot1213; robot1213="$(grep -c 'sending it again' "$W/$name.err" || true)"
  ROWS+=("$(printf '%-13s %5s %7s %10s %6s %8s %8s %8s %10s %10s %11s %5s' \
    "$name" "$nodes" "$#" "$rps" "$(ratio "$rps" "$FLOOR_RPS")" "$(field "$name" p50_ms)" "$(field "$name" p99_ms)" \
    "$(conflicts "${logs[@]}")" "$robot1213" "$(field "$name" reconnects)" "${COMMIT[$name]:--}" "$load")")
  echo "${ROWS[-1]}"
}

declare -A COMMIT=()
# commit_probe NAME TARGET: COMMITS single-row autocommit INSERTs in one session; the gaps
# between consecutive rows' SYSDATE(6) are the commits' round trips: "p50/p99" in ms.
commit_probe() {  # commit_probe NAME TARGET [SQL run first in the session]
  local name="$1" t="$2" i
  {
    echo "${3:-}"
    echo "CREATE DATABASE IF NOT EXISTS fleetmap_probe;"
    echo "CREATE TABLE IF NOT EXISTS fleetmap_probe.commit_probe (id BIGINT AUTO_INCREMENT PRIMARY KEY,"
    echo "  run VARCHAR(32) NOT NULL, at DATETIME(6) NOT NULL) ENGINE=InnoDB;"
    for i in $(seq 1 "$COMMITS"); do echo "INSERT INTO fleetmap_probe.commit_probe (run, at) VALUES ('$name', SYSDATE(6));"; done
    echo "SELECT TIMESTAMPDIFF(MICROSECOND, LAG(at) OVER (ORDER BY id), at) FROM fleetmap_probe.commit_probe WHERE run = '$name';"
  } | target_sql "$t" -N > "$W/commit-$name.txt"
  COMMIT[$name]="$(grep -v NULL "$W/commit-$name.txt" | sort -n | awk '{v[NR] = $1}
    END { if (NR == 0) { print "-"; exit }
          i50 = int(0.50 * (NR - 1) + 1.5); i99 = int(0.99 * (NR - 1) + 1.5); if (i99 > NR) i99 = NR
          printf "%.2f/%.2f", v[i50] / 1000, v[i99] / 1000 }')"
  echo "commit round trip on $name (${COMMITS} INSERTs, ms p50/p99): ${COMMIT[$name]}"
}

step "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
bash "$CL" stop >/dev/null 2>&1 || true
floor_db stop >/dev/null 2>&1 || true
rm -rf "$FLEETMAP_CLUSTER_HOME"
mkdir -p "$W"

step "floor: a standalone instance (port $FLOOR_PORT), $ROBOTS robots"
floor_db start >/dev/null
DB="$(awk '$1=="name"{print $3; exit}' "$(target_conf floor)")"
add_robots "$(target_conf floor)" "$ROBOTS"
commit_probe floor floor
# A wsrep node writes no redo log fsync per commit (0 Innodb_os_log_fsyncs in 100 commits
# here): the other nodes' copies stand for it. The floor without it, for the same footing.
floor_db sql -e "SET GLOBAL innodb_flush_log_at_trx_commit = 2"
commit_probe floor-nofsync floor
floor_db sql -e "SET GLOBAL innodb_flush_log_at_trx_commit = 1"
run_phase floor 0 "127.0.0.1:$FLOOR_PORT" floor:0/1
floor_db stop >/dev/null

N1="127.0.0.1:$P" N2="127.0.0.1:$((P + 1))" N3="127.0.0.1:$((P + 2))"
step "node 1 bootstraps a cluster of one (port $P)"
bash "$CL" start 1 >/dev/null
add_robots "$(conf 1)" "$ROBOTS"
commit_probe "1-node" 1
run_phase "1-node" 1 "$N1" 1:0/1

step "node 2 joins"
bash "$CL" start 2 >/dev/null
commit_probe "2-nodes" 1
run_phase "2-nodes" 2 "$N1,$N2" 1:0/2 2:1/2

step "node 3 joins"
bash "$CL" start 3 >/dev/null
commit_probe "3-nodes" 1
run_phase "3-nodes" 3 "$N1,$N2,$N3" 1:0/3 2:1/3 3:2/3
run_phase "one-writer-3" 3 "$N1,$N2,$N3" 1:0/3 1:1/3 1:2/3
run_phase "one-writer-1" 3 "$N1,$N2,$N3" 1:0/1
run_phase "all-on-node1" 3 "$N1" 1:0/1
[ "$SHARED" = 1 ] && run_phase "shared-3" 3 "$N1,$N2,$N3" 1:0/1 2:0/1 3:0/1

echo
echo "$ROBOTS robots, bursts of 3, ${PHASE_S} s a phase; load average at the end: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
printf '%-13s %5s %7s %10s %6s %8s %8s %8s %10s %10s %11s %5s\n' phase nodes servers answered/s xfloor \
  p50_ms p99_ms srv_1213 robot_1213 reconnects commit_ms load1
printf '%s\n' "${ROWS[@]}"
echo "commit_ms: p50/p99 of one INSERT's commit on node 1, idle cluster; the floor without its log fsync" \
     "(innodb_flush_log_at_trx_commit = 2, as on a wsrep node): ${COMMIT[floor-nofsync]}"
echo "(one run on one machine shared with other jobs: compare the ratios)"
[ "$RC" = 0 ] && echo "PASS" || echo "FAILED (logs in $W)"
exit "$RC"
