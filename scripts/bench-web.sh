#!/usr/bin/env bash
# The operator's view of a moving fleet, on its own private MariaDB (<build>/benchweb,
# port 33319): N robots (own account each, plain SQL) send SendPos at 3 Hz to the real
# fleetmap-server; P viewers watch them, first as WebSocket pages of the real fleetmap-web,
# then as P `fleetmap robots --json --watch 0.1` processes (the CLI polling the same
# view), in the same run. bench-web-push prints push latency (robot's commit -> viewer),
# the share of poses seen, and the CPU of the viewers' side, the server and mariadbd.
#
#   scripts/bench-web.sh [--robots N] [--pages P] [--seconds S] [--no-build]
# Environment: FLEETMAP_BUILD_DIR (default build), FLEETMAP_BENCH_PORT (default 33319).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
BIN="$BUILD/bin"
ROBOTS=200 PAGES=5 SECONDS_=20 BUILD_FIRST=1
while [ $# -gt 0 ]; do
  case "$1" in
    --robots) ROBOTS="$2"; shift 2 ;;
    --pages) PAGES="$2"; shift 2 ;;
    --seconds) SECONDS_="$2"; shift 2 ;;
    --no-build) BUILD_FIRST=0; shift ;;
    -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench-web: unknown option '$1' (--help)" >&2; exit 64 ;;
  esac
done
if [ "$BUILD_FIRST" = 1 ]; then
  cmake --build "$BUILD" -j2 --target fleetmap fleetmap-server fleetmap-web bench-web-push >/dev/null
fi

export FLEETMAP_HOME="$PWD/$BUILD/benchweb" FLEETMAP_PORT="${FLEETMAP_BENCH_PORT:-33319}"
unset FLEETMAP_CONFIG FLEETMAP_HOST FLEETMAP_SOCKET FLEETMAP_DB FLEETMAP_USER FLEETMAP_PASSWORD
CONF="$FLEETMAP_HOME/fleetmap.conf"
PIDS=()
cleanup() {
  local p
  for p in "${PIDS[@]}"; do kill -TERM "$p" 2>/dev/null || true; done
  for p in "${PIDS[@]}"; do wait "$p" 2>/dev/null || true; done
  bash scripts/db.sh stop >/dev/null || true
}
trap cleanup EXIT
bash scripts/db.sh start
DB_PID="$(cat "$FLEETMAP_HOME/mysqld.pid")"
# One connection per robot, the viewers and the server: more than the default 151.
bash scripts/db.sh sql -e "SET GLOBAL max_connections = $(( ROBOTS + 100 ))"

"$BIN/fleetmap" map list | grep -qw webbench ||
  "$BIN/fleetmap" map import maps/example-campus.map --name webbench >/dev/null

# Robot accounts wp0001..: created once, reused later (scripts/robot-accounts.sh).
PWDIR="$FLEETMAP_HOME/robots"
source scripts/robot-accounts.sh
ensure_robot_accounts "$BIN/fleetmap" wp "$ROBOTS" webbench "$PWDIR" bench-web
bash scripts/db.sh sql -e "DELETE FROM rr; DELETE FROM sa WHERE sentinel = 0"

"$BIN/fleetmap-server" --log-level warn >>"$FLEETMAP_HOME/server.log" 2>&1 &
SERVER_PID=$!; PIDS+=("$SERVER_PID")
"$BIN/fleetmap-web" --http-port 0 --log-level warn >"$FLEETMAP_HOME/web.out" 2>>"$FLEETMAP_HOME/web.log" &
WEB_PID=$!; PIDS+=("$WEB_PID")
URL=""
for _ in $(seq 1 100); do
  URL="$(sed -n 's|.*listening on http://\([^/]*\)/.*|\1|p' "$FLEETMAP_HOME/web.out" | head -1)"
  [ -n "$URL" ] && break
  kill -0 "$WEB_PID" 2>/dev/null || { echo "bench-web: fleetmap-web exited, see $FLEETMAP_HOME/web.log" >&2; exit 1; }
  sleep 0.1
done
[ -n "$URL" ] || { echo "bench-web: fleetmap-web printed no address" >&2; exit 1; }
echo "bench-web: fleetmap-server pid $SERVER_PID, fleetmap-web on $URL (pid $WEB_PID), mariadbd pid $DB_PID"

"$BIN/bench-web-push" --config "$CONF" --password-dir "$PWDIR" --web "$URL" --fleetmap "$BIN/fleetmap" \
  --robots "$ROBOTS" --pages "$PAGES" --seconds "$SECONDS_" \
  --web-pid "$WEB_PID" --server-pid "$SERVER_PID" --db-pid "$DB_PID"
