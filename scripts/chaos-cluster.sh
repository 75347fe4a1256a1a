#!/usr/bin/env bash
# The fault run of a fleet on a three-node Galera cluster (docs/galera.md "Faults"):
# robots on RobotClient (galera_robot_fleet) send numbered requests through every phase:
#
#   floor     1 server on node 1, every robot on node 1: the single-node figures
#   shared    2 servers on nodes 1 and 2 that both claim every robot (no partition),
#             robots spread over nodes 1-3: the certification conflicts (1213) they cost
#   cluster   2 partitioned servers (0/2 on node 1, 1/2 on node 2), robots spread over
#             nodes 1-3, each with every node as a failover host
#   faults    the same, while: node 3 is killed -9 and restarted (it rejoins); server A
#             is killed -9 and restarted; node 2 and server B are killed -9 together, B
#             restarts on node 3, node 2 rejoins; node 2 is cut off from the others
#             (Galera's gmcast.isolate) and must end non-primary while nodes 1 and 3 stay
#             primary (no split brain), then healed
#
# and fails (exit 1) unless, in every phase, no request was lost, none answered twice,
# each robot's answers came in the order of its requests; and, in the fault phase,
# robots reconnected by themselves. The shared phase's losses are reported, and fail the
# run only with --strict-shared (a known defect, docs/galera.md). Prints each phase's line
# and the cluster/floor ratios.
#
#   scripts/chaos-cluster.sh [--robots N] [--phase-seconds S] [--fault-step S] [--keep] [--strict-shared]
#
# Settings (environment): FLEETMAP_CLUSTER_HOME, FLEETMAP_CLUSTER_PORT (scripts/cluster.sh;
# the run starts a fresh cluster there), FLEETMAP_BIN (default <checkout>/build/bin, with
# fleetmap, fleetmap-server and galera_robot_fleet). --keep leaves the cluster running.
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BIN="${FLEETMAP_BIN:-$ROOT/build/bin}"
CL="$ROOT/scripts/cluster.sh"
# shellcheck source=scripts/cluster-fleet.sh
. "$ROOT/scripts/cluster-fleet.sh"
ROBOTS=20 PHASE_S=6 STEP_S=3 KEEP=0 STRICT_SHARED=0
while [ $# -gt 0 ]; do
  case "$1" in
    --robots) ROBOTS="$2"; shift 2 ;;
    --phase-seconds) PHASE_S="$2"; shift 2 ;;
    --fault-step) STEP_S="$2"; shift 2 ;;
    --keep) KEEP=1; shift ;;
    --strict-shared) STRICT_SHARED=1; shift ;;
    -h|--help) sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "chaos-cluster.sh: unknown option '$1' (--robots N, --phase-seconds S, --fault-step S, --keep, --strict-shared)" >&2; exit 64 ;;
  esac
done
positive_int chaos-cluster.sh --robots "$ROBOTS"
need_bins chaos-cluster.sh fleetmap fleetmap-server galera_robot_fleet

cluster_env "$ROOT/.fleetmap-chaos"
W="$FLEETMAP_CLUSTER_HOME/chaos"
RC=0

fail() { echo "FAIL: $*" >&2; RC=1; }
cleanup() {
  stall_watch_stop
  fleet_stop
  servers_stop
  [ "$KEEP" = 1 ] || bash "$CL" stop >/dev/null 2>&1 || true
}
trap cleanup EXIT
wsrep() { bash "$CL" sql "$1" -N -e "SHOW GLOBAL STATUS LIKE '$2'" 2>/dev/null | awk '{print $2}'; }
check_phase() {  # check_phase NAME RC
  local line; line="$(cat "$W/$1.out" 2>/dev/null || true)"
  printf '%-8s %s\n' "$1" "$line"
  [ "$2" = 0 ] || fail "$1: the fleet found lost, doubled or reordered answers, or robots that never registered (exit $2): $(grep -m5 -i 'error\|not answered' "$W/$1.err" | tr '\n' ' ')"
  [ -n "$line" ] || fail "$1: no figures"
}

step "a fresh cluster of three (port $P)"
bash "$CL" stop >/dev/null 2>&1 || true
rm -rf "$FLEETMAP_CLUSTER_HOME"
bash "$CL" start >/dev/null
mkdir -p "$W"
DB="$(awk '$1=="name"{print $3; exit}' "$(conf 1)")"
add_robots "$(conf 1)" "$ROBOTS"
N1="127.0.0.1:$P" N2="127.0.0.1:$((P + 1))" N3="127.0.0.1:$((P + 2))"
stall_watch_start

step "floor: one server, one node, $ROBOTS robots for ${PHASE_S} s"
server_start floor "$(conf 1)" 0/1
rc=0; fleet floor "$N1" "$PHASE_S" || rc=$?
server_stop floor
check_phase floor "$rc"

step "shared: two servers claiming every robot, on nodes 1 and 2, robots on nodes 1-3, ${PHASE_S} s"
server_start S1 "$(conf 1)" 0/1
server_start S2 "$(conf 2)" 0/1
rc=0; fleet shared "$N1,$N2,$N3" "$PHASE_S" || rc=$?
server_stop S1; server_stop S2
# Two servers claiming the same robots through two nodes is the set-up docs/galera.md
# advises against ("Several servers"). It lost 2 of 1 155 requests in one run of eight here
# (docs/galera.md, "Requests lost with shared servers"), a defect not yet found: its losses
# are reported here and fail the run only with --strict-shared.
if [ "$STRICT_SHARED" = 1 ] || [ "$rc" = 0 ]; then
  check_phase shared "$rc"
