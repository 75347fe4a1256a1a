#!/usr/bin/env bash
# Builds and runs every test (unit and integration) against a fresh private MariaDB
# that the CTest fixture starts and stops (tests/CMakeLists.txt). Ends with CTest's summary.
#
# Stage 1: Release build (g++) in FLEETMAP_BUILD_DIR and the whole suite.
# Stage 2 (sanitizers): clang++ build in FLEETMAP_ASAN_BUILD_DIR with ASan, LSan and
#   UBSan (cmake/sanitizers.cmake), -Werror and the libFuzzer targets (fuzz/), then the
#   whole suite again, against its own MariaDB, plus the fuzz tests (label fuzz). A
#   sanitizer report in a test or in a program it runs fails that test.
#   Runs when CI=true or FLEETMAP_SANITIZE_STAGE=1; FLEETMAP_SANITIZE_STAGE=0 skips it.
#   Off by default for a developer: a second full build and a slower suite (about 15
#   minutes on 2 cores); turn it on before pushing a change to parsers or memory handling.
#
#   FLEETMAP_BUILD_DIR       stage 1 build folder (default: build)
#   FLEETMAP_ASAN_BUILD_DIR  stage 2 build folder (default: build-asan)
#   FLEETMAP_TEST_DB_PORT    stage 1 test database port (default: 33307; the second
#                            instance on that + 10)
#   FLEETMAP_ASAN_DB_PORT    stage 2 test database port (default: 33308; + 10 likewise)
#   FLEETMAP_MAPS_DIR        the real maps; when set, checked and configured as the
#                            build's folder (otherwise the one configured, ../shared/maps)
# Warnings fail the build when CI=true (FLEETMAP_WERROR, cmake/sanitizers.cmake), in both
# stages; setup.sh configures the same way, so CI builds stage 1 once.
#   FLEETMAP_FUZZ_SECONDS    how long each fuzz test runs (default: 15)
#   FLEETMAP_JOBS            parallel build and test jobs (default: 2)
# Other arguments go to ctest (both stages), e.g. -R SeedFormat.
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS="${FLEETMAP_JOBS:-2}"
IN_CI=0
[ "${CI:-}" = true ] && IN_CI=1
SANITIZE_STAGE="${FLEETMAP_SANITIZE_STAGE:-$IN_CI}"
MAPS_FLAG=()
if [ -n "${FLEETMAP_MAPS_DIR:-}" ]; then
  source "$(dirname "$0")/real-maps.sh"
  require_real_maps test GDC1.vectormap.txt GDC1.navigation.json UT_Campus.vectormap.txt UT_Campus.navigation.json
  MAPS_FLAG=(-DFLEETMAP_MAPS_DIR="$MAPS")
fi

stamp() { date +%s; }
took() { echo "test.sh: $1 took $(( $(stamp) - $2 )) s"; }

# run_suite BUILD_DIR PORT [ctest args]: stale instances from an interrupted run are
# stopped and thrown away, then CTest starts fresh ones (fixtures db and db2, the second
# on PORT + 10: tests/CMakeLists.txt).
run_suite() {
  local build="$1" port="$2"
  shift 2
  FLEETMAP_HOME="$PWD/$build/testdb" FLEETMAP_PORT="$port" bash scripts/db.sh stop >/dev/null 2>&1 || true
  FLEETMAP_HOME="$PWD/$build/testdb2" FLEETMAP_PORT="$((port + 10))" bash scripts/db.sh stop >/dev/null 2>&1 || true
  rm -rf "$build/testdb" "$build/testdb2"
  (cd "$build" && ctest --output-on-failure -j"$JOBS" "$@")
}

BUILD="${FLEETMAP_BUILD_DIR:-build}"
PORT="${FLEETMAP_TEST_DB_PORT:-33307}"
t=$(stamp)
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DTEST_DB_PORT="$PORT" "${MAPS_FLAG[@]}" >/dev/null
cmake --build "$BUILD" -j"$JOBS"
took "stage 1 build ($BUILD)" "$t"
if [ "$SANITIZE_STAGE" != 1 ]; then
  run_suite "$BUILD" "$PORT" "$@"
  exit
fi
t=$(stamp)
run_suite "$BUILD" "$PORT" "$@"
took "stage 1 tests" "$t"
# Stage 1's instances are stopped (the fixtures' cleanup) and no longer needed: their
# data directories would take disk that stage 2's build and instances need.
rm -rf "$BUILD/testdb" "$BUILD/testdb2" "$BUILD/testcluster" "$BUILD/testchaos"
echo "test.sh: $(df -Pm . | awk 'NR==2 {print $4}') MiB free for stage 2"

ASAN_BUILD="${FLEETMAP_ASAN_BUILD_DIR:-build-asan}"
ASAN_PORT="${FLEETMAP_ASAN_DB_PORT:-33308}"
t=$(stamp)
cmake -S . -B "$ASAN_BUILD" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
  -DFLEETMAP_SANITIZE=ON -DFLEETMAP_FUZZ=ON -DFLEETMAP_WERROR=ON -DFLEETMAP_BUILD_BENCHMARKS=OFF \
  -DFLEETMAP_FUZZ_SECONDS="${FLEETMAP_FUZZ_SECONDS:-15}" -DTEST_DB_PORT="$ASAN_PORT" "${MAPS_FLAG[@]}" >/dev/null
cmake --build "$ASAN_BUILD" -j"$JOBS"
took "stage 2 build ($ASAN_BUILD, sanitizers)" "$t"
# abort_on_error: a report ends the program with SIGABRT, which no test mistakes for
# one of our exit codes. Programs run by integration tests log to files of their own
# (tests/integration/sanitizer_reports.cpp).
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
# MySQL++ 3.3 frees a connection's MYSQL handle and options only after a successful
# connect; the leaks of a refused connect (wrong password, database down) are its own.
# print_suppressions=0: the statistics of used suppressions are no report, and a test
# reading a program's stderr must not see them.
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
echo "test.sh: stage 2 tests under ASAN_OPTIONS=$ASAN_OPTIONS LSAN_OPTIONS=$LSAN_OPTIONS UBSAN_OPTIONS=$UBSAN_OPTIONS"
# Long pure-computation trials on the real maps run in stage 1 only (about 330 s under
# the sanitizers, a third of the stage): the same code stays under ASan through the
# shorter tests of each (RealMaps' tracking, GlobalSearch, MapSlice and TopoRoute's
# synthetic cases, the ray casters' equivalence on the real maps).
ASAN_SKIP='^(RealMaps\.(LookingAroundLocalizesWhereTheFirstScansFitElsewhere|GlobalLocalization.*)|MapSlice\.SameRangesOnTheRealMaps|TopoRoute\.RandomPairsAreAsShortAsFloydWarshall)$'
run_suite "$ASAN_BUILD" "$ASAN_PORT" -E "$ASAN_SKIP" "$@"
