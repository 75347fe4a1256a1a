#!/usr/bin/env bash
# Installs every Debian package fleetmap needs, then configures and builds.
# Idempotent: packages already present are not fetched again, the build is incremental.
#   FLEETMAP_BUILD_DIR  build folder (default: build)
#   FLEETMAP_SKIP_APT=1 never call apt-get (machines without root)
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  build-essential cmake pkg-config ccache git python3
  libmysql++-dev mariadb-server mariadb-client
  libboost-dev libboost-system-dev libeigen3-dev nlohmann-json3-dev libcli11-dev
  libspdlog-dev zlib1g-dev googletest libgtest-dev libgmock-dev
  dpkg-dev file
  clang libclang-rt-14-dev llvm
  libgdal-dev gdal-bin libproj-dev proj-bin
  libjs-leaflet chromium curl libssl-dev openssl
  galera-4 rsync
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ "${#missing[@]}" -gt 0 ] && [ "${FLEETMAP_SKIP_APT:-0}" != 1 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "setup: all ${#PACKAGES[@]} packages present"
fi

BUILD="${FLEETMAP_BUILD_DIR:-build}"
echo "setup: building in $BUILD"
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD" -j"${FLEETMAP_JOBS:-2}"
echo "setup: done; programs are in $BUILD/bin"
