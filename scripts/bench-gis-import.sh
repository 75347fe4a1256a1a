#!/usr/bin/env bash
# GIS import benchmark, no database: `fleetmap map check` reads the Liechtenstein OSM PBF
# through OGR and builds the map (rules, transform, validation), beside ogr2ogr's own
# time to read and write the same file (to a GeoPackage), measured in the same run
# (SPEC 8). Prints features/s for both. Argument: another OGR source (default the PBF).
set -euo pipefail
source "$(dirname "$0")/real-maps.sh"
require_real_maps bench-gis-import gis/osm-liechtenstein-2013/liechtenstein-2013-08-03.osm.pbf
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
cmake --build "$BUILD" -j2 --target fleetmap >/dev/null
SRC="${1:-$MAPS/gis/osm-liechtenstein-2013/liechtenstein-2013-08-03.osm.pbf}"
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT

now() { date +%s.%N; }
t0=$(now)
"$BUILD/bin/fleetmap" map check "$SRC" --no-clip >"$OUT/report.txt"
t1=$(now)
ogr2ogr -q -f GPKG "$OUT/copy.gpkg" "$SRC"
t2=$(now)

features=$(awk '/^layer /{ n += $3 } END { print n }' "$OUT/report.txt")
grep -E '^(layer|total|extent)' "$OUT/report.txt"
awk -v f="$features" -v a="$t0" -v b="$t1" -v c="$t2" 'BEGIN {
  printf "fleetmap map check: %d features in %.2f s (%.0f features/s)\n", f, b - a, f / (b - a)
  printf "ogr2ogr -f GPKG:    %d features in %.2f s (%.0f features/s)  baseline, same run\n", f, c - b, f / (c - b)
}'
