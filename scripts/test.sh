#!/usr/bin/env bash
# Builds and runs every test (unit and integration) against a fresh private MariaDB
# that the CTest fixture starts and stops (tests/CMakeLists.txt). Ends with CTest's summary.
#   FLEETMAP_BUILD_DIR  build folder (default: build)
#   FLEETMAP_MAPS_DIR   the real maps; when set, checked and configured as the build's
#                       folder (otherwise the one configured, default ../shared/maps)
set -euo pipefail
MAPS_FLAG=()
if [ -n "${FLEETMAP_MAPS_DIR:-}" ]; then
  source "$(dirname "$0")/real-maps.sh"
  require_real_maps test GDC1.vectormap.txt GDC1.navigation.json UT_Campus.vectormap.txt UT_Campus.navigation.json
  MAPS_FLAG=(-DFLEETMAP_MAPS_DIR="$MAPS")
fi
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release "${MAPS_FLAG[@]}" >/dev/null
cmake --build "$BUILD" -j"${FLEETMAP_JOBS:-2}"
# A stale instance from an interrupted run is stopped and thrown away.
FLEETMAP_HOME="$PWD/$BUILD/testdb" FLEETMAP_PORT=33307 bash scripts/db.sh stop >/dev/null 2>&1 || true
rm -rf "$BUILD/testdb"
cd "$BUILD"
ctest --output-on-failure -j"${FLEETMAP_JOBS:-2}" "$@"
