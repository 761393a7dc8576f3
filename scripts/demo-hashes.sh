#!/usr/bin/env bash
# Hashes every file the main job writes, to show that a change of structure changes no
# output. Two uses:
#
#   scripts/demo-hashes.sh run SHITSUKAN_BINARY OUT_DIR > hashes.txt
#       runs `make demo`'s job (scripts/demo.sh) into a fresh OUT_DIR, then prints one
#       line per file: its SHA-256 and its path under OUT_DIR, sorted by path
#   scripts/demo-hashes.sh compare BEFORE.txt AFTER.txt
#       lists the files whose bytes differ, that only one run wrote, and a count; exit 1
#       when any differ
#
# Files that differ between two runs of the same binary (the MP4's encoder stamps, say)
# show as differences too: compare two runs of the old binary first to know them.
set -euo pipefail

usage() {
  echo "usage: scripts/demo-hashes.sh run SHITSUKAN_BINARY OUT_DIR | compare BEFORE AFTER" >&2
  exit 2
}

[ $# -eq 3 ] || usage
here=$(cd "$(dirname "$0")" && pwd)
case "$1" in
  run)
    rm -rf "$3"
    bash "$here/demo.sh" "$2" "$3" >&2
    (cd "$3" && find . -type f -print0 | sort -z | xargs -0 sha256sum)
    ;;
  compare)
    join -j 2 -a 1 -a 2 -e MISSING -o 0,1.1,2.1 <(sort -k 2 "$2") <(sort -k 2 "$3") |
      awk '$2 != $3 { n++; if ($2 == "MISSING") print "only after:  " $1;
                     else if ($3 == "MISSING") print "only before: " $1;
                     else print "differs:     " $1 }
           END { printf "%d file(s) differ of %d\n", n, NR; exit n > 0 }'
    ;;
  *) usage ;;
esac
