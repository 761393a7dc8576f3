#!/usr/bin/env bash
# Runs the studio's browser tests: serves the assembled page with `shitsukan studio` on
# a free port, then Playwright (from node_modules) with the system Chromium. Exits 77
# (ctest's skip) with a message when the studio is not built or node, Chromium or
# Playwright are absent.
#
#   web/tests/run.sh SHITSUKAN_BINARY STUDIO_DIR [OUT_DIR]
set -u
bin=$1
www=$2
out=${3:-$(dirname "$www")/studio-tests}
root=$(cd "$(dirname "$0")/../.." && pwd)
skip() { echo "studio tests skipped: $*"; exit 77; }
command -v node >/dev/null 2>&1 || skip "no node"
chromium=${CHROMIUM:-$(command -v chromium || true)}
[ -n "$chromium" ] || skip "no chromium (scripts/deps.sh studio installs it)"
[ -f "$root/node_modules/@playwright/test/cli.js" ] || skip "no Playwright in node_modules (scripts/deps.sh node)"
[ -f "$www/index.html" ] && [ -f "$www/wasm/studio.wasm" ] || skip "the studio is not built (make studio; needs emscripten)"
mkdir -p "$out"
log="$out/server.log"
"$bin" studio --port 0 --quiet --root "$www" > "$log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; wait $server 2>/dev/null' EXIT
url=
for _ in $(seq 1 100); do
  url=$(grep -o 'http://[0-9.:]*/' "$log" | head -n 1 || true)
  [ -n "$url" ] && break
  kill -0 $server 2>/dev/null || { cat "$log"; echo "studio tests: the server did not start"; exit 1; }
  sleep 0.1
done
[ -n "$url" ] || { echo "studio tests: no address from the server"; exit 1; }
export STUDIO_URL=$url STUDIO_WWW=$www SHITSUKAN=$bin CHROMIUM=$chromium STUDIO_TEST_OUT=$out/results STUDIO_TMP=$out/tmp
# screenshots of each panel: into the test folder, or where STUDIO_SHOTS says
# (make studio-docs: docs/images/studio)
export STUDIO_SHOTS=${STUDIO_SHOTS:-$out/shots} PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1
mkdir -p "$STUDIO_TMP"
cd "$root" && node node_modules/@playwright/test/cli.js test -c web/tests/playwright.config.mjs
