#!/usr/bin/env bash
# Server load benchmark on its own private MariaDB (<build>/benchsrv, port 33318):
# fleetmap-loadgen plays N robots (own account and connection each, plain SQL), first
# against a minimal answering loop (the floor: the bare database path), then against the
# real fleetmap-server, in the same run; then the servers' idle polling cost, then scaling.
# Beside the server, "lean" rows: a batched prototype inside fleetmap-loadgen that does the
# server's durable work in a few round trips per batch (what the proposals would reach).
#
#   scripts/bench-server.sh [options]
#     --robots N          fleet size of phases 1-2, trips and soak (default 200); also the
#                         largest fleet of phase 4 when --scaling is not given (steps of 200)
#     --seconds S         measurement window of phases 1-2 (default 20)
#     --scaling "LIST"    robot counts of phase 4 (default "200 400 600 800 1000")
#     --scaling-seconds S window of each phase-4 run (default 30)
#     --procs "LIST"      server processes in phase 4 (default "1")
#     --idle-seconds S    no-traffic window of phase 3 (default 10)
#     --polls "LIST"      --poll-max-ms values of phase 3 (default "1 10 50")
#     --threads T         loadgen client threads (default 8)
#     --phases "LIST"     any of floor server idle scaling policy trips soak (default the first four)
#     --trips-seconds S   phase trips: the general log's window on a fleet of --robots (default 10)
#     --before-bin PATH   phase trips: also count the round trips of this fleetmap-server binary
#                         (an older build, for before/after)
#     --soak MINUTES      phase soak only: --robots robots for MINUTES against one server, the
#                         RSS of fleetmap-server and mariadbd sampled every 10 s, slopes in MiB/min
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
# FLEETMAP_MAPS_DIR (the real maps, default ../shared/maps beside the checkout),
# FLEETMAP_MYSQLD_ARGS (extra mariadbd options, e.g. "--thread-handling=pool-of-threads";
# the instance is started for the run and stopped after it, so they apply to this run).
# Results: <build>/benchsrv/results-<time>.jsonl (one JSON line per run), tables at the end.
# Robot accounts lg0001... are created once with `fleetmap robot add` and reused.
set -euo pipefail
source "$(dirname "$0")/real-maps.sh"
require_real_maps bench-server UT_Campus.vectormap.txt
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
BIN="$BUILD/bin"

ROBOTS=200 SECONDS_=20 SCALING="" SCALING_SECONDS=30 PROCS="1" IDLE_SECONDS=10 TRIPS_SECONDS=10 BEFORE_BIN=""
SOAK_MIN=0 ROBOTS_GIVEN=0
POLLS="1 10 50" THREADS=8 PHASES="floor server idle scaling" SERVER_FLAGS="" BUILD_FIRST=1 LEAN=1
POLICIES="fixed1:0,1,1,0 fixed2:0,2,2,0 fixed5:0,5,5,0 loadgen-before:0,1,100000,0.1 backoff1:1,1,50,0.1 backoff2:2,2,50,0.25" IDLES="0 100 250 1000"
while [ $# -gt 0 ]; do
  case "$1" in
    --robots) ROBOTS="$2"; ROBOTS_GIVEN=1; shift 2 ;;
    --trips-seconds) TRIPS_SECONDS="$2"; shift 2 ;;
    --before-bin) BEFORE_BIN="$2"; shift 2 ;;
    --soak) SOAK_MIN="$2"; PHASES="soak"; shift 2 ;;
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
    -h|--help) sed -n '2,39p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench-server: unknown option '$1' (--help)" >&2; exit 64 ;;
  esac
done
has_phase() { case " $PHASES " in *" $1 "*) return 0 ;; *) return 1 ;; esac; }
for v in "$ROBOTS" "$SOAK_MIN" "$TRIPS_SECONDS"; do
  [[ "$v" =~ ^[0-9]+$ ]] || { echo "bench-server: expected a whole number, got '$v'" >&2; exit 64; }
done
if [ -z "$SCALING" ]; then
  if [ "$ROBOTS_GIVEN" = 1 ] && [ "$ROBOTS" -gt 200 ]; then SCALING="$(seq -s ' ' 200 200 "$ROBOTS")"
  else SCALING="200 400 600 800 1000"; fi
