#!/usr/bin/env bash
# The seeds' experiments (docs/experiments.md), no database:
#   experiment-slices  seed 004 Fig. 9-10: tracking on the slice at the laser's height
#                      (0.381 m) vs the other laser's (0.794 m), example room and a hall
#                      generated from it, seeded 100 m drives;
#   experiment-zoom    seed 002 Fig. 8: the robot's map handling with a zoom window
#                      vs the whole campus map, same drive.
# experiment-slices runs twice: with the seed's sensor model (eq. 4-6) and with the
# robot's (robust: beam product with a floor, tempering); experiment-zoom twice: a 40 m
# window refreshed at 10 m and the seed's proportions (a window of 10 % of the
# area, new at 40 % of its side). 10-12 minutes on two cores. Environment: FLEETMAP_BUILD_DIR
# (default build), FLEETMAP_MAPS_DIR (the campus map for experiment-zoom, default
# ../shared/maps beside the checkout), SLICES_ARGS and ZOOM_ARGS (extra flags, e.g.
# SLICES_ARGS="--runs 20").
set -euo pipefail
source "$(dirname "$0")/real-maps.sh"
require_real_maps experiments UT_Campus.vectormap.txt
cd "$(dirname "$0")/.."
BUILD="${FLEETMAP_BUILD_DIR:-build}"
if [ ! -f "$BUILD/CMakeCache.txt" ]; then cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null; fi
cmake --build "$BUILD" -j2 --target experiment-slices experiment-zoom >/dev/null
# shellcheck disable=SC2086
for model in seed robust; do
  "$BUILD/bin/experiment-slices" --runs 10 --model "$model" ${SLICES_ARGS:-}
  echo
done
# shellcheck disable=SC2086
"$BUILD/bin/experiment-zoom" --map "$MAPS/UT_Campus.vectormap.txt" --runs 2 --drive 200 ${ZOOM_ARGS:-}
echo
# shellcheck disable=SC2086
"$BUILD/bin/experiment-zoom" --map "$MAPS/UT_Campus.vectormap.txt" --runs 1 --drive 200 --window 146 --refresh 58 ${ZOOM_ARGS:-}
