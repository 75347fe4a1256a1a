#!/usr/bin/env bash
# The client package end to end (CTest: package_example_robot, fixture db): cpack -G DEB,
# the .deb unpacked into a temporary prefix (never installed), examples/example_robot
# built against it with find_package(fleetmap), then against the test database the
# installed programs import a map, add a robot and serve it, and the example registers as
# that robot and must report the segment count `fleetmap map list` gives for the map.
#   example_robot_test.sh SOURCE_DIR BUILD_DIR VERSION     (FLEETMAP_CONFIG: the test instance)
set -euo pipefail
SRC="$1" BUILD="$2" VERSION="$3"
: "${FLEETMAP_CONFIG:?expected FLEETMAP_CONFIG, the config of the test database (tests/CMakeLists.txt)}"

TMP="$(mktemp -d /tmp/fleetmap-package.XXXXXX)"
NAME="pkg$$"  # map and robot, unique per run
SERVER_PID=""
fail() { echo "FAIL: $*" >&2; exit 1; }
step() { echo "--- $(date +%T) $*"; }
cleanup() {
  if [ -n "$SERVER_PID" ]; then kill "$SERVER_PID" 2>/dev/null || true; wait "$SERVER_PID" 2>/dev/null || true; fi
  if [ -x "$TMP/root/usr/bin/fleetmap" ]; then
    "$TMP/root/usr/bin/fleetmap" robot remove "$NAME" >/dev/null 2>&1 || true
    "$TMP/root/usr/bin/fleetmap" map delete "$NAME" >/dev/null 2>&1 || true
  fi
  rm -rf "$TMP"
}
trap cleanup EXIT

step "cpack -G DEB (builds what is not built yet)"
(cd "$BUILD" && cpack -G DEB -B "$TMP/cpack" >"$TMP/cpack.log" 2>&1) || { cat "$TMP/cpack.log"; fail "cpack"; }
DEB="$TMP/cpack/fleetmap_${VERSION}_$(dpkg --print-architecture).deb"
[ -f "$DEB" ] || fail "expected $DEB; cpack made: $(ls "$TMP/cpack")"
DEPENDS="$(dpkg-deb -f "$DEB" Depends)"
echo "Depends: $DEPENDS"
for dep in libmysql++-dev nlohmann-json3-dev libeigen3-dev libc6; do  # libc6: from dpkg-shlibdeps
  [[ "$DEPENDS" == *"$dep"* ]] || fail "Depends lacks $dep"
done

step "dpkg-deb -x into $TMP/root"
dpkg-deb -x "$DEB" "$TMP/root"
BIN="$TMP/root/usr/bin"
for f in bin/fleetmap bin/fleetmap-server bin/fleetmap-robot include/fleetmap/client/robot_client.h \
         include/fleetmap/common/map/map.h share/fleetmap/sql/10_schema.sql share/fleetmap/fleetmap.conf.sample; do
  [ -e "$TMP/root/usr/$f" ] || fail "the package lacks /usr/$f"
done
[ ! -e "$TMP/root/usr/include/fleetmap/client/sim" ] || fail "the package holds client/sim (not public)"
[ ! -e "$TMP/root/usr/include/fleetmap/server" ] || fail "the package holds server/ headers"

step "build examples/example_robot against the unpacked prefix"
cmake -S "$SRC/examples/example_robot" -B "$TMP/example" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$TMP/root/usr" >"$TMP/example.log" 2>&1 || { cat "$TMP/example.log"; fail "configure"; }
FOUND="$(sed -n 's/^fleetmap_DIR:PATH=//p' "$TMP/example/CMakeCache.txt")"
[ "$FOUND" = "$TMP/root/usr/lib/cmake/fleetmap" ] || fail "find_package(fleetmap) found $FOUND, not the unpacked package"
cmake --build "$TMP/example" -j2 >>"$TMP/example.log" 2>&1 || { cat "$TMP/example.log"; fail "build"; }
EXAMPLE="$TMP/example/example_robot"
"$EXAMPLE" --help | grep -q "usage: example_robot" || fail "--help"

step "import a map and add a robot with the installed fleetmap"
"$BIN/fleetmap" map import "$SRC/maps/example-room.map" --name "$NAME"
# The segment count as the operator sees it: the SEGMENTS column of its row.
SEGMENTS="$("$BIN/fleetmap" map list | awk -v n="$NAME" '$1 == n { print $3 }')"
[[ "$SEGMENTS" =~ ^[0-9]+$ ]] || fail "map list: no segment count for $NAME: '$SEGMENTS'"
"$BIN/fleetmap" robot add "$NAME" --map "$NAME" --password-out "$TMP/robot.pw"
[ -s "$TMP/robot.pw" ] || fail "robot add wrote no password"

step "fleetmap-server, then the example as robot $NAME"
"$BIN/fleetmap-server" >"$TMP/server.log" 2>&1 &
SERVER_PID=$!
set +e
OUT="$("$EXAMPLE" --user "$NAME" --password-file "$TMP/robot.pw" --timeout 20 2>"$TMP/example.err")"
CODE=$?
set -e
echo "$OUT"
[ "$CODE" -eq 0 ] || { cat "$TMP/example.err" "$TMP/server.log"; fail "example_robot exited $CODE"; }
GOT="$(sed -n 's/^SetMap: .* \([0-9][0-9]*\) segments.*/\1/p' <<<"$OUT")"
[ "$GOT" = "$SEGMENTS" ] || fail "example_robot printed '$GOT' segments, map list says $SEGMENTS"

step "without a server: a clear time-out, exit 1"
kill "$SERVER_PID"; wait "$SERVER_PID" 2>/dev/null || true; SERVER_PID=""
set +e
"$EXAMPLE" --user "$NAME" --password-file "$TMP/robot.pw" --timeout 2 >/dev/null 2>"$TMP/timeout.err"
CODE=$?
set -e
cat "$TMP/timeout.err"
[ "$CODE" -eq 1 ] || fail "expected exit 1 without a server, got $CODE"
grep -q "no answer to request" "$TMP/timeout.err" || fail "expected the time-out message"
step "ok"
