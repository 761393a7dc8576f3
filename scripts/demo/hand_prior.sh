#!/usr/bin/env bash
# Hand posture from data (thesis 3.2.2 calibrated in full): on the shipped synthetic glove
# recordings (presets/hand/samples/synthetic-grasps.csv, made by `shitsukan hand
# synthesize`), held out by person, the model before calibration (the natural set and
# Table 3.2 with the built-in relaxed posture), the thesis's pair lines with eq. 3.18
# weights, its lookup tables (3.2.3), the thesis's form with pairs and weight scale chosen
# on held-out samples, and the calibrated potential (one Gaussian, the mixture), each
# against the training mean, linear regression and a PCA prior with 6 components, for the
# three pin sets of the reported real-data comparison. Writes
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
  --plot-title "Before: the natural set (synthetic grasps, held out by person)" \
  > "$out/prior-eval-natural.txt"
"$SK" hand evaluate "$data" "${pins[@]}" "${held[@]}" -q --model yasumuro-table-3.2 \
  --report "$out/prior-eval-table32.json"
pairs=I.MCP.flex:I.PIP.flex,M.MCP.flex:M.PIP.flex,R.MCP.flex:L.MCP.flex,I.PIP.flex:I.DIP.flex,M.PIP.flex:R.PIP.flex
"$SK" hand evaluate "$data" "${pins[@]}" "${held[@]}" -q --model pairs --pairs "$pairs" \
  --report "$out/prior-eval-eq318.json"
"$SK" hand evaluate "$data" "${pins[@]}" "${held[@]}" -q --model lookup-tables --pairs "$pairs" \
  --report "$out/prior-eval-tables.json"
"$SK" hand evaluate "$data" "${pins[@]}" "${held[@]}" -q --method pairs \
  --report "$out/prior-eval-pairs.json"
"$SK" hand evaluate "$data" "${pins[@]}" "${held[@]}" -q --method gaussian \
  --report "$out/prior-eval-gaussian.json"
"$SK" hand evaluate "$data" "${pins[@]}" "${held[@]}" \
  --report "$out/prior-eval-calibrated.json" --plot "$out/prior-eval-calibrated.png" \
  --plot-title "After: the calibrated mixture (synthetic grasps, held out by person)" \
  > "$out/prior-eval-calibrated.txt"

# one summary table: RMS over the unpinned joints, degrees, and the solves that did not converge
python3 - "$out" > "$out/prior-eval-summary.txt" <<'PY' 2>/dev/null || awk 'BEGIN { print "(python3 not found: see the .txt tables)" }' > "$out/prior-eval-summary.txt"
import json, sys
out = sys.argv[1]
models = [("natural", "natural"), ("table32", "Table 3.2"), ("eq318", "pairs, eq. 3.18"), ("tables", "lookup tables"),
          ("pairs", "pairs chosen"), ("gaussian", "Gaussian"), ("calibrated", "mixture")]
rows = {name: json.load(open(f"{out}/prior-eval-{name}.json")) for name, _ in models}
print("| pins | " + " | ".join(title for _, title in models) + " | training mean | linear regression | PCA prior, 6 comps |")
print("|---" * (len(models) + 4) + "|")
for i, entry in enumerate(rows["calibrated"]):
    b = entry["baselines"]
    cells = [f"{rows[name][i]['model_rms_deg']:.1f}" for name, _ in models]
    print(f"| {' + '.join(p.replace('.flex', '') for p in entry['pins'])} | " + " | ".join(cells) +
          f" | {b['mean']:.1f} | {b['linear']:.1f} | {b['pca']['rms_deg']:.1f} |")
bad = sum(e["solves"]["not_converged"] for name, _ in models for e in rows[name])
total = sum(e["solves"]["count"] for name, _ in models for e in rows[name])
print(f"\nsolves: {total}, not converged: {bad}")
PY

# the potential of the whole data set, and a pose from one pinned joint
"$SK" hand calibrate "$data" --group person --ignore-columns trial -o "$out/prior-potential.json" \
  > "$out/prior-calibration.txt"
"$SK" hand pose --potential "$out/prior-potential.json" --pin I.MCP.flex=60 --pin I.PIP.flex=80 \
  -o "$out/prior-pose.json" --png "$out/prior-pose.png"
