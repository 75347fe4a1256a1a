#!/usr/bin/env bash
# The seeds' experiments (issue 8, docs/experiments.md), no database:
#   experiment-slices  seed 004 Fig. 9-10: tracking on the slice at the laser's height
#                      (0.381 m) vs the other laser's (0.794 m), example room and a hall
#                      generated from it, seeded 100 m drives;
#   experiment-zoom    seed 002 Fig. 8: the robot's map handling with a 40 m zoom window
#                      vs the whole campus map, same drive.
# About 6-8 minutes on two shared cores with the defaults. Environment: FLEETMAP_BUILD_DIR
# (default build), SLICES_ARGS and ZOOM_ARGS (extra flags, e.g. SLICES_ARGS="--runs 20").
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
if [ ! -f "$BUILD/CMakeCache.txt" ]; then cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null; fi
cmake --build "$BUILD" -j2 --target experiment-slices experiment-zoom >/dev/null
# shellcheck disable=SC2086
"$BUILD/bin/experiment-slices" --runs 10 ${SLICES_ARGS:-}
echo
# shellcheck disable=SC2086
"$BUILD/bin/experiment-zoom" --runs 2 --drive 200 ${ZOOM_ARGS:-}
