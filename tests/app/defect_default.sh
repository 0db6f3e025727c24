#!/usr/bin/env bash
# `skinfem defect` on the default scene against issue 26's criteria and the scene's reference numbers
# (scenes/candelier2011.reference.json): every curve of defect.csv smooth, the largest sliding signal with an
# error bar of at most 2 %, and that signal within its bar plus the reference's own error of the resolved
# hole (an independent second method: the hole cutting the hats on a path meshed at 0.1 mm).
set -u
skinfem=$1
source_dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if ! "$skinfem" defect "$source_dir/scenes/candelier2011.json" --out "$tmp/out" >"$tmp/log" 2>&1; then
  cat "$tmp/log"
  echo "FAIL: skinfem defect exited non-zero"
  exit 1
fi
/usr/bin/python3 - "$tmp/out/summary.json" "$source_dir/scenes/candelier2011.reference.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
ref = json.load(open(sys.argv[2]))
bad = []
crit = ref["defect"]
if s.get("hole_model") != "bulge":
    bad.append(f"hole_model {s.get('hole_model')}, expected the default bulge")
for case, c in s["cases"].items():
    if not c["max_roughness"] <= crit["max_roughness"]:
        bad.append(f"{case}: max_roughness {c['max_roughness']:.4f} ({c['max_roughness_curve']}) > {crit['max_roughness']}")
b = s.get("largest_sliding")
if b is None:
    bad.append("summary.json has no largest_sliding (error bar)")
else:
    if not b["relative_error"] <= crit["max_relative_error"]:
        bad.append(f"largest sliding signal's bar {100 * b['relative_error']:.2f} % > {100 * crit['max_relative_error']} %")
    r = ref["largest_sliding_varsigma_z"]
    allowed = b["error_kPa"] + r["error_kPa"]
    if not abs(b["value_kPa"] - r["value_kPa"]) <= allowed:
        bad.append(f"largest sliding signal {b['value_kPa']:.4f} kPa: {abs(b['value_kPa'] - r['value_kPa']):.4f} "
                   f"from the resolved reference {r['value_kPa']} kPa, more than the bars' sum {allowed:.4f}")
    peak = max(x["peak_abs_varsigma_z_kPa"] for x in s["cases"]["sliding"]["sensors"])
    if abs(peak - b["value_kPa"]) > 1e-12 * peak:
        bad.append(f"largest_sliding {b['value_kPa']} is not the sliding case's largest peak {peak}")
for line in bad:
    print("FAIL", line)
print("defect_default:", "ok" if not bad else f"{len(bad)} failures",
      f"(roughness {[round(c['max_roughness'], 4) for c in s['cases'].values()]},",
      f"largest sliding {b['value_kPa']:.4f} +- {b['error_kPa']:.4f} kPa)" if b else ")")
sys.exit(1 if bad else 0)
PY
