#!/usr/bin/env bash
# Sliding along y reports the coupling's shift along y: a sphere on a square flat layer, coupled friction,
# sliding along +x and along +y. The square is symmetric under the 90° rotation that maps one onto the
# other, so the coupled − uncoupled pressure-centroid shift along the sliding direction must be the same
# (up to the two meshes' asymmetry: TetGen orients them differently, a few % of the shift) and the shift
# across it about zero. Before, summary.json gave the x component for both (−0.0002 mm along y against
# +0.063 mm in the per-mode centroids).
set -u
skinfem=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for d in "x 1.0 0.0" "y 0.0 1.0"; do
  set -- $d
  cat >"$tmp/$1.json" <<JSON
{"name": "slide_$1", "geometry": {"type": "flat", "h": 3.0, "half_width": 8.0},
 "material": {"E": 3.0, "nu": 0.5},
 "sensors": {"positions": [[0.0, 0.0]], "disc_diameter": 0.2},
 "mesh": {"h_min": 0.5, "growth": 1.6, "h_max": 2.5},
 "contact": {"indenter": {"type": "sphere", "R": 50.0, "center": [0.0, 0.0]}, "force": 0.3, "zone_radius": 2.0,
             "h": 0.4, "friction": {"mode": "coupled", "mu": 1.0, "direction": [$2, $3]}}}
JSON
  "$skinfem" contact "$tmp/$1.json" --out "$tmp/$1" >"$tmp/$1.out" 2>"$tmp/err" || { echo "FAIL contact $1:"; cat "$tmp/err"; exit 1; }
done
/usr/bin/python3 - "$tmp" <<'PY'
import json, sys
tmp = sys.argv[1]
c = {k: json.load(open(f"{tmp}/{k}/summary.json"))["coupled_minus_uncoupled"] for k in "xy"}
bad = []
along = {k: c[k]["pressure_centroid_shift_mm"] for k in "xy"}
across = {"x": c["x"]["pressure_centroid_shift_xy_mm"][1], "y": c["y"]["pressure_centroid_shift_xy_mm"][0]}
print(f"shift along the sliding direction: x {along['x']:+.5f} mm, y {along['y']:+.5f} mm; across: {across}")
if not along["x"] > 0: bad.append(f"sliding along x: the pressure centroid does not move ahead ({along['x']})")
if not abs(along["y"] / along["x"] - 1) < 0.1: bad.append(f"along y {along['y']} vs along x {along['x']}: more than 10 % apart")
for k in "xy":
    if not abs(across[k]) < 0.1 * along["x"]: bad.append(f"sliding along {k}: shift across {across[k]}")
    xy = c[k]["pressure_centroid_shift_xy_mm"]
    d = c[k]["direction"]
    if abs(xy[0] * d[0] + xy[1] * d[1] - along[k]) > 1e-12: bad.append(f"{k}: the shift along is not the vector's projection")
for b in bad: print("FAIL", b)
sys.exit(1 if bad else 0)
PY
