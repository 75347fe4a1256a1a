#!/usr/bin/env bash
# Server load benchmark on its own private MariaDB (<build>/benchsrv, port 33318):
# fleetmap-loadgen plays N robots (own account and connection each, plain SQL), first
# against a minimal answering loop (the floor: the bare database path), then against the
# real fleetmap-server, in the same run; then the servers' idle polling cost, then scaling.
# Beside the server, "lean" rows: a batched prototype inside fleetmap-loadgen that does the
# server's durable work in a few round trips per batch (what the proposals would reach).
#
#   scripts/bench-server.sh [options]
#     --robots N          fleet size of phases 1-2 (default 200)
#     --seconds S         measurement window of phases 1-2 (default 20)
#     --scaling "LIST"    robot counts of phase 4 (default "200 400 600 1000")
#     --scaling-seconds S window of each phase-4 run (default 10)
#     --procs "LIST"      server processes in phase 4 (default "1 2")
#     --idle-seconds S    no-traffic window of phase 3 (default 10)
#     --polls "LIST"      --poll-max-ms values of phase 3 (default "1 10 50")
#     --threads T         loadgen client threads (default 8)
#     --phases "LIST"     any of floor server idle scaling policy (default the first four)
#     --policies "LIST"   phase policy: the robots' wait policies (protocol/wait_policy.h), each
#                         NAME:FIRST,MIN,MAX,BACKOFF (ms, ms, ms, fraction), one fleet run of --robots
#                         robots each (default: fixed 1, 2, 5 ms, loadgen's old loop, two back-off schedules)
#     --idles "LIST"      phase policy: idle_ms values, one quiet run each (Alive and idle polls only;
#                         0 = no idle polls, the baseline) (default "0 100 250 1000")
#     --server-flags "F"  extra flags for every fleetmap-server (e.g. "--workers 4")
#     --long              longer windows: --seconds 60 --scaling-seconds 40 --idle-seconds 30
#     --no-lean           skip the lean prototype rows
#     --no-build          use the binaries in the build folder as they are
# Environment: FLEETMAP_BUILD_DIR (default build), FLEETMAP_BENCH_PORT (default 33318),
# FLEETMAP_MAPS_DIR (the real maps, default ../shared/maps beside the checkout).
# Results: <build>/benchsrv/results-<time>.jsonl (one JSON line per run), tables at the end.
# Robot accounts lg0001... are created once with `fleetmap robot add` and reused.
set -euo pipefail
source "$(dirname "$0")/real-maps.sh"
require_real_maps bench-server UT_Campus.vectormap.txt
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
BIN="$BUILD/bin"

ROBOTS=200 SECONDS_=20 SCALING="200 400 600 1000" SCALING_SECONDS=10 PROCS="1 2" IDLE_SECONDS=10
POLLS="1 10 50" THREADS=8 PHASES="floor server idle scaling" SERVER_FLAGS="" BUILD_FIRST=1 LEAN=1
POLICIES="fixed1:0,1,1,0 fixed2:0,2,2,0 fixed5:0,5,5,0 loadgen-before:0,1,100000,0.1 backoff1:1,1,50,0.1 backoff2:2,2,50,0.25" IDLES="0 100 250 1000"
while [ $# -gt 0 ]; do
  case "$1" in
    --robots) ROBOTS="$2"; shift 2 ;;
    --seconds) SECONDS_="$2"; shift 2 ;;
    --scaling) SCALING="$2"; shift 2 ;;
    --scaling-seconds) SCALING_SECONDS="$2"; shift 2 ;;
    --procs) PROCS="$2"; shift 2 ;;
    --idle-seconds) IDLE_SECONDS="$2"; shift 2 ;;
    --polls) POLLS="$2"; shift 2 ;;
    --threads) THREADS="$2"; shift 2 ;;
    --phases) PHASES="$2"; shift 2 ;;
    --policies) POLICIES="$2"; shift 2 ;;
    --idles) IDLES="$2"; shift 2 ;;
    --server-flags) SERVER_FLAGS="$2"; shift 2 ;;
    --long) SECONDS_=60; SCALING_SECONDS=40; IDLE_SECONDS=30; shift ;;
    --no-build) BUILD_FIRST=0; shift ;;
    --no-lean) LEAN=0; shift ;;
    -h|--help) sed -n '2,31p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench-server: unknown option '$1' (--help)" >&2; exit 64 ;;
  esac
done
has_phase() { case " $PHASES " in *" $1 "*) return 0 ;; *) return 1 ;; esac; }

if [ "$BUILD_FIRST" = 1 ]; then
  cmake --build "$BUILD" -j2 --target fleetmap fleetmap-server fleetmap-loadgen >/dev/null
fi
for b in fleetmap fleetmap-server fleetmap-loadgen; do
  [ -x "$BIN/$b" ] || { echo "bench-server: $BIN/$b missing; build it (cmake --build $BUILD --target $b)" >&2; exit 1; }
