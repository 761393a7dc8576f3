#!/usr/bin/env bash
# The test suite under valgrind memcheck: scripts/test-valgrind.sh BUILD_DIR [REGEX]
# (REGEX: only the tests whose names match it, e.g. '^(test_cli|test_robustness)$').
# Every test executable that ctest runs, and the shitsukan command the tests start, runs
# under memcheck; any invalid access, use of uninitialised memory or definite leak fails
# the test (exit 99). Leaks are counted as definite only: OpenMP's and Embree's thread
# pools keep their memory until exit on purpose.
set -euo pipefail
build=${1:?usage: test-valgrind.sh BUILD_DIR [REGEX]}
only=${2:-}
command -v valgrind >/dev/null || { echo "test-valgrind: valgrind is not installed" >&2; exit 2; }
vg="valgrind --tool=memcheck --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite --show-leak-kinds=definite --track-origins=no --num-callers=30 -q"
# Skipped, each with its reason (memcheck runs code 20 to 50 times slower than native):
#   test_render_*   Embree builds its BVH and traces millions of rays per test: hours
#                   under memcheck; the renderer's inputs are covered by the
#                   fuzz_render_scene replay and its own tests under ASan + UBSan.
#   test_skin       builds skins of up to a million cells (about 35 s native): 20+ min.
#   test_wood       renders many cuts at several thread counts (about 15 s native).
#   test_noise_map  renders maps at several sizes and thread counts (about 20 s native).
#   install_package builds another project with cmake: not a test of our memory use.
#   demo_job        the whole of make demo (about 90 s native): every command it runs is
#                   tested here on its own.
#   studio_browser  drives headless Chromium against the served page for minutes; the
#                   server's request parser is replayed by fuzz_http_request and its
#                   end-to-end test (test_studio_server) runs here.
#   gltf_validator, gltf_blender_import, tissue_blender_pc2, docs_links,
#   lint_posix_source
#                   run another program (the Khronos validator in node, Blender, shell
#                   checks of the sources) on files: none of our code runs in them. The
#                   commands that write their files (render_export_*, hand_export_*,
#                   tissue_export_*) do run here.
# Those run under ASan + UBSan in make test-asan (but demo_job, for the same reason).
skip='^(test_render_.*|test_skin|test_wood|test_noise_map|install_package|demo_job|studio_browser|gltf_validator|gltf_blender_import|tissue_blender_pc2|docs_links|lint_posix_source)$'
export SK_TEST_SANITIZED=1 OMP_NUM_THREADS=2
export SK_TEST_CLI_WRAPPER="$vg"
mapfile -t tests < <(ctest --test-dir "$build" -N | sed -n 's/^ *Test *#[0-9]*: //p')
passed=0 failed=0 skipped=0
for name in "${tests[@]}"; do
    if [[ $name =~ $skip ]] || { [ -n "$only" ] && ! [[ $name =~ $only ]]; }; then
        skipped=$((skipped + 1))
        continue
    fi
    # the test's command line as ctest has it
    line=$(ctest --test-dir "$build" -R "^${name}\$" -V -N | sed -n 's/^[0-9]*: Test command: //p' | head -1)
    start=$(date +%s)
    if (cd "$build/tests" && eval "$vg $line") >"$build/valgrind-$name.log" 2>&1; then
        passed=$((passed + 1))
        status=ok
    else
        failed=$((failed + 1))
        status="FAILED (see $build/valgrind-$name.log)"
    fi
    printf '%-28s %4ds  %s\n' "$name" $(($(date +%s) - start)) "$status"
done
echo "valgrind: $passed passed, $failed failed, $skipped skipped"
[ $failed -eq 0 ]
