#!/usr/bin/env bash
# skinfem scan and skinfem perceive through the command line, on a sphere pressed into a small flat layer.
# scan: a random texture of two holes off y = 0 (so the whole mesh, not the half) scanned 4 mm: exit 0;
# scan.csv has a row per case, position and sensor with the superposition beside, every number finite; the
# animation lists a frame per position and case and each file exists; summary.json counts the holes and
# holes.csv lists them (in their rectangle, the narrowest ligament the summary's); a
# second run writes the same scan.csv byte for byte (the cut problems are built on several threads).
# perceive: the required SNR is Φ⁻¹(0.99) + Φ⁻¹(0.9) = 3.608 (tables); the ROC curves rise with the
# false-alarm rate; the Monte Carlo rates lie within 4 standard errors of the nominal ones, the slid filter's
# false alarms under Rice's bound; dictionary.csv holds what summary.json counts. invert: the
# scene's defect sweep, inverted, gives its hole back at the plate's origin; with --dictionary the same
# features from the dictionary it wrote, and that dictionary refused for another case or offset range.
set -u
skinfem=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/scene.json" <<'JSON'
{"name": "scanned", "geometry": {"type": "flat", "h": 2.0, "half_width": 5.0},
 "material": {"E": 3.0, "nu": 0.5},
 "sensors": {"positions": [[-1.0, 0.0], [0.0, 0.0], [1.0, 0.0]], "disc_diameter": 0.2},
 "mesh": {"h_min": 0.5, "growth": 1.7, "h_max": 1.5},
 "contact": {"indenter": {"type": "sphere", "R": 20.0, "center": [0.0, 0.0]}, "force": 0.3, "zone_radius": 2.2,
             "h": 0.35, "friction": {"mode": "coupled", "mu": 0.5, "static_ratio": 0.1},
             "texture": {"random": {"from": [-3.0, -0.5], "to": [-1.0, 0.5], "density": 1.0,
                                    "diameter": [0.35, 0.45], "seed": 3}, "h": 0.35},
             "scan": {"from": 0.0, "to": 4.0, "step": 0.1},
             "sweep": {"from": [-1.8, 0.0], "to": [1.8, 0.0], "positions": 41, "hole_diameter": 0.4}}}
JSON
for run in a b; do
  "$skinfem" scan "$tmp/scene.json" --out "$tmp/$run" >"$tmp/$run.out" 2>"$tmp/err" ||
    { echo "FAIL scan $run:"; cat "$tmp/err"; exit 1; }
done
cmp -s "$tmp/a/scan.csv" "$tmp/b/scan.csv" || { echo "FAIL: two runs wrote different scan.csv"; exit 1; }
"$skinfem" perceive "$tmp/scene.json" --out "$tmp/p" >"$tmp/p.out" 2>"$tmp/err" ||
  { echo "FAIL perceive:"; cat "$tmp/err"; exit 1; }
"$skinfem" defect "$tmp/scene.json" --no-error-bars --out "$tmp/d" >"$tmp/d.out" 2>"$tmp/err" ||
  { echo "FAIL defect:"; cat "$tmp/err"; exit 1; }
"$skinfem" invert "$tmp/d/defect.csv" "$tmp/scene.json" --offset-range 0.3 --out "$tmp/i" >"$tmp/i.out" 2>"$tmp/err" ||
  { echo "FAIL invert:"; cat "$tmp/err"; exit 1; }
"$skinfem" invert "$tmp/d/defect.csv" "$tmp/scene.json" --offset-range 0.3 --dictionary "$tmp/i" --out "$tmp/r" \
  >"$tmp/r.out" 2>"$tmp/err" || { echo "FAIL invert --dictionary:"; cat "$tmp/err"; exit 1; }
# A dictionary reused for what it was not built for: another case, a wider offset range.
refused() {
  if "$skinfem" invert "$tmp/d/defect.csv" "$tmp/scene.json" --dictionary "$tmp/i" --out "$tmp/x" "${@:2}" \
    >/dev/null 2>"$tmp/err"; then
    echo "FAIL invert --dictionary ${*:2}: accepted"; exit 1
  fi
  grep -q -- "$1" "$tmp/err" || { echo "FAIL invert --dictionary ${*:2}: said"; cat "$tmp/err"; exit 1; }
  [ ! -e "$tmp/x" ] || { echo "FAIL invert --dictionary ${*:2}: wrote $tmp/x"; exit 1; }
}
refused "built for another scene or case: line 3 of its dictionary.key reads 'case sliding', this run's 'case static'" \
  --case static --offset-range 0.3
refused "it has no virtual sensor at .*it was built for another --offset-range" --offset-range 0.5
/usr/bin/python3 - "$tmp" <<'PY'
import csv, json, math, os, re, sys
tmp = sys.argv[1]
bad = []
rows = list(csv.DictReader(open(f"{tmp}/a/scan.csv")))
cols = ["case", "u_mm", "sensor", "varsigma_z_kPa", "varsigma_x_kPa", "superposed_z_kPa", "superposed_x_kPa"]
if list(rows[0].keys()) != cols:
    bad.append(f"scan.csv columns {list(rows[0].keys())}")
if len(rows) != 2 * 41 * 3:
    bad.append(f"scan.csv has {len(rows)} rows, expected 2 x 41 x 3")
if not all(math.isfinite(float(r[c])) for r in rows for c in cols[1:]):
    bad.append("a number in scan.csv is not finite")
