#!/usr/bin/env bash
# An imported skin end to end: a closed STL box (16 × 16 × 3 mm, base on z = 0) through `kfit`, `green` and
# `solve`.
# Its thickness comes from the meshed top (3 mm exactly: flat faces), the calibration scan is shortened to
# stay on the box, and its k and solve's center_ratio (which divides by the skin's own h) agree with the exact
# infinite layer of the same thickness, as the same layer generated as a flat scene does.
set -u
skinfem=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 "$(dirname "$0")/box_stl.py" "$tmp/box.stl"
cat >"$tmp/box.json" <<'JSON'
{"geometry": {"type": "surface", "path": "box.stl"}, "material": {"E": 3.0, "nu": 0.5},
 "sensors": {"positions": [[0.0, 0.0]], "disc_diameter": 0.2},
 "mesh": {"h_min": 0.3, "growth": 1.6, "h_max": 2.0},
 "loads": {"punches": [{"center": [0.0, 0.0], "diameter": 0.5, "force": 1.0}]},
 "calibration": {"punch_diameter": 0.5, "spacing": 0.1}}
JSON
sed 's/{"type": "surface", "path": "box.stl"}/{"type": "flat", "h": 3.0, "half_width": 8.0}/' "$tmp/box.json" >"$tmp/flat.json"
fail=0
for run in "kfit box" "kfit flat" "green box" "solve box" "solve flat"; do
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
# Against the exact infinite layer of the same h (kfit's k_central_exact of the flat scene): within 2.5 %,
# the flat layer's FE error at 16k DOFs in docs/numerics.md's refinement table (these meshes have ~30k).
exact = flat["k_central_exact"]
for name, v in (("imported k_central", box["k_central"]), ("generated k_central", flat["k_central"])):
    print(f"{name} {v:.5f} against the exact layer's {exact:.5f} ({100 * (v / exact - 1):+.2f} %)")
    if abs(v / exact - 1) > 0.025: bad.append(f"{name} {v} is more than 2.5 % from the exact layer's {exact}")
if abs(green["sensors"][0]["h_mm"] - 3.0) > 1e-9: bad.append("green: thickness not from the mesh")
# solve's center_ratio divides by 3F/(2πh²) with the skin's own h (it once used 3.04 mm for any import).
cb = json.load(open(os.path.join(t, "solve_box", "summary.json")))["center_ratio"]
cf = json.load(open(os.path.join(t, "solve_flat", "summary.json")))["center_ratio"]
for name, v in (("imported center_ratio", cb), ("generated center_ratio", cf)):
    print(f"{name} {v:.5f} ({100 * (v / exact - 1):+.2f} %)")
    if abs(v / exact - 1) > 0.025: bad.append(f"{name} {v} is more than 2.5 % from the exact layer's {exact}")
for b in bad: print("FAIL", b)
sys.exit(1 if bad else 0)
PY
