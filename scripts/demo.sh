#!/usr/bin/env bash
# The main job behind `make demo`: runs each module's part (scripts/demo/*.sh, in name
# order) with SK = the shitsukan binary and OUT = the output root, and times each.
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: scripts/demo.sh SHITSUKAN_BINARY OUT_DIR" >&2
  exit 2
fi
SK=$(realpath "$1")
mkdir -p "$2"
OUT=$(realpath "$2")
export SK OUT
here=$(dirname "$0")
start=$(date +%s)
for part in "$here"/demo/*.sh; do
  [ -e "$part" ] || continue
  name=$(basename "$part" .sh)
  t0=$(date +%s)
  echo "demo: $name"
  bash "$part"
  echo "demo: $name done in $(( $(date +%s) - t0 )) s"
done
echo "demo: all outputs in $OUT ($(( $(date +%s) - start )) s)"
