#!/usr/bin/env bash
# Hand posture from data (thesis 3.2.2 calibrated in full): on the shipped synthetic glove
# recordings (presets/hand/samples/synthetic-grasps.csv, made by `shitsukan hand
# synthesize`), held out by person, the model before calibration (the natural set with the
# built-in relaxed posture), the thesis's pair lines with eq. 3.18 weights, and the
# calibrated potential, each against the training mean, linear regression and a PCA prior
# with 6 components, for the three pin sets of the reported real-data comparison. Writes
# into $OUT/hand/: evaluation tables (.txt), reports (.json), bar charts (.png) and the
# calibrated potential of the whole data set with a pose it gives.
set -euo pipefail
: "${SK:?}" "${OUT:?}"
here=$(cd "$(dirname "$0")/../.." && pwd)
data="$here/presets/hand/samples/synthetic-grasps.csv"
out="$OUT/hand"
mkdir -p "$out"
pins=(--pins I.MCP.flex,I.PIP.flex --pins L.MCP.flex --pins M.MCP.flex,M.PIP.flex)
held=(--group person --ignore-columns trial)
# (tables go to stdout: the runs that write them drop -q)

"$SK" hand evaluate "$data" "${pins[@]}" "${held[@]}" --model natural \
  --report "$out/prior-eval-natural.json" --plot "$out/prior-eval-natural.png" \
  --plot-title "Before: the natural set and built-in relaxed posture (synthetic grasps, held out by person)" \
  > "$out/prior-eval-natural.txt"
"$SK" hand evaluate "$data" "${pins[@]}" "${held[@]}" -q --model pairs \
  --pairs I.MCP.flex:I.PIP.flex,M.MCP.flex:M.PIP.flex,R.MCP.flex:L.MCP.flex,I.PIP.flex:I.DIP.flex,M.PIP.flex:R.PIP.flex \
  --report "$out/prior-eval-eq318.json"
"$SK" hand evaluate "$data" "${pins[@]}" "${held[@]}" \
  --report "$out/prior-eval-calibrated.json" --plot "$out/prior-eval-calibrated.png" \
  --plot-title "After: the calibrated potential (synthetic grasps, held out by person)" \
  > "$out/prior-eval-calibrated.txt"

# one summary table: RMS over the unpinned joints, degrees
python3 - "$out" > "$out/prior-eval-summary.txt" <<'PY' 2>/dev/null || awk 'BEGIN { print "(python3 not found: see the .txt tables)" }' > "$out/prior-eval-summary.txt"
import json, sys
out = sys.argv[1]
rows = {name: json.load(open(f"{out}/prior-eval-{name}.json")) for name in ("natural", "eq318", "calibrated")}
print("| pins | natural | calibrated (eq. 3.18) | calibrated potential | training mean | linear regression | PCA prior, 6 comps |")
print("|---|---|---|---|---|---|---|")
for i, entry in enumerate(rows["calibrated"]):
    b = entry["baselines"]
    print(f"| {' + '.join(p.replace('.flex', '') for p in entry['pins'])} | {rows['natural'][i]['model_rms_deg']:.1f} | "
          f"{rows['eq318'][i]['model_rms_deg']:.1f} | {entry['model_rms_deg']:.1f} | {b['mean']:.1f} | {b['linear']:.1f} | "
          f"{b['pca']['rms_deg']:.1f} |")
PY

# the potential of the whole data set, and a pose from one pinned joint
"$SK" hand calibrate "$data" --group person --ignore-columns trial -o "$out/prior-potential.json" \
  > "$out/prior-calibration.txt"
"$SK" hand pose --potential "$out/prior-potential.json" --pin I.MCP.flex=60 --pin I.PIP.flex=80 \
  -o "$out/prior-pose.json" --png "$out/prior-pose.png"
