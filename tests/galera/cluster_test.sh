#!/usr/bin/env bash
# A real three-node Galera cluster (scripts/cluster.sh) under fleetmap (CTest: galera_cluster):
#  - the cluster forms: three nodes Synced, each seeing a cluster of 3;
#  - what the operator writes on one node (a map, a robot account and its grants) is
#    there on every other node;
#  - robots on any node: a robot account logs in on node 2 and its Ready, inserted there,
#    is answered by a fleetmap-server connected to node 1;
#  - a node killed with -9 leaves a working cluster of 2; restarted, it rejoins and has
#    what was written while it was down.
#   cluster_test.sh SOURCE_DIR BUILD_DIR PORT
set -euo pipefail
SRC="$1" BUILD="$2" PORT="$3"
BIN="$BUILD/bin"
export FLEETMAP_CLUSTER_HOME="$BUILD/testcluster" FLEETMAP_CLUSTER_PORT="$PORT"
export FLEETMAP_CLUSTER_MYSQLD_ARGS="--innodb-buffer-pool-size=64M --innodb-log-file-size=32M"
unset FLEETMAP_CONFIG FLEETMAP_HOST FLEETMAP_PORT FLEETMAP_SOCKET FLEETMAP_DB FLEETMAP_USER FLEETMAP_PASSWORD
CL="$SRC/scripts/cluster.sh"
SERVER_PID=""
fail() { echo "FAIL: $*" >&2; exit 1; }
step() { echo "--- $(date +%T) $*"; }
cleanup() {
  if [ -n "$SERVER_PID" ]; then kill "$SERVER_PID" 2>/dev/null || true; wait "$SERVER_PID" 2>/dev/null || true; fi
  bash "$CL" stop >/dev/null 2>&1 || true
}
trap cleanup EXIT
conf() { bash "$CL" conf "$1"; }
fm() { local n="$1"; shift; FLEETMAP_CONFIG="$(conf "$n")" "$BIN/fleetmap" "$@"; }
node_status() { { bash "$CL" status || true; } | sed -n "${1}p"; }

step "a fresh cluster of three"
bash "$CL" stop >/dev/null 2>&1 || true
rm -rf "$FLEETMAP_CLUSTER_HOME"
bash "$CL" start
for n in 1 2 3; do
  node_status "$n" | grep -q "cluster size 3, Synced, ready ON" || fail "node $n: $(node_status "$n")"
done

step "the operator writes on node 3; nodes 1 and 2 have it"
fm 3 map import "$SRC/maps/example-room.map" --name gal_room >/dev/null
PW="$FLEETMAP_CLUSTER_HOME/r1.pw"
(umask 077; echo "galera-test-$$-pw" > "$PW")
fm 3 robot add gal_r1 --map gal_room --password-file "$PW" >/dev/null
for n in 1 2; do
  fm "$n" map list | grep -qw gal_room || fail "node $n does not have the map written on node 3"
  fm "$n" robot list | grep -qw gal_r1 || fail "node $n does not have the robot added on node 3"
done

step "a robot on node 2, the server on node 1"
FLEETMAP_CONFIG="$(conf 1)" "$BIN/fleetmap-server" --log-level warn > "$FLEETMAP_CLUSTER_HOME/server.log" 2>&1 &
SERVER_PID=$!
robot_sql() {  # robot_sql NODE SQL: as the robot, over TCP, on that node
  mariadb --no-defaults -h 127.0.0.1 -P "$((PORT + $1 - 1))" -u gal_r1 -p"$(cat "$PW")" -N -e "$2" \
    "$(awk '$1=="name"{print $3; exit}' "$(conf 1)")"
}
robot_sql 2 "INSERT INTO rr (op, params) VALUES ('Ready', '{\"magic\": 77}')"
got=""
for _ in $(seq 1 80); do
  got="$(robot_sql 2 "SELECT op FROM sa_mine ORDER BY id" | tr '\n' ' ')"
  case "$got" in *Start*) break ;; esac
  sleep 0.25
done
case "$got" in *Start*) ;; *) cat "$FLEETMAP_CLUSTER_HOME/server.log" >&2; fail "no Start for the robot on node 2 (sa_mine: '$got')" ;; esac

[ "$(fm 1 robot list | awk '$2=="gal_r1"{print $4}')" = ready ] || fail "gal_r1 is not ready on node 1: $(fm 1 robot list)"
kill "$SERVER_PID"; wait "$SERVER_PID" 2>/dev/null || true; SERVER_PID=""

step "kill -9 node 2; the other two go on"
bash "$CL" kill 2
node_status 2 | grep -q "not running" || fail "node 2 still runs: $(node_status 2)"
for _ in $(seq 1 40); do node_status 1 | grep -q "cluster size 2, Synced" && break; sleep 0.25; done
node_status 1 | grep -q "cluster size 2, Synced, ready ON" || fail "node 1 after the kill: $(node_status 1)"
(umask 077; echo "galera-test-$$-pw2" > "$PW.2")
fm 1 robot add gal_r2 --map gal_room --password-file "$PW.2" >/dev/null
fm 3 robot list | grep -qw gal_r2 || fail "node 3 does not have the robot added on node 1"

step "node 2 rejoins and has what was written while it was down"
bash "$CL" start 2
node_status 2 | grep -q "cluster size 3, Synced, ready ON" || fail "node 2 after the restart: $(node_status 2)"
fm 2 robot list | grep -qw gal_r2 || fail "node 2 lacks the robot added while it was down"
mariadb --no-defaults -h 127.0.0.1 -P "$((PORT + 1))" -u gal_r2 -p"$(cat "$PW.2")" -N -e "SELECT 1" >/dev/null \
  || fail "the robot account added while node 2 was down cannot log in on node 2"

step "clean stop"
bash "$CL" stop
bash "$CL" status >/dev/null && fail "status says running after stop"
echo "PASS"
