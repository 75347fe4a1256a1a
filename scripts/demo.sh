#!/usr/bin/env bash
# The main job, end to end on a private MariaDB: start it, import the real maps, start
# the map server and three simulated robots on the GDC1 building floor, give them goals,
# watch them live, abort one task on the way; then the semantic layer on the example room
# (objects, slices at two laser heights, Nav2 files, a goal by meaning); then the OSM
# campus imported through GDAL/OGR, its georeference, SVG and WGS 84 GeoJSON, and a robot
# driven on it; and end with a summary and a picture of the map with the robots' trajectories (out/demo-GDC1.svg). The database stays up for
# exploring afterwards:
#   scripts/db.sh sql        # administrator
#   scripts/db.sh stop
# Settings: FLEETMAP_HOME (instance folder), FLEETMAP_PORT (default 33306),
# DEMO_TIMEOUT (seconds to wait for the robots, default 150), FLEETMAP_MAPS_DIR (the real
# maps, default ../shared/maps beside the checkout).
set -euo pipefail
source "$(dirname "$0")/real-maps.sh"
require_real_maps demo GDC1.vectormap.txt UT_Campus.vectormap.txt \
  gis/osm-montgomery-college-rockville/campus.osm
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
BIN="$PWD/$BUILD/bin"
export FLEETMAP_HOME="${FLEETMAP_HOME:-$PWD/.fleetmap}"
TIMEOUT="${DEMO_TIMEOUT:-150}"
[ -x "$BIN/fleetmap" ] || { echo "demo: build first: scripts/setup.sh" >&2; exit 1; }
mkdir -p out
FM="$BIN/fleetmap"
PIDS=()
cleanup() {
  for p in "${PIDS[@]}"; do kill "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
}
trap cleanup EXIT

step() { printf '\n== %s\n' "$*"; }

step "private MariaDB ($FLEETMAP_HOME)"
bash scripts/db.sh start
CONF="$FLEETMAP_HOME/fleetmap.conf"

step "import the real maps (AMRL vector maps, $MAPS) and the example campus"
"$FM" map import "$MAPS/GDC1.vectormap.txt" --name GDC1 --replace
"$FM" map import "$MAPS/UT_Campus.vectormap.txt" --name UT_Campus --in-out 1 --semantic wall,building --replace
"$FM" map import maps/example-campus.map --name example-campus --replace
"$FM" map list

step "an inspector's query (plain SQL over TCP with the inspector account): walls crossing a 40 m square"
IPW="$(awk '/^\[inspector\]/{f=1;next} /^\[/{f=0} f&&$1=="password"{print $3}' "$CONF")"
PORT="$(awk '$1=="port"{print $3; exit}' "$CONF")"
SQL="SELECT map, COUNT(*) AS segments, ROUND(SUM(ST_Length(geom)), 1) AS metres FROM v_segments
     WHERE MBRIntersects(geom, ST_GeomFromText('POLYGON((-20 -20, 20 -20, 20 20, -20 20, -20 -20))'))
     GROUP BY map ORDER BY map;"
echo "$SQL"
MYSQL_PWD="$IPW" mariadb --no-defaults -h 127.0.0.1 -P "$PORT" -u fleetmap_inspector fleetmap --table -e "$SQL"

STARTED="$(date '+%F %T')"
step "the map server"
"$BIN/fleetmap-server" --config "$CONF" > out/demo-server.log 2>&1 &
PIDS+=($!)
sleep 0.5
"$BIN/fleetmap-server" --config "$CONF" --check

step "the operator's console (fleetmap-web: HTTP/WebSocket API and the live map page, docs/console.md)"
# Port FLEETMAP_WEB_PORT (default 8080), else any free one; the address is on its stdout.
WEB_PORT="${FLEETMAP_WEB_PORT:-8080}"
(exec 3<>"/dev/tcp/127.0.0.1/$WEB_PORT") 2>/dev/null && WEB_PORT=0  # taken: let it choose
"$BIN/fleetmap-web" --config "$CONF" --http-port "$WEB_PORT" > out/demo-web.out 2> out/demo-web.log &
PIDS+=($!)
WEB_URL=""
for _ in $(seq 1 100); do
  WEB_URL="$(sed -n 's|.*listening on \(https\{0,1\}://[^ ]*\).*|\1|p' out/demo-web.out | head -1)"
  [ -n "$WEB_URL" ] && break
  sleep 0.1
