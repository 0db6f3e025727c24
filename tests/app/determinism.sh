#!/usr/bin/env bash
# Every command twice on one scene (a coarse cap with a punch, a plate, friction and a short hole sweep):
# the outputs must be the same bytes, apart from the wall-clock and memory figures of the JSON summaries.
set -u
skinfem=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/scene.json" <<'JSON'
{"name": "coarse_cap",
 "geometry": {"type": "cap", "R": 129.7, "h": 3.04, "apex": [0.5, 0.0], "truncation_radius": 12.0},
 "material": {"E": 3.0, "nu": 0.5},
 "sensors": {"positions": [[-1.5, 0.0], [0.5, 0.0], [2.5, 0.0]], "disc_diameter": 0.2},
 "mesh": {"h_min": 0.6, "growth": 1.7, "h_max": 3.0},
 "loads": {"punches": [{"center": [0.5, 0.0], "diameter": 0.5, "force": 1.0}]},
 "calibration": {"punch_diameter": 0.5, "spacing": 0.2},
 "contact": {"indenter": {"type": "plane"}, "force": 0.8, "zone_radius": 4.0, "h": 0.8,
             "friction": {"mode": "coupled", "mu": 3.0, "static_ratio": 0.1},
             "sweep": {"from": [-2.0, 0.0], "to": [3.0, 0.0], "positions": 7, "hole_diameter": 0.8}}}
JSON
fail=0
for cmd in mesh solve green kfit contact defect; do
  for run in 1 2; do
    extra=(); [ $cmd = green ] && extra=(--grid 0.25)  # and the kernel export (HDF5, VTI)
    if ! "$skinfem" $cmd "$tmp/scene.json" --out "$tmp/$cmd.$run" "${extra[@]}" >/dev/null 2>"$tmp/err"; then
      echo "FAIL $cmd run $run:"; cat "$tmp/err"; fail=1
    fi
  done
done
[ $fail -eq 0 ] || exit 1
/usr/bin/python3 - "$tmp" <<'PY' || fail=1
import json, os, sys
tmp = sys.argv[1]
def timeless(node):
    # Wall-clock and memory figures differ between runs by nature; everything else must not.
    if isinstance(node, dict):
        return {k: timeless(v) for k, v in node.items()
                if not (k.endswith(("_s", "seconds")) or "wall" in k or "rss" in k or k.startswith("ms_") or "_ms" in k)}
    if isinstance(node, list):
        return [timeless(v) for v in node]
    return node
bad = compared = 0
for cmd in ["mesh", "solve", "green", "kfit", "contact", "defect"]:
    a, b = os.path.join(tmp, cmd + ".1"), os.path.join(tmp, cmd + ".2")
    for root, _, files in os.walk(a):
        for f in files:
            pa = os.path.join(root, f)
            pb = os.path.join(b, os.path.relpath(pa, a))
            if not os.path.exists(pb):
                print(f"FAIL {cmd}: {os.path.relpath(pa, a)} missing in the second run"); bad += 1; continue
            if f.endswith(".json"):
                same = timeless(json.load(open(pa))) == timeless(json.load(open(pb)))
            else:
                same = open(pa, "rb").read() == open(pb, "rb").read()
            compared += 1
            if not same:
                print(f"FAIL {cmd}: {os.path.relpath(pa, a)} differs between two runs"); bad += 1
print(f"{compared} files compared, {bad} differ")
sys.exit(1 if bad or compared < 15 else 0)
PY
exit $fail