summary = json.load(open(f"{tmp}/a/summary.json"))
if summary["holes"] != 2:
    bad.append(f"summary.json: {summary['holes']} holes, expected 2")
# holes.csv lists the random holes: inside their rectangle, diameters in range, the narrowest ligament the
# summary's (recomputed from the file's 10 digits).
holes = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(f"{tmp}/a/holes.csv"))]
if len(holes) != 2 or not all(-3 <= h["x_mm"] <= -1 and -0.5 <= h["y_mm"] <= 0.5 and 0.35 <= h["diameter_mm"] <= 0.45
                              for h in holes):
    bad.append(f"holes.csv: {holes}")
else:
    a, b = holes
    gap = math.hypot(a["x_mm"] - b["x_mm"], a["y_mm"] - b["y_mm"]) - 0.5 * (a["diameter_mm"] + b["diameter_mm"])
    if not gap > 0 or abs(gap - summary["closest_rims_mm"]) > 1e-8:
        bad.append(f"closest rims {summary['closest_rims_mm']} against holes.csv's {gap}")
frames = re.findall(r'file="(frames/[^"]+)"', open(f"{tmp}/a/scan.pvd").read())
if len(frames) != 2 * 41 or not all(os.path.exists(f"{tmp}/a/{f}") for f in frames):
    bad.append(f"scan.pvd lists {len(frames)} frames (expected 82, each written)")
p = json.load(open(f"{tmp}/p/perception.json"))
if abs(p["required_snr"] - 3.6079) > 1e-3:
    bad.append(f"required SNR {p['required_snr']}")
roc = list(csv.DictReader(open(f"{tmp}/p/roc.csv")))
for case in ["static", "sliding"]:
    for f in ["array", "best_sensor"]:
        pd = [float(r["p_d"]) for r in roc if r["case"] == case and r["filter"] == f]
        if any(b < a for a, b in zip(pd, pd[1:])):
            bad.append(f"ROC {case} {f} falls somewhere")
    mc = p["cases"][case]["monte_carlo"]
    if abs(mc["false_alarm"] - p["p_fa"]) > 4 * mc["false_alarm_sigma"]:
        bad.append(f"{case}: Monte Carlo false alarms {mc['false_alarm']}")
    if abs(mc["detection"] - p["p_d"]) > 4 * mc["detection_sigma"]:
        bad.append(f"{case}: Monte Carlo detections {mc['detection']}")
    # At an unknown place the slid filter's false alarms stay under Rice's bound (within 4 sampling errors).
    un = p["cases"][case]["unknown_place"]
    if not un["array_threshold"] > p["threshold"]:
        bad.append(f"{case}: the unknown place's threshold {un['array_threshold']} is not above {p['threshold']}")
    if un["monte_carlo"]["false_alarm"] > p["p_fa"] + 4 * un["monte_carlo"]["false_alarm_sigma"]:
        bad.append(f"{case}: slid filter false alarms {un['monte_carlo']['false_alarm']}")
# invert: the defect sweep's hole sits at the plate's origin (its centre is at u); the strongest feature
# comes back there within the sweep's step, the contact within one offset step of its place.
features = list(csv.DictReader(open(f"{tmp}/i/features.csv")))
if not features or list(features[0].keys()) != ["position_mm", "diameter_mm", "amplitude", "snr"]:
    bad.append("features.csv: no feature, or other columns")
else:
    strongest = max(features, key=lambda f: float(f["snr"]))
    if abs(float(strongest["position_mm"])) > 0.09 + 1e-9:
        bad.append(f"invert: the hole found at {strongest['position_mm']} mm, not 0")
    if abs(json.load(open(f"{tmp}/i/summary.json"))["contact_offset_mm"]) > 0.1 + 1e-9:
        bad.append("invert: the contact's offset is more than one step off")
# --dictionary: the reused dictionary (its 10 digits read back) gives the built one's features and offset.
reused = list(csv.DictReader(open(f"{tmp}/r/features.csv")))
rs = json.load(open(f"{tmp}/r/summary.json"))
if len(reused) != len(features) or any(abs(float(a[c]) - float(b[c])) > 1e-6 * max(1, abs(float(a[c])))
                                       for a, b in zip(features, reused) for c in a):
    bad.append("invert --dictionary: other features than the built dictionary's")
if rs["contact_offset_mm"] != json.load(open(f"{tmp}/i/summary.json"))["contact_offset_mm"]:
    bad.append("invert --dictionary: another offset")
if "dictionary_sweep" in rs["wall_s"] or rs["dictionary"].get("read_from") != f"{tmp}/i":
    bad.append(f"invert --dictionary: built it again, or did not say where it read it: {rs['wall_s']}")
# dictionary.csv: one row per virtual sensor and hole position, as summary.json counts them.
d = json.load(open(f"{tmp}/i/summary.json"))["dictionary"]
rows = list(csv.DictReader(open(f"{tmp}/i/dictionary.csv")))
if not rows or list(rows[0].keys()) != ["x_mm", "site_mm", "R_z_kPa", "R_x_kPa"]:
    bad.append("dictionary.csv: empty, or other columns")
elif len(rows) != d["virtual_sensors"] * d["hole_positions"]:
    bad.append(f"dictionary.csv: {len(rows)} rows for {d['virtual_sensors']} x {d['hole_positions']}")
for b in bad:
    print("FAIL", b)
sys.exit(1 if bad else 0)
PY