done
[ -n "$WEB_URL" ] || { echo "demo: fleetmap-web did not start, see out/demo-web.log" >&2; exit 1; }
echo "  console: $WEB_URL  (sign in as fleetmap_operator, or fleetmap_inspector to look only;"
echo "  the passwords are in $CONF)"
echo "  API: ${WEB_URL}api/openapi.json; log: out/demo-web.log"

step "three robots with their own database accounts, on GDC1"
mkdir -p "$FLEETMAP_HOME/robots"
# name, true start pose (x y theta), goal: all in the long corridor of the upper wing
ROBOTS=("r1 -24 8.6 0.0 28 8.8" "r2 30 8.8 3.14 -8 8.5" "r3 -5 8.5 0.0 20 8.7")
# A previous run's campus robot (below) would show in the live status as silent ("lost").
"$FM" robot remove c1 >/dev/null 2>&1 || true
for spec in "${ROBOTS[@]}"; do
  read -r name x y th gx gy <<<"$spec"
  "$FM" robot remove "$name" >/dev/null 2>&1 || true
  "$FM" robot add "$name" --map GDC1 --password-out "$FLEETMAP_HOME/robots/$name.pw" | head -n 1
  # The operator's initial pose: each robot starts tracking from it (GetPosIni).
  "$FM" pose-ini "$name" "$x" "$y" "$th" >/dev/null
  "$BIN/fleetmap-robot" --config "$CONF" --user "$name" --password-file "$FLEETMAP_HOME/robots/$name.pw" \
    --start "$x" "$y" "$th" --particles 3000 --tracking-particles 800 --speed 1.2 --seed "${#PIDS[@]}" \
    > "out/demo-$name.log" 2>&1 &
  PIDS+=($!)
done

step "localization (each robot on the map the server sent it, from its initial pose)"
for i in $(seq 1 60); do
  n="$( (grep -l -E "localized after|tracking from" out/demo-r*.log 2>/dev/null || true) | wc -l)"
  [ "$n" -ge 3 ] && break
  sleep 1
done
(grep -h -E "localized after|tracking from|failed" out/demo-r*.log || true) | sed 's/^/  /'

step "goals (the server pushes SetPosEnd; each robot acknowledges, asks for a path, drives)"
for spec in "${ROBOTS[@]}"; do
  read -r name x y th gx gy <<<"$spec"
  "$FM" goal "$name" "$gx" "$gy"
done

step "live status (every 3 s); r3's task is aborted on the way"
aborted=0
for i in $(seq 1 $((TIMEOUT / 3))); do
  sleep 3
  echo "--- $(date +%T)"
  "$FM" robots
  if [ "$aborted" = 0 ] && [ "$i" -ge 3 ]; then
    "$FM" abort r3 --reason "demo: corridor closed"
    aborted=1
  fi
  open="$(MYSQL_PWD="$IPW" mariadb --no-defaults -h 127.0.0.1 -P "$PORT" -u fleetmap_inspector fleetmap -N -e \
    "SELECT COUNT(*) FROM v_tasks WHERE robot IN ('r1','r2','r3') AND state IN ('assigned','acknowledged','active')")"
  [ "$open" = 0 ] && break
done

step "the same fleet through the HTTP API (curl, signed in as the operator; the CSRF token on every write)"
OPW="$(awk '/^\[operator\]/{f=1;next} /^\[/{f=0} f&&$1=="password"{print $3}' "$CONF")"
JAR="$(mktemp)"
CSRF="$(curl -fsS -c "$JAR" -H 'Content-Type: application/json' \
  -d "{\"user\":\"fleetmap_operator\",\"password\":\"$OPW\"}" "${WEB_URL}api/login" |
  python3 -c 'import json,sys; print(json.load(sys.stdin)["csrf"])')"
