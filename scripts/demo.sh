#!/usr/bin/env bash
# The main job, end to end on a private MariaDB: start it, import the real maps and
# the example map, show what is stored (counts, a window, an inspector's SQL query),
# and draw the maps as SVG pictures in out/. The instance stays up for exploring:
#   scripts/db.sh sql        # administrator
#   scripts/db.sh stop
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
BIN="$BUILD/bin"
export FLEETMAP_HOME="${FLEETMAP_HOME:-$PWD/.fleetmap}"
[ -x "$BIN/fleetmap" ] || { echo "demo: build first: scripts/setup.sh" >&2; exit 1; }
mkdir -p out

step() { printf '\n== %s\n' "$*"; }

step "private MariaDB ($FLEETMAP_HOME)"
bash scripts/db.sh start

step "import the real maps (AMRL vector maps) and the example campus"
"$BIN/fleetmap" map import maps/amrl/GDC1.vectormap.txt --name GDC1 --replace
"$BIN/fleetmap" map import maps/amrl/UT_Campus.vectormap.txt --name UT_Campus --in-out 1 --semantic wall,building --replace
"$BIN/fleetmap" map import maps/example-campus.map --name example-campus --replace

step "stored maps"
"$BIN/fleetmap" map list

step "the example campus, by shape type"
"$BIN/fleetmap" map check maps/example-campus.map

step "a 10 m x 8 m window of the example campus around (20, 30), as a robot gets it with GetMap"
"$BIN/fleetmap" window example-campus 20 30 10 8 | head -n 24
echo "..."

step "an inspector's query (plain SQL over TCP with the inspector account): walls crossing a 40 m square of the campus"
CONF="$FLEETMAP_HOME/fleetmap.conf"
IPW="$(awk '/^\[inspector\]/{f=1;next} /^\[/{f=0} f&&$1=="password"{print $3}' "$CONF")"
PORT="$(awk '$1=="port"{print $3; exit}' "$CONF")"
SQL="SELECT map, COUNT(*) AS segments, ROUND(SUM(ST_Length(geom)), 1) AS metres
     FROM v_segments
     WHERE MBRIntersects(geom, ST_GeomFromText('POLYGON((-20 -20, 20 -20, 20 20, -20 20, -20 -20))'))
     GROUP BY map ORDER BY map;"
echo "$SQL"
MYSQL_PWD="$IPW" mariadb --no-defaults -h 127.0.0.1 -P "$PORT" -u fleetmap_inspector fleetmap --table -e "$SQL"

step "pictures"
for m in GDC1 UT_Campus example-campus; do
  "$BIN/fleetmap" map export "$m" --format svg -o "out/$m.svg"
  "$BIN/fleetmap" map export "$m" --format geojson -o "out/$m.geojson"
  echo "out/$m.svg  out/$m.geojson"
done

step "done: the database is still running (scripts/db.sh stop to stop it)"
