#!/usr/bin/env bash
# An imported skin end to end: a closed STL box (16 × 16 × 3 mm, base on z = 0) through `kfit` and `green`.
# Its thickness comes from the meshed top (3 mm exactly: flat faces), the calibration scan is shortened to
# stay on the box, and its k equals that of the same layer generated as a flat scene (a second meshing path
# inside skinfem) within 1.5 %: at this resolution both lie within 0.8 % of the exact infinite layer
# (1.5494), so two meshes of one geometry differ by at most about twice that.
set -u
skinfem=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 "$(dirname "$0")/box_stl.py" "$tmp/box.stl"
cat >"$tmp/box.json" <<'JSON'
{"geometry": {"type": "surface", "path": "box.stl"}, "material": {"E": 3.0, "nu": 0.5},
 "sensors": {"positions": [[0.0, 0.0]], "disc_diameter": 0.2},
 "mesh": {"h_min": 0.3, "growth": 1.6, "h_max": 2.0},
 "calibration": {"punch_diameter": 0.5, "spacing": 0.1}}
JSON
sed 's/{"type": "surface", "path": "box.stl"}/{"type": "flat", "h": 3.0, "half_width": 8.0}/' "$tmp/box.json" >"$tmp/flat.json"
fail=0
for run in "kfit box" "kfit flat" "green box"; do
  set -- $run
  if ! "$skinfem" "$1" "$tmp/$2.json" --out "$tmp/$1_$2" >/dev/null 2>"$tmp/err"; then
    echo "FAIL $run:"; cat "$tmp/err"; fail=1
  fi
done
[ $fail -eq 0 ] || exit 1
/usr/bin/python3 - "$tmp" <<'PY'
import json, os, sys
t = sys.argv[1]
box = json.load(open(os.path.join(t, "kfit_box", "kfit.json")))
flat = json.load(open(os.path.join(t, "kfit_flat", "kfit.json")))
green = json.load(open(os.path.join(t, "green_box", "summary.json")))
bad = []
h = box["sensors"][0]["h_mm"]
if abs(h - 3.0) > 1e-9: bad.append(f"thickness from the meshed top {h}, expected 3")
w = box["sensors"][0]["scan_half_width_mm"]
if not 7.75 - 0.2 < w <= 7.75: bad.append(f"scan half-width {w}: should stop within a step of 8 - 0.25")
for k in ("k_central", "k_lsq_line"):
    r = box[k] / flat[k] - 1
    print(f"{k}: imported {box[k]:.5f}, generated {flat[k]:.5f} ({100 * r:+.2f} %)")
    if abs(r) > 0.015: bad.append(f"{k} of the imported box differs from the flat scene's by {100 * r:.2f} %")
if abs(green["sensors"][0]["h_mm"] - 3.0) > 1e-9: bad.append("green: thickness not from the mesh")
for b in bad: print("FAIL", b)
sys.exit(1 if bad else 0)
PY
