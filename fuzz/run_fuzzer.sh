#!/usr/bin/env bash
# Runs one libFuzzer target for SECONDS on a copy of CORPUS (the repository is never
# written); exit status non-zero when libFuzzer found something, whose input is then
# printed (hex) so that it reaches the test log.
#   run_fuzzer.sh BINARY CORPUS SECONDS
set -uo pipefail
BIN="$1" CORPUS="$2" SECONDS_TO_RUN="$3"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/fleetmap-fuzz.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
mkdir -p "$WORK/corpus" "$WORK/artifacts"
cp "$CORPUS"/* "$WORK/corpus/"
# -timeout: one input taking 10 s is a hang; -rss_limit_mb: a runaway allocation.
"$BIN" -max_total_time="$SECONDS_TO_RUN" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$WORK/artifacts/" "$WORK/corpus"
status=$?
for f in "$WORK"/artifacts/*; do
  [ -f "$f" ] || continue
  echo "run_fuzzer: input of $(basename "$f") ($(stat -c %s "$f") bytes):"
  od -A d -c "$f" | head -n 40
done
exit "$status"