done

export FLEETMAP_HOME="$PWD/$BUILD/benchsrv" FLEETMAP_PORT="${FLEETMAP_BENCH_PORT:-33318}"
unset FLEETMAP_CONFIG FLEETMAP_HOST FLEETMAP_SOCKET FLEETMAP_DB FLEETMAP_USER FLEETMAP_PASSWORD
SERVER_PIDS=()
stop_servers() {
  local p
  for p in "${SERVER_PIDS[@]}"; do kill -TERM "$p" 2>/dev/null || true; done
  for p in "${SERVER_PIDS[@]}"; do wait "$p" 2>/dev/null || true; done
  SERVER_PIDS=()
}
cleanup() { stop_servers; bash scripts/db.sh stop >/dev/null || true; }
trap cleanup EXIT
T_START=$(date +%s)
bash scripts/db.sh start
DB_PID="$(cat "$FLEETMAP_HOME/mysqld.pid")"
sql() { bash scripts/db.sh sql -N -e "$1"; }

# One connection per robot, plus servers and tools. max_connections is dynamic; the
# open-files limit was set at start (db.sh) and bounds it.
MAXC=$(( $(echo $SCALING $ROBOTS | tr ' ' '\n' | sort -n | tail -1) + 200 ))
sql "SET GLOBAL max_connections = $MAXC"
echo "bench-server: max_connections $MAXC, open_files_limit $(sql "SELECT @@open_files_limit")," \
     "innodb_flush_log_at_trx_commit $(sql "SELECT @@innodb_flush_log_at_trx_commit")"

if ! "$BIN/fleetmap" map list | grep -qw UT_Campus; then
  "$BIN/fleetmap" map import "$MAPS/UT_Campus.vectormap.txt" --name UT_Campus
fi

# Robot accounts lg0001..lgNNNN: reuse those that exist with their password file.
NEED=$(echo $SCALING $ROBOTS | tr ' ' '\n' | sort -n | tail -1)
has_phase scaling || NEED=$ROBOTS
PWDIR="$FLEETMAP_HOME/robots"
T0=$(date +%s)
source scripts/robot-accounts.sh
ensure_robot_accounts "$BIN/fleetmap" lg "$NEED" UT_Campus "$PWDIR" bench-server
ADDED=$ROBOT_ACCOUNTS_ADDED
echo "bench-server: $NEED robot accounts ready ($ADDED added in $(( $(date +%s) - T0 )) s)"

RES="$FLEETMAP_HOME/results-$(date +%Y%m%d-%H%M%S).jsonl"
: > "$RES"
LG=("$BIN/fleetmap-loadgen" --password-dir "$PWDIR" --map UT_Campus --results "$RES" --db-pid "$DB_PID"
    --threads "$THREADS")
WORKERS=$( "$BIN/fleetmap-server" --check $SERVER_FLAGS | sed -n 's/.*, \([0-9]*\) workers.*/\1/p' )

# Undelivered traffic of an earlier run must not be the next run's load.
clear_mailboxes() {
  local i n
  # A fleetmap-server left from elsewhere would answer (and end robot connections) under the
  # floor's feet: none may be connected between runs.
  n="$(sql "SELECT COUNT(*) FROM information_schema.PROCESSLIST WHERE USER = 'fleetmap_server'")"
  if [ "$n" != 0 ]; then
    echo "bench-server: $n connection(s) of fleetmap_server to $FLEETMAP_HOME between runs; stop that server first" >&2
    exit 1
  fi
  for i in 1 2 3 4 5; do
    sql "DELETE FROM rr; DELETE FROM sa WHERE sentinel = 0" 2>/dev/null && return 0
    sleep 1
  done
  sql "DELETE FROM rr; DELETE FROM sa WHERE sentinel = 0"
}

start_servers() {  # PROCS [flags...]
  local n="$1" i; shift
  clear_mailboxes
  for i in $(seq 1 "$n"); do
    # shellcheck disable=SC2086
    "$BIN/fleetmap-server" --log-level warn $SERVER_FLAGS "$@" >>"$FLEETMAP_HOME/server-$i.log" 2>&1 &
    SERVER_PIDS+=($!)
  done
  sleep 1
  for i in "${SERVER_PIDS[@]}"; do kill -0 "$i" || { echo "bench-server: fleetmap-server exited, see $FLEETMAP_HOME/server-*.log" >&2; exit 1; }; done
}
pids() { local IFS=,; echo "${SERVER_PIDS[*]}"; }
worst_p99() { awk '/answered \(GetMap\+SendGPS\)/ { print $(NF-1) }' "$1"; }
run_lg() {  # LOG ARGS...: a loadgen run, its output shown and kept; a failed run is reported, the rest goes on
  local log="$1"; shift
  "${LG[@]}" "$@" | tee "$log" || echo "bench-server: fleetmap-loadgen $* failed (see above)" >&2
}
LOG="$FLEETMAP_HOME/last-run.txt"