fi
if [ -n "$BEFORE_BIN" ] && [ ! -x "$BEFORE_BIN" ]; then echo "bench-server: --before-bin $BEFORE_BIN is not an executable" >&2; exit 64; fi

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
     "innodb_flush_log_at_trx_commit $(sql "SELECT @@innodb_flush_log_at_trx_commit")," \
     "thread_handling $(sql "SELECT @@thread_handling"), buffer pool $(( $(sql "SELECT @@innodb_buffer_pool_size") >> 20 )) MiB," \
     "redo log $(( $(sql "SELECT @@innodb_log_file_size") >> 20 )) MiB, sync_binlog $(sql "SELECT @@sync_binlog")," \
     "log_bin $(sql "SELECT @@log_bin"); FLEETMAP_MYSQLD_ARGS '${FLEETMAP_MYSQLD_ARGS:-}'; load average $(cut -d' ' -f1-3 /proc/loadavg)"

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

SERVER_BIN="$BIN/fleetmap-server"
start_servers() {  # PROCS [flags...]
  local n="$1" i; shift
  clear_mailboxes
  for i in $(seq 1 "$n"); do
    # shellcheck disable=SC2086
    "$SERVER_BIN" --log-level warn $SERVER_FLAGS "$@" >>"$FLEETMAP_HOME/server-$i.log" 2>&1 &
    SERVER_PIDS+=($!)
  done
  sleep 1
  for i in "${SERVER_PIDS[@]}"; do kill -0 "$i" || { echo "bench-server: fleetmap-server exited, see $FLEETMAP_HOME/server-*.log" >&2; exit 1; }; done
}
pids() { local IFS=,; echo "${SERVER_PIDS[*]}"; }
worst_p99() { awk '/answered \(GetMap\+SendGPS\)/ { print $(NF-1) }' "$1"; }
stored_share() { awk '/SendPos stored within 100 ms:/ { print $6 }' "$1"; }
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
  # The goal (answered p99 <= 20 ms, every SendPos within 100 ms) is judged in the report;
  # a series goes on past a miss, to show where the limit is and what saturates, and stops
  # when it falls behind: answered p99 over 1 s, or under 90 % of SendPos within 100 ms.
  over() {
    local p99 pos; p99="$(worst_p99 "$LOG")"; pos="$(stored_share "$LOG")"
    if [ -z "$p99" ] || [ -z "$pos" ] || awk -v p="$p99" -v s="$pos" 'BEGIN { exit !(p > 1000 || s < 90) }'; then
      echo "bench-server: p99 ${p99:-?} ms, SendPos within 100 ms ${pos:-?} % at $1: fallen behind; this series stops here"
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

if has_phase trips; then
  # Round trips are what the general log records: one row per statement text a client sent
  # (a multi-statement is one row). Counted on a fleet in steady state, the monitor off; the
  # stall guard's own query (the server account too) left out.
  printf '\n######## 6. round trips of the server (%s robots, general log for %s s)\n' "$ROBOTS" "$TRIPS_SECONDS"
  TRIPS_OUT="$FLEETMAP_HOME/trips-$(date +%Y%m%d-%H%M%S).txt"
  : > "$TRIPS_OUT"
  for bin in "$BIN/fleetmap-server" ${BEFORE_BIN:+"$BEFORE_BIN"}; do
    SERVER_BIN="$bin"
    start_servers 1
    "${LG[@]}" --mode server --robots "$ROBOTS" --seconds $(( TRIPS_SECONDS + 6 )) --phase trips --label "trips $bin" \
      --monitor-ms 0 --server-pid "$(pids)" --server-procs 1 --workers "$WORKERS" > "$LOG" 2>&1 &
    LGP=$!
    for _ in $(seq 1 600); do grep -q "robots set up" "$LOG" && break; sleep 0.5; done
    sleep 6  # warm-up (3 s) and a little more
    sql "SET GLOBAL log_output = 'TABLE'; TRUNCATE TABLE mysql.general_log; SET GLOBAL general_log = 1"
    sleep "$TRIPS_SECONDS"
    sql "SET GLOBAL general_log = 0"
    wait "$LGP" || echo "bench-server: fleetmap-loadgen (trips) failed, see $LOG" >&2
    stop_servers
    # Statements in a row: its ';\n' separators + 1 (write_batch.h, request_loop.cpp join with them).
    sql "SELECT SUM(srv), SUM(srv AND argument LIKE 'SELECT db_user FROM rr%'),
                SUM(srv AND argument LIKE '%START TRANSACTION%'),
                SUM(IF(srv, (LENGTH(argument) - LENGTH(REPLACE(argument, CONCAT(';', CHAR(10)), ''))) / 2 + 1, 0)),
                SUM(NOT srv AND argument LIKE 'INSERT INTO rr%')
         FROM (SELECT argument, user_host LIKE 'fleetmap\\_server%' AS srv FROM mysql.general_log
               WHERE command_type = 'Query' AND argument NOT LIKE 'SELECT DISTINCT b.trx_mysql_thread_id%'
                 AND argument NOT LIKE 'SET GLOBAL general_log%') g" |
      awk -v bin="$bin" -v sec="$TRIPS_SECONDS" '{
        printf "%s: %d requests in %d s; server: %d round trips (%d queue heads, %d transactions), %d statements;", bin, $5, sec, $1, $2, $3, $4
        printf " round trips per transaction %.2f, per request %.3f; statements per request %.3f\n", ($1 - ($2 - $3)) / ($3 ? $3 : 1), $1 / ($5 ? $5 : 1), $4 / ($5 ? $5 : 1) }' |
      tee -a "$TRIPS_OUT"
    sql "TRUNCATE TABLE mysql.general_log"
  done
  SERVER_BIN="$BIN/fleetmap-server"
  echo "(round trips per transaction: those not an empty queue head; $TRIPS_OUT)"
