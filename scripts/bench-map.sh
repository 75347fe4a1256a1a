#!/usr/bin/env bash
# Map benchmark on its own private MariaDB (build/benchdb, port 33308): import of a
# ~1 M-segment tiled campus map, then 200 random 100 m x 100 m windows with the spatial
# index and with a full scan. Extra arguments go to bench-map (--help lists them).
# The campus map is read from FLEETMAP_MAPS_DIR (default ../shared/maps beside the checkout).
set -euo pipefail
source "$(dirname "$0")/real-maps.sh"
require_real_maps bench-map UT_Campus.vectormap.txt
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
cmake --build "$BUILD" -j2 --target bench-map >/dev/null
export FLEETMAP_HOME="$PWD/$BUILD/benchdb" FLEETMAP_PORT="${FLEETMAP_BENCH_PORT:-33308}"
unset FLEETMAP_CONFIG
bash scripts/db.sh start
trap 'bash scripts/db.sh stop' EXIT
"$BUILD/bin/bench-map" --map "$MAPS/UT_Campus.vectormap.txt" "$@"
