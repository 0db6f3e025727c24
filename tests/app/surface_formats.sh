#!/usr/bin/env bash
# Imported surfaces in every supported format and as exporters write them: the 16 x 16 x 3 mm box as ASCII
# STL, OBJ and OFF, with each triangle's points repeated (OBJ/OFF), orientations mixed, or all inward. Each
# must mesh to the box's volume, 768 mm3 (flat faces: the P2 volume is exact up to round-off).
set -u
skinfem=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
for variant in "box.stl" "inward.stl --inward" "mixed.stl --mixed" "box.obj" "unshared.obj --unshared" \
  "mixed.obj --mixed" "unshared_mixed.off --unshared --mixed" "inward.off --inward"; do
  set -- $variant
  /usr/bin/python3 "$(dirname "$0")/box_stl.py" "$tmp/$@"
  cat >"$tmp/scene.json" <<JSON
{"geometry": {"type": "surface", "path": "$1"}, "material": {"E": 3.0, "nu": 0.5},
 "sensors": {"positions": [[0.0, 0.0]], "disc_diameter": 0.2}, "mesh": {"h_min": 1.0, "growth": 1.6, "h_max": 3.0}}
JSON
  rm -rf "$tmp/out"
  if ! "$skinfem" mesh "$tmp/scene.json" --out "$tmp/out" >/dev/null 2>"$tmp/err"; then
    echo "FAIL $variant:"; cat "$tmp/err"; fail=1; continue
  fi
  /usr/bin/python3 - "$tmp/out/summary.json" "$variant" <<'PY' || fail=1
import json, sys
v = json.load(open(sys.argv[1]))["volume_mm3"]
print(f"{sys.argv[2]}: volume {v:.12f} mm3")
if abs(v / 768 - 1) > 1e-12:
    print(f"FAIL {sys.argv[2]}: volume {v}, expected 768"); sys.exit(1)
PY
done
exit $fail