fi

if has_phase soak; then
  [ "$SOAK_MIN" -gt 0 ] || SOAK_MIN=10
  printf '\n######## 7. soak: %s robots for %s min, RSS every 10 s\n' "$ROBOTS" "$SOAK_MIN"
  start_servers 1
  SOAK_OUT="$FLEETMAP_HOME/soak-$(date +%Y%m%d-%H%M%S).tsv"
  rss_kib() { awk '/^VmRSS:/ { print $2 }' "/proc/$1/status" 2>/dev/null || echo 0; }
  # The pages InnoDB holds in its pool: the fleet appends trajectory rows and GPS fixes
  # all the time and the pool caches them as they are written, up to its size. RSS
  # beyond them is what a leak would grow.
  pool_kib() { echo $(( $(sql "SHOW GLOBAL STATUS LIKE 'Innodb_buffer_pool_bytes_data'" | awk '{ print $2 }') / 1024 )); }
  ( t0=$(date +%s)
    echo "# s	server_kib	mariadbd_kib	load1	pool_data_kib"
    while :; do
      printf '%s\t%s\t%s\t%s\t%s\n' $(( $(date +%s) - t0 )) "$(rss_kib "${SERVER_PIDS[0]}")" "$(rss_kib "$DB_PID")" \
        "$(cut -d' ' -f1 /proc/loadavg)" "$(pool_kib)"
      sleep 10
    done ) > "$SOAK_OUT" &
  SAMPLER=$!
  run_lg "$LOG" --mode server --robots "$ROBOTS" --seconds $(( SOAK_MIN * 60 )) --phase soak --label "soak $ROBOTS" \
    --server-pid "$(pids)" --server-procs 1 --workers "$WORKERS"
  kill "$SAMPLER"; wait "$SAMPLER" 2>/dev/null || true
  stop_servers
  # Least-squares slopes, MiB/min, over the whole run and without its first 2 minutes
  # (connections, caches and the buffer pool's first pages come in then): the server's
  # RSS, mariadbd's, the pool's data pages, and mariadbd's RSS less those pages.
  for from in 0 120; do
    awk -v from="$from" -F'\t' '!/^#/ && $1 >= from { n++; x = $1 / 60; sx += x; sxx += x * x
        v[2] = $2; v[3] = $3; v[5] = $5; v[6] = $3 - $5
        for (k = 2; k <= 6; k++) { if (k == 4) continue; y = v[k] / 1024; sy[k] += y; sxy[k] += x * y
          if (!(k in first)) first[k] = y; last[k] = y } }
      function slope(k) { return (n * sxy[k] - sx * sy[k]) / d }
      END { d = n * sxx - sx * sx; if (n < 3 || d == 0) { print "soak: too few samples from " from " s"; exit }
        printf "soak from %d s (%d samples): fleetmap-server %.1f -> %.1f MiB, slope %.3f MiB/min; mariadbd %.1f -> %.1f MiB, slope %.3f MiB/min\n",
          from, n, first[2], last[2], slope(2), first[3], last[3], slope(3)
        printf "  mariadbd: buffer pool data pages %.1f -> %.1f MiB, slope %.3f MiB/min; RSS less those pages %.1f -> %.1f MiB, slope %.3f MiB/min\n",
          first[5], last[5], slope(5), first[6], last[6], slope(6) }' "$SOAK_OUT"
  done
  echo "(samples: $SOAK_OUT)"
fi

printf '\n######## summary (%s; all figures from this run, %d s)\n' "$RES" $(( $(date +%s) - T_START ))
for ph in floor server idle scaling policy; do
  if has_phase "$ph"; then "$BIN/fleetmap-loadgen" --mode report --results "$RES" --phase "$ph"; fi
done
