#!/usr/bin/env bash
# GIS import benchmark, no database: `fleetmap map check` reads a source through OGR and
# builds the map (rules, transform, validation), beside ogr2ogr's own time to read and
# write the same file (to a GeoPackage), measured in the same run (SPEC 8). Prints
# features/s for both and their ratio.
#
# Sources: the Liechtenstein OSM PBF (built-in OSM rules); the same data as a GeoPackage
# (one tile); and a tiling of it to >= 100 000 features (issue "GIS in and out",
# benchmark): TILES copies (default 12, 102 336 features) shifted by whole tile offsets
# in a grid, written by ogr2ogr with an affine coordinate operation, so the reader and
# the rules stay those of the one-tile GeoPackage and only the size changes.
# Generated files go to a temporary folder, never into the repository.
#
#   scripts/bench-gis-import.sh            the three sources above
#   scripts/bench-gis-import.sh SOURCE     one other OGR source instead
set -euo pipefail
source "$(dirname "$0")/real-maps.sh"
require_real_maps bench-gis-import gis/osm-liechtenstein-2013/liechtenstein-2013-08-03.osm.pbf
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
cmake --build "$BUILD" -j2 --target fleetmap >/dev/null
PBF="$MAPS/gis/osm-liechtenstein-2013/liechtenstein-2013-08-03.osm.pbf"
TILES="${TILES:-12}"
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT

now() { date +%s.%N; }

# One source: map check (its progress on stderr, as an operator sees it), then ogr2ogr.
bench() {
  local label="$1" src="$2" t0 t1 t2 features
  echo "== $label: $src"
  rm -f "$OUT/copy.gpkg"
  t0=$(now)
  "$BUILD/bin/fleetmap" map check "$src" --no-clip >"$OUT/report.txt"
  t1=$(now)
  ogr2ogr -q -f GPKG "$OUT/copy.gpkg" "$src"
  t2=$(now)
  features=$(awk '/^layer /{ n += $3 } END { print n }' "$OUT/report.txt")
  grep -E '^(layer|total|extent)' "$OUT/report.txt"
  awk -v f="$features" -v a="$t0" -v b="$t1" -v c="$t2" 'BEGIN {
    printf "fleetmap map check: %d features in %.2f s (%.0f features/s)\n", f, b - a, f / (b - a)
    printf "ogr2ogr -f GPKG:    %d features in %.2f s (%.0f features/s)  baseline, same run\n", f, c - b, f / (c - b)
    printf "ratio: map check takes %.2f x ogr2ogr'"'"'s time\n", (b - a) / (c - b)
  }'
}

if [ $# -gt 0 ]; then
  bench "source" "$1"
  exit 0
fi

# The tiling: tile (i, j) shifted by i whole extents east and j north. The PBF spans
# 0.166 deg of longitude and 0.224 deg of latitude; the offsets leave a gap between tiles.
# The coordinate operation works in EPSG:4326's own axis order (lat, lon): xoff is the
# latitude offset, yoff the longitude one.
ogr2ogr -q -f GPKG "$OUT/tile.gpkg" "$PBF"
cp "$OUT/tile.gpkg" "$OUT/tiled.gpkg"
cols=$(awk -v n="$TILES" 'BEGIN { c = int(sqrt(n)); if (c * c < n) c++; print c }')
for ((k = 1; k < TILES; k++)); do
  i=$((k % cols)); j=$((k / cols))
  ogr2ogr -q -append "$OUT/tiled.gpkg" "$OUT/tile.gpkg" -s_srs EPSG:4326 -t_srs EPSG:4326 \
    -ct "+proj=affine +xoff=$(awk -v j=$j 'BEGIN { print 0.23 * j }') +yoff=$(awk -v i=$i 'BEGIN { print 0.17 * i }')"
  printf '\rtiling: %d/%d' $((k + 1)) "$TILES" >&2
done
echo >&2
echo "machine: $(nproc) cores, $(awk -F': ' '/model name/{ print $2; exit }' /proc/cpuinfo); $(ogr2ogr --version)"

bench "Liechtenstein OSM PBF (OSM rules)" "$PBF"
bench "Liechtenstein as GeoPackage, 1 tile (plain rules)" "$OUT/tile.gpkg"
bench "Liechtenstein tiled x$TILES as GeoPackage (plain rules)" "$OUT/tiled.gpkg"
