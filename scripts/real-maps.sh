# Sourced (before any cd) by the scripts that read the real maps: the AMRL vector maps
# and navigation graphs (ut-amrl/amrl_maps, unmodified) and the GIS datasets are read
# where they are kept, never copied into the repository.
#   require_real_maps NAME FILE...   sets MAPS to the folder (absolute) and exports
#                                    FLEETMAP_MAPS_DIR, so the programs read the same one;
#                                    exits 1 naming the folder and the file when one is missing.
# The folder is $FLEETMAP_MAPS_DIR, or ../shared/maps beside the checkout.
FLEETMAP_CHECKOUT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

require_real_maps() {
  local name="$1" dir f
  shift
  dir="${FLEETMAP_MAPS_DIR:-$FLEETMAP_CHECKOUT/../shared/maps}"
  if [ ! -d "$dir" ]; then
    echo "$name: no folder of real maps at $dir; expected the AMRL maps (ut-amrl/amrl_maps) there," \
         "or set FLEETMAP_MAPS_DIR to their folder" >&2
    exit 1
  fi
  MAPS="$(cd "$dir" && pwd)"
  for f in "$@"; do
    if [ ! -f "$MAPS/$f" ]; then
      echo "$name: $MAPS/$f is missing; expected the real maps there (FLEETMAP_MAPS_DIR)" >&2
      exit 1
    fi
  done
  export FLEETMAP_MAPS_DIR="$MAPS"
}
