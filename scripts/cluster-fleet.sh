# shellcheck shell=bash
# Sourced by the cluster drivers (scripts/chaos-cluster.sh, scripts/bench-cluster.sh): the
# servers, the robot fleet (galera_robot_fleet) and its figures, shared so that both drive
# the same workload the same way. The caller sets ROOT, BIN, CL (scripts/cluster.sh), W
# (the run's folder) and, once the schema exists, DB (the database name).

declare -A SRV=()  # server name -> pid
FLEET=""           # pid of a fleet run in the background

step() { echo "--- $(date +%T) $*"; }
conf() { bash "$CL" conf "$1"; }

need_bins() {  # need_bins DRIVER PROGRAM...: each must be built
  local who="$1" b; shift
  for b in "$@"; do
    [ -x "$BIN/$b" ] || { echo "$who: $BIN/$b is missing (cmake --build build --target $b)" >&2; exit 1; }
  done
}

cluster_env() {  # cluster_env HOME: the cluster under HOME unless FLEETMAP_CLUSTER_HOME says where
  # Small buffers so that three nodes start fast; none of the caller's connection settings.
  export FLEETMAP_CLUSTER_HOME="${FLEETMAP_CLUSTER_HOME:-$1}"
  export FLEETMAP_CLUSTER_PORT="${FLEETMAP_CLUSTER_PORT:-33406}"
  export FLEETMAP_CLUSTER_MYSQLD_ARGS="${FLEETMAP_CLUSTER_MYSQLD_ARGS:---innodb-buffer-pool-size=64M --innodb-log-file-size=32M}"
  unset FLEETMAP_CONFIG FLEETMAP_HOST FLEETMAP_PORT FLEETMAP_SOCKET FLEETMAP_DB FLEETMAP_USER FLEETMAP_PASSWORD FLEETMAP_HOSTS
  P="$FLEETMAP_CLUSTER_PORT"
}

positive_int() {  # positive_int DRIVER OPTION VALUE
  [[ "$3" =~ ^[1-9][0-9]*$ ]] || { echo "$1: $2 expects a positive whole number, got '$3'" >&2; exit 64; }
}

# A server on the database of fleetmap.conf CONF, claiming share PARTITION (I/N).
server_start() {  # server_start NAME CONF PARTITION
  FLEETMAP_CONFIG="$2" "$BIN/fleetmap-server" --log-level warn --partition "$3" --poll-max-ms 5 \
    >> "$W/server-$1.log" 2>&1 &
  SRV[$1]=$!
}
server_stop() { local p="${SRV[$1]:-}"; [ -n "$p" ] && { kill "$p" 2>/dev/null || true; wait "$p" 2>/dev/null || true; }; SRV[$1]=""; }
server_kill() { local p="${SRV[$1]:-}"; [ -n "$p" ] && { kill -9 "$p" 2>/dev/null || true; wait "$p" 2>/dev/null || true; }; SRV[$1]=""; }
servers_stop() { local s; for s in "${!SRV[@]}"; do server_stop "$s"; done; }
fleet_stop() { [ -n "$FLEET" ] && { kill "$FLEET" 2>/dev/null || true; wait "$FLEET" 2>/dev/null || true; }; FLEET=""; }

# Server retries of certification conflicts: the server logs each rolled-back claim.
conflicts() { cat "$@" 2>/dev/null | grep -c "error 1213" || true; }

# The map and COUNT robot accounts on the database of CONF, written to $W/accounts. The
# passwords are made once, so another database (the floor's) gets the same robots.
add_robots() {  # add_robots CONF COUNT
  local cf="$1" count="$2" i
  FLEETMAP_CONFIG="$cf" "$BIN/fleetmap" map import "$ROOT/maps/example-room.map" --name chaos_room >/dev/null
  : > "$W/accounts"
  for i in $(seq 1 "$count"); do
    [ -f "$W/r$i.pw" ] || (umask 077; echo "chaos-$i-$$-$RANDOM" > "$W/r$i.pw")
    FLEETMAP_CONFIG="$cf" "$BIN/fleetmap" robot add "chaos_r$i" --map chaos_room --password-file "$W/r$i.pw" >/dev/null
    echo "chaos_r$i $(cat "$W/r$i.pw")" >> "$W/accounts"
  done
}

# One phase of the fleet (tests/galera/robot_fleet.cpp): every robot sends bursts of 3
# numbered requests and waits for their answers. Its figures go to $W/NAME.out, its log to
# $W/NAME.err (FLEET_LOG_LEVEL, default warn; debug adds one line per 1213 a robot retried).
fleet() {  # fleet NAME HOSTS SECONDS [STOPFILE PAUSE_MS]
  "$BIN/galera_robot_fleet" --accounts "$W/accounts" --hosts "$2" --database "$DB" --seconds "$3" \
    ${4:+--stop-file "$4"} ${5:+--pause-ms "$5"} \
    --answer-timeout 40 --log-level "${FLEET_LOG_LEVEL:-warn}" > "$W/$1.out" 2> "$W/$1.err"
}
# What a stalled phase was waiting on: every 2 s, each node's statements running 5 s or
# more (with their state) and Galera's flow-control pause, into $W/stalls.log. A fleet
# that stops for tens of seconds leaves its cause there (docs/galera.md, "A robot's lock
# wait"); the drivers print its first lines when a phase fails.
STALLS=""
stall_watch_start() {
  ( while :; do
      local n rows
      for n in 1 2 3; do
        rows="$(bash "$CL" sql "$n" -N -e "SELECT ID, USER, TIME, STATE, LEFT(REPLACE(INFO, '\n', ' '), 120)
                FROM information_schema.PROCESSLIST WHERE COMMAND <> 'Sleep' AND TIME >= 5" 2>/dev/null)" || continue
        [ -n "$rows" ] && printf '%s node %s\n%s\n%s\n' "$(date +%T)" "$n" "$rows" \
          "$(bash "$CL" sql "$n" -N -e "SHOW GLOBAL STATUS LIKE 'wsrep_flow_control_paused'" 2>/dev/null)" >> "$W/stalls.log"
      done
      sleep 2
    done ) &
  STALLS=$!
}
stall_watch_stop() { [ -n "$STALLS" ] && { kill "$STALLS" 2>/dev/null || true; wait "$STALLS" 2>/dev/null || true; }; STALLS=""; }
stalls_seen() { [ -s "$W/stalls.log" ] && { echo "statements that ran 5 s or more ($W/stalls.log):"; head -40 "$W/stalls.log"; } || true; }

field() { awk -v k="$2" '{for (i = 1; i < NF; i += 2) if ($i == k) print $(i + 1)}' "$W/$1.out"; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "-" }'; }
