#!/usr/bin/env bash
# `objects near` benchmark on its own private MariaDB (build/benchdb-objects, port 33319):
# 100 000 generated objects, k nearest with a tag from random points, spatial index vs
# full scans. Extra arguments go to bench-objects (--help lists them).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
cmake --build "$BUILD" -j2 --target bench-objects >/dev/null
export FLEETMAP_HOME="$PWD/$BUILD/benchdb-objects" FLEETMAP_PORT="${FLEETMAP_BENCH_PORT:-33319}"
unset FLEETMAP_CONFIG
bash scripts/db.sh start
trap 'bash scripts/db.sh stop' EXIT
"$BUILD/bin/bench-objects" "$@"