if has_phase floor; then
  printf '\n######## 1. floor\n'
  clear_mailboxes
  run_lg "$LOG" --mode floor --workload lone --phase floor --label "lone robot"
  clear_mailboxes
  run_lg "$LOG" --mode floor --robots "$ROBOTS" --seconds "$SECONDS_" --phase floor --label "$ROBOTS robots"
fi

if has_phase server; then
  printf '\n######## 2. server (1 process, %s workers)\n' "$WORKERS"
  start_servers 1
  run_lg "$LOG" --mode server --robots "$ROBOTS" --seconds "$SECONDS_" --phase server --label "$ROBOTS robots" \
    --server-pid "$(pids)" --server-procs 1 --workers "$WORKERS"
  stop_servers
  if [ "$LEAN" = 1 ]; then
    clear_mailboxes
    run_lg "$LOG" --mode lean --robots "$ROBOTS" --seconds "$SECONDS_" --phase server --label "lean $ROBOTS robots"
  fi
fi

if has_phase idle; then
  printf '\n######## 3. idle polling cost and lone requests\n'
  for pm in $POLLS; do
    start_servers 1 --poll-max-ms "$pm"
    sleep 1
    run_lg "$LOG" --mode idle --seconds "$IDLE_SECONDS" --phase idle --label "poll-max-ms $pm" --poll-max-ms "$pm" \
      --server-pid "$(pids)" --server-procs 1 --workers "$WORKERS"
    stop_servers
  done
fi

if has_phase scaling; then
  printf '\n######## 4. scaling (each robot count: floor, server with each process count, lean; interleaved)\n'
  over() {  # the last run's answered p99 (GetMap and SendGPS together) is over 20 ms (or missing)
    local p99; p99="$(worst_p99 "$LOG")"
    if [ -z "$p99" ] || awk -v p="$p99" 'BEGIN { exit !(p > 20) }'; then
      echo "bench-server: p99 ${p99:-?} ms > 20 ms at $1; this series stops here"
      return 0
    fi
    return 1
  }
  SERIES="floor"
  for procs in $PROCS; do SERIES="$SERIES p$procs"; done
  if [ "$LEAN" = 1 ]; then SERIES="$SERIES lean"; fi
  for n in $SCALING; do
    NEXT=""
    for s in $SERIES; do
      case "$s" in
        floor)
          clear_mailboxes
          run_lg "$LOG" --mode floor --robots "$n" --seconds "$SCALING_SECONDS" --phase scaling --label "floor $n" ;;
        lean)
          clear_mailboxes
          run_lg "$LOG" --mode lean --robots "$n" --seconds "$SCALING_SECONDS" --phase scaling --label "lean $n" ;;
        p*)
          procs="${s#p}"
          start_servers "$procs"
          run_lg "$LOG" --mode server --robots "$n" --seconds "$SCALING_SECONDS" --phase scaling \
            --label "$procs proc $n robots" --server-pid "$(pids)" --server-procs "$procs" --workers "$WORKERS"
          stop_servers ;;
      esac
      # The floor is the reference: it runs as long as another series does.
      if [ "$s" = floor ] || ! over "$n robots ($s)"; then NEXT="$NEXT $s"; fi
    done
    SERIES="$NEXT"
    if [ "${SERIES// /}" = floor ]; then break; fi
  done
fi

if has_phase policy; then
  printf '\n######## 5. robot waiting policy (each: one fleet run of %s robots; then quiet runs by idle_ms)\n' "$ROBOTS"
  for p in $POLICIES; do
    IFS=, read -r first min max backoff <<<"${p#*:}"
    start_servers 1
    run_lg "$LOG" --mode server --robots "$ROBOTS" --seconds "$SECONDS_" --phase policy --label "${p%%:*} $ROBOTS" \
      --server-pid "$(pids)" --server-procs 1 --workers "$WORKERS" --wait-first-poll-ms "$first" --wait-min-ms "$min" \
      --wait-max-ms "$max" --wait-backoff "$backoff"
    stop_servers
  done
  for idle in $IDLES; do
    start_servers 1
    run_lg "$LOG" --mode server --workload quiet --robots "$ROBOTS" --seconds "$SECONDS_" --phase policy \
      --label "quiet idle $idle ms" --server-pid "$(pids)" --server-procs 1 --workers "$WORKERS" --wait-idle-ms "$idle"
    stop_servers
  done
fi

printf '\n######## summary (%s; all figures from this run, %d s)\n' "$RES" $(( $(date +%s) - T_START ))
for ph in floor server idle scaling policy; do
  if has_phase "$ph"; then "$BIN/fleetmap-loadgen" --mode report --results "$RES" --phase "$ph"; fi
done