echo "-- GET /api/robots"
curl -fsS -b "$JAR" "${WEB_URL}api/robots" | python3 -c '
import json, sys
for r in json.load(sys.stdin):
    t = r.get("task") or {}
    print("  %-4s %-8s x=%s y=%s task=%s %s" % (r["name"], r["state"], r["x"], r["y"], t.get("id"), t.get("state")))'
echo "-- POST /api/robots/r1/goal {x: 500, y: 500} (outside GDC1): refused at once, no task"
curl -sS -b "$JAR" -H "X-CSRF-Token: $CSRF" -H 'Content-Type: application/json' -d '{"x":500,"y":500}' \
  -w '  HTTP %{http_code}\n' "${WEB_URL}api/robots/r1/goal" | sed 's/^/  /'
echo "-- the same write without the CSRF token"
curl -sS -b "$JAR" -H 'Content-Type: application/json' -d '{"x":1,"y":1}' -w '  HTTP %{http_code}\n' \
  "${WEB_URL}api/robots/r1/goal" | sed 's/^/  /'
rm -f "$JAR"

step "the semantic layer (example room): objects, nearest chairs, what two laser heights see, a goal by meaning"
"$FM" map import maps/example-room.map --name room --replace >/dev/null
"$FM" tags import maps/example-room.tags.json >/dev/null
"$FM" objects import room maps/example-room.geojson --replace
echo "-- the chairs nearest (7.5, 1.5), by distance to their footprints:"
"$FM" objects near room 7.5 1.5 --tag chair -k 2
echo "-- the map a laser sees at 0.381 m and at 0.794 m (chair legs vs backrests, boxes, table top...):"
for h in 0.381 0.794; do "$FM" map slice room --height "$h" -o "out/room-slice-$h.map"; done
"$FM" map nav2 room --laser-height 0.381 -o out/room-0.381 >/dev/null
echo "-- Nav2 map and keep-out mask for a 0.381 m laser: out/room-0.381.pgm/.yaml, out/room-0.381_keepout.pgm/.yaml"
echo "-- a goal by meaning: robot r4 (laser 0.381 m, radius 0.25 m, 0.6 m tall) at the door, to the charging station:"
"$FM" robot remove r4 >/dev/null 2>&1 || true
"$FM" robot add r4 --map room --laser-height 0.381 --radius 0.25 --height 0.6 --password-out "$FLEETMAP_HOME/robots/r4.pw" | head -n 1
"$FM" pose-ini r4 7.5 1.5 1.57 >/dev/null
"$FM" goal r4 --near charging_station
"$FM" tasks --robot r4 --limit 1

step "GIS in: the OSM campus (Montgomery College, Rockville) through GDAL/OGR, shown and driven on"
CAMPUS_OSM="$MAPS/gis/osm-montgomery-college-rockville/campus.osm"
# The per-layer report: what OGR read, what the built-in OSM rules kept and why the rest
# was skipped (footways and roads have no rule: they are where robots drive, not walls).
"$FM" map import "$CAMPUS_OSM" --name campus-osm --replace 2>&1 | grep -v -E '^(reading|importing):'
echo "-- its georeference (a local Transverse Mercator at the centre of the data):"
"$FM" map georef campus-osm
"$FM" map export campus-osm --format geojson -o out/demo-campus-osm.geojson
echo "-- out/demo-campus-osm.geojson: RFC 7946, WGS 84 lon/lat (opens in any GIS tool)"
if command -v ogrinfo >/dev/null; then
  echo "-- the same map read back from the database as GIS layers (<db>_gis, docs/gis-layers.md):"
  GISCONN="MYSQL:fleetmap_gis,host=127.0.0.1,port=$PORT,user=fleetmap_inspector,password=$IPW"
  ogrinfo -ro -so "$GISCONN" "campus-osm:segments" 2>/dev/null \
    | grep -E '^(Layer name|Geometry|Feature Count|Extent|FID Column)|METHOD\[|origin",' | sed 's/^/  /' || true
