#!/usr/bin/env bash
# Runs every libFuzzer harness of a fuzz build for a bounded time, one after the other:
#   scripts/fuzz.sh BUILD_DIR SECONDS [HARNESS...]
# Each harness starts from its seed corpus (fuzz/corpus/<reader>/) and the inputs of past
# findings (fuzz/regressions/<reader>/), copied into BUILD_DIR/fuzz-corpus/<reader>/ so
# the shipped corpora stay small; it uses fuzz/dict/<reader>.dict (json.dict for the JSON
# readers). Crashes, leaks and timeouts go to BUILD_DIR/fuzz-findings/; copy a finding
# into fuzz/regressions/<reader>/ with its fix, so every test pass replays it.
# Prints one line per harness: seconds, executions, new findings.
set -euo pipefail
build=${1:?usage: fuzz.sh BUILD_DIR SECONDS [HARNESS...]}
seconds=${2:?usage: fuzz.sh BUILD_DIR SECONDS [HARNESS...]}
shift 2
here=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$build" && pwd)
fuzz="$here/fuzz"
mapfile -t harnesses < <(if [ $# -gt 0 ]; then printf '%s\n' "$@"; else
    for f in "$fuzz"/fuzz_*.c; do basename "$f" .c; done; fi)
mkdir -p "$build/fuzz-findings"
status=0
for name in "${harnesses[@]}"; do
    reader=${name#fuzz_}
    bin="$build/fuzz/$name"
    [ -x "$bin" ] || { echo "fuzz: $bin is not built" >&2; exit 2; }
    work="$build/fuzz-corpus/$reader"
    mkdir -p "$work"
    cp -n "$fuzz/corpus/$reader"/* "$work"/ 2>/dev/null || true
    [ -d "$fuzz/regressions/$reader" ] && cp -n "$fuzz/regressions/$reader"/* "$work"/ 2>/dev/null || true
    dict="$fuzz/dict/$reader.dict"
    case $reader in constraints|anatomy|animation|preset|render_scene|hand_potential) dict="$fuzz/dict/json.dict" ;; esac
    dict_arg=()
    [ -f "$dict" ] && dict_arg=("-dict=$dict")
    # the command line's parsers print an error line per bad input: closed, not logged
    [ "$reader" = cli ] && dict_arg+=("-close_fd_mask=2")
    log="$build/fuzz-findings/$reader.log"
    before=$(find "$build/fuzz-findings" -name "$reader-*" | wc -l)
    # one process at a time (the machine is shared); 2 GiB and 10 s per input at most
    set +e
    (cd "$build/fuzz-findings" && "$bin" "$work" "${dict_arg[@]}" -max_total_time="$seconds" \
        -rss_limit_mb=2048 -timeout=10 -max_len=65536 -print_final_stats=1 \
        -artifact_prefix="$build/fuzz-findings/$reader-" >"$log" 2>&1)
    rc=$?
    set -e
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    after=$(find "$build/fuzz-findings" -name "$reader-*" | wc -l)
    printf '%-24s %4ss  %10s executions  %d finding(s)%s\n' "$name" "$seconds" "${runs:-?}" \
        $((after - before)) "$([ $rc -ne 0 ] && echo " (exit $rc, see $log)")"
    [ $rc -ne 0 ] && status=1
done
exit $status
