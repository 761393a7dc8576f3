#!/usr/bin/env bash
# Runs a Blender import check headless: run.sh SCRIPT.py ARGS... (exit 77 = skipped when
# Blender is not installed, so ctest reports the check as skipped).
set -u
if ! command -v blender >/dev/null 2>&1; then
  echo "skip: blender is not installed (scripts/deps.sh blender)"
  exit 77
fi
script=$1
shift
# --python-exit-code: an exception in the script fails the run instead of exiting 0
exec blender -b --factory-startup --python-exit-code 3 --python "$script" -- "$@"