fi
# A robot on the campus: start on the open ground west of the south row of buildings,
# goal 61 m east-south-east along their south side (both checked free with `fleetmap plan`).
# It tracks from the operator's initial pose (GetPosIni) with few particles: an outdoor
# map is large and a tracking filter needs no global spread.
echo "-- robot c1 on campus-osm: from (-116, -36) to (-60, -60)"
"$FM" robot remove c1 >/dev/null 2>&1 || true
"$FM" robot add c1 --map campus-osm --password-out "$FLEETMAP_HOME/robots/c1.pw" | head -n 1
"$FM" pose-ini c1 -116 -36 -0.4 >/dev/null
CAMPUS_STARTED="$(date '+%F %T')"
"$BIN/fleetmap-robot" --config "$CONF" --user c1 --password-file "$FLEETMAP_HOME/robots/c1.pw" \
  --start -116 -36 -0.4 --tracking-particles 300 --speed 2.0 --seed 5 > out/demo-c1.log 2>&1 &
PIDS+=($!)
for i in $(seq 1 30); do
  grep -q -E "localized after|tracking from" out/demo-c1.log 2>/dev/null && break
  sleep 1
done
(grep -h -E "localized after|tracking from|failed" out/demo-c1.log || true) | sed 's/^/  /'
"$FM" goal c1 -60 -60
"$FM" robots | head -n 1 | sed 's/^/  time     /'
for i in $(seq 1 $((TIMEOUT / 3))); do
  sleep 3
  "$FM" robots | awk '$1 == "c1"' | sed "s/^/  $(date +%T) /"
  open="$(MYSQL_PWD="$IPW" mariadb --no-defaults -h 127.0.0.1 -P "$PORT" -u fleetmap_inspector fleetmap -N -e \
    "SELECT COUNT(*) FROM v_tasks WHERE robot = 'c1' AND state IN ('assigned','acknowledged','active')")"
  [ "$open" = 0 ] && break
done
"$FM" tasks --robot c1 --limit 1
(grep -h -E "arrived|bumped|failed" out/demo-c1.log || true) | sed 's/^/  /'
"$FM" trajectory c1 --since "$CAMPUS_STARTED" > out/demo-c1-trajectory.csv
awk -F, 'NR == 2 {t0 = $1} NR > 2 {d += sqrt(($2 - px) ^ 2 + ($3 - py) ^ 2)} NR > 1 {px = $2; py = $3; t1 = $1; n++}
  END {printf "  c1 drove %.1f m: %d poses reported from %s to %s (out/demo-c1-trajectory.csv)\n", d, n, t0, t1}' \
  out/demo-c1-trajectory.csv
"$FM" map export campus-osm --format svg --trajectories --since "$CAMPUS_STARTED" -o out/demo-campus-osm.svg

step "summary"
"$FM" tasks --limit 4
"$FM" map export GDC1 --format svg --trajectories --since "$STARTED" -o out/demo-GDC1.svg
for r in r1 r2 r3; do
  echo "  $r: $("$FM" trajectory "$r" --since "$STARTED" | tail -n +2 | wc -l) poses reported; log out/demo-$r.log"
done
echo "  picture: out/demo-GDC1.svg (map with the three trajectories); server log: out/demo-server.log"
echo "  OSM campus: out/demo-campus-osm.svg (with c1's trajectory), out/demo-campus-osm.geojson (WGS 84);"
echo "  the database as GIS layers for QGIS, ogrinfo, ogr2ogr (docs/gis-layers.md), e.g."
echo "    ogrinfo -ro -so \"MYSQL:fleetmap_gis,host=127.0.0.1,port=$PORT,user=fleetmap_inspector,password=...\" campus-osm:segments"
for m in UT_Campus example-campus; do "$FM" map export "$m" --format svg -o "out/$m.svg"; done

echo "  console: $WEB_URL (fleetmap_operator; passwords in $CONF)"
if [ -t 0 ] && [ "${CI:-}" != true ]; then
  step "the console stays up at $WEB_URL with the server and robot c1's map; press Enter to stop"
  read -r _ || true
fi

step "done: robots, server and console stopped, the database is still running (scripts/db.sh stop to stop it)"
