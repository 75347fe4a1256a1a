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

# Robot accounts wp0001..: created once with `fleetmap robot add`, reused later.
PWDIR="$FLEETMAP_HOME/robots"
mkdir -p "$PWDIR"; chmod 700 "$PWDIR"
declare -A EXISTS=()
for name in $("$BIN/fleetmap" robot list | awk 'NR > 1 { print $2 }'); do EXISTS[$name]=1; done
MISSING=()
for i in $(seq 1 "$ROBOTS"); do
  printf -v name 'wp%04d' "$i"
  if [ -n "${EXISTS[$name]:-}" ]; then
    [ -s "$PWDIR/$name.pw" ] && continue
    "$BIN/fleetmap" robot remove "$name" >/dev/null
  fi
  (umask 077; head -c 18 /dev/urandom | base64 | tr -d '/+=' > "$PWDIR/$name.pw")
  MISSING+=("$name")
done
if [ ${#MISSING[@]} -gt 0 ]; then
  echo "bench-web: creating ${#MISSING[@]} robot accounts (once; reused later) ..."
  printf '%s\n' "${MISSING[@]}" | xargs -P 4 -I{} "$BIN/fleetmap" robot add {} --map webbench \
    --password-file "$PWDIR/{}.pw" >/dev/null
fi
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