else
  printf '%-8s %s\n' shared "$(cat "$W/shared.out" 2>/dev/null || true)"
  echo "KNOWN DEFECT, not failed on (--strict-shared fails): shared: $(grep -m5 -i 'error\|not answered' "$W/shared.err" | tr '\n' ' ')"
fi
# What the shared phase left unanswered must not reach the next phase's robots as
# answers to no request of theirs.
echo "left by the shared phase: $(bash "$CL" sql 1 -N -e "SELECT COUNT(*) FROM rr") request(s)," \
     "$(bash "$CL" sql 1 -N -e "SELECT COUNT(*) FROM sa WHERE sentinel = 0") answer(s); removed"
bash "$CL" sql 1 -e "DELETE FROM rr; DELETE FROM sa WHERE sentinel = 0"

step "cluster: servers 0/2 on node 1 and 1/2 on node 2, robots on nodes 1-3, ${PHASE_S} s"
server_start A "$(conf 1)" 0/2
server_start B "$(conf 2)" 1/2
rc=0; fleet cluster "$N1,$N2,$N3" "$PHASE_S" || rc=$?
check_phase cluster "$rc"
SHARED_1213="$(conflicts "$W/server-S1.log" "$W/server-S2.log")"
CLUSTER_1213="$(conflicts "$W/server-A.log" "$W/server-B.log")"

step "faults: traffic until the last fault healed, a fault every ${STEP_S} s"
rm -f "$W/faults.stop"
# Paced, as a fleet sends: a closed loop at full speed keeps a rejoining node catching up.
fleet faults "$N1,$N2,$N3" 600 "$W/faults.stop" 250 & FLEET=$!
sleep "$STEP_S"
step "kill -9 node 3 (robots on it fail over)"; bash "$CL" kill 3 >/dev/null
sleep "$STEP_S"
step "node 3 rejoins"; bash "$CL" start 3 >/dev/null || fail "node 3 did not rejoin"
step "kill -9 server A, restart it"; server_kill A; sleep 1; server_start A "$(conf 1)" 0/2
sleep "$STEP_S"
step "kill -9 node 2 and server B together; B restarts on node 3"
server_kill B; bash "$CL" kill 2 >/dev/null; server_start B "$(conf 3)" 1/2
sleep "$STEP_S"
step "node 2 rejoins"; bash "$CL" start 2 >/dev/null || fail "node 2 did not rejoin"
sleep 1
step "cut node 2 off the others (gmcast.isolate)"
bash "$CL" sql 2 -e "SET GLOBAL wsrep_provider_options = 'gmcast.isolate=1'"
cut=""
for _ in $(seq 1 40); do
  cut="$(wsrep 2 wsrep_cluster_status) $(wsrep 1 wsrep_cluster_status)/$(wsrep 1 wsrep_cluster_size) $(wsrep 3 wsrep_cluster_status)/$(wsrep 3 wsrep_cluster_size)"
  [ "$cut" = "non-Primary Primary/2 Primary/2" ] && break
  sleep 0.25
done
echo "node 2: $(echo "$cut" | awk '{print $1}'); nodes 1 and 3: $(echo "$cut" | awk '{print $2, $3}')"
[ "$cut" = "non-Primary Primary/2 Primary/2" ] || fail "after the cut: node 2, node 1, node 3 = '$cut', expected non-Primary, Primary/2, Primary/2"
# No split brain: the cut-off node refuses writes and reads.
if bash "$CL" sql 2 -e "SELECT COUNT(*) FROM $DB.robots" >/dev/null 2>&1; then fail "node 2 serves reads while non-primary"; fi
sleep "$STEP_S"
step "heal the cut"
bash "$CL" sql 2 -e "SET GLOBAL wsrep_provider_options = 'gmcast.isolate=0'"
healed=""
for _ in $(seq 1 120); do
  healed="$(wsrep 2 wsrep_local_state_comment)/$(wsrep 2 wsrep_cluster_size)"
  [ "$healed" = "Synced/3" ] && break
  sleep 0.25
done
[ "$healed" = "Synced/3" ] || fail "node 2 after the cut healed: '$healed', expected Synced/3"
sleep "$STEP_S"  # traffic on the healed cluster
touch "$W/faults.stop"
rc=0; wait "$FLEET" || rc=$?
FLEET=""
check_phase faults "$rc"
[ "$(field faults reconnected_robots)" -ge 1 ] 2>/dev/null || fail "faults: no robot reconnected"
for n in 1 2 3; do
  s="$(wsrep "$n" wsrep_local_state_comment)/$(wsrep "$n" wsrep_cluster_size)"
  [ "$s" = "Synced/3" ] || fail "node $n at the end: '$s', expected Synced/3"
done

echo "server retries of certification conflicts (1213): shared $SHARED_1213, partitioned $CLUSTER_1213" \
     "(p50 $(field shared p50_ms) ms against $(field cluster p50_ms) ms)"
echo "shared / floor: throughput $(ratio "$(field shared throughput_rps)" "$(field floor throughput_rps)")," \
     "p50 $(ratio "$(field shared p50_ms)" "$(field floor p50_ms)")"
echo "cluster / floor: throughput $(ratio "$(field cluster throughput_rps)" "$(field floor throughput_rps)")," \
     "p50 $(ratio "$(field cluster p50_ms)" "$(field floor p50_ms)"), p99 $(ratio "$(field cluster p99_ms)" "$(field floor p99_ms)")" \
     "(same run; the machine is shared, so compare ratios)"
stall_watch_stop
[ "$RC" = 0 ] || stalls_seen
[ "$RC" = 0 ] && echo "PASS" || echo "FAILED (logs in $W)"
exit "$RC"
