#!/usr/bin/env bash
# The Green kernel export (skinfem green --grid) and the h5py snippet of docs/kernels.md: the snippet, run as
# written on the exported kernel, must give the sensor reading that skinfem's own FE solve of the same load
# gives (reciprocity: the solve and the kernel are the same FE field, so only the grid's quadrature differs).
# Tolerance 0.25 %: a study on this scene at DX = 0.1, 0.05, 0.025 mm gave errors 0.26 %, 0.064 %, 0.022 % for
# σ_z (second order down to the FE load quadrature's 0.02–0.04 % floor); 0.25 % is 4× the DX = 0.05 error.
# Also: the HDF5 attributes (units, convention, sensor positions), the VTI arrays, and a too-fine grid
# refused before meshing. green takes the 3D path on the whole skin (`--path 3d`, "symmetry": "none") so that
# green and solve share one mesh; the half mesh's kernel equals the whole body's to round-off
# (tests/green/test_mirror_symmetry.cpp), the meridian path's is checked in tests/app/kfit_paths.sh.
set -u
skinfem=$(realpath "$1")
doc=$(realpath "$(dirname "$0")/../../docs/kernels.md")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cat >scene.json <<'JSON'
{"name": "kernel_layer", "symmetry": "none",
 "geometry": {"type": "flat", "h": 3.0, "half_width": 8.0},
 "material": {"E": 3.0, "nu": 0.5},
 "sensors": {"positions": [[0.0, 0.0], [1.5, 0.0]], "disc_diameter": 0.2},
 "mesh": {"h_min": 0.4, "growth": 1.5, "h_max": 3.0},
 "loads": {"patches": [{"center": [1.0, 0.0], "diameter": 1.0, "force": 0.01, "direction": [0, 0, -1]}]},
 "calibration": {"punch_diameter": 0.5, "spacing": 0.1}}
JSON
"$skinfem" green scene.json --path 3d --grid 0.05 --out out/green >green.log 2>&1 || { echo "FAIL green --grid:"; cat green.log; exit 1; }
"$skinfem" solve scene.json --out out/solve >solve.log 2>&1 || { echo "FAIL solve:"; cat solve.log; exit 1; }
# docs/kernels.md's block after the kernel-snippet marker, exactly as a reader would copy it.
awk '/<!-- kernel-snippet/ {on = 1; next} on && /^```python/ {inside = 1; next} inside && /^```/ {exit} inside' \
  "$doc" >snippet.py
[ -s snippet.py ] || { echo "FAIL: no kernel snippet found in $doc"; exit 1; }
/usr/bin/python3 snippet.py >snippet.out 2>&1 || { echo "FAIL snippet:"; cat snippet.out; exit 1; }
/usr/bin/python3 - <<'PY'
import csv, h5py, json, re, sys
m = re.search(r"sigma_z = (\S+) MPa, sigma_x = (\S+) MPa", open("snippet.out").read())
if not m:
    sys.exit("FAIL: snippet printed " + open("snippet.out").read())
snip = {"z": float(m.group(1)), "x": float(m.group(2))}
row = next(r for r in csv.DictReader(open("out/solve/sensors.csv")) if r["sensor"] == "1")
fe = {"z": 1e-3 * float(row["sigma_z_kPa"]), "x": 1e-3 * float(row["sigma_x_kPa"])}
bad = 0
for c in "zx":
    rel = abs(snip[c] - fe[c]) / abs(fe[c])
    ok = rel < 2.5e-3
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} sigma_{c}: snippet {snip[c]:.8g} MPa, FE solve {fe[c]:.8g} MPa, rel {rel:.2e}")
with h5py.File("out/green/kernel.h5") as f:
    for key in ("units", "convention", "grid_spacing_mm", "disc_diameter_mm"):
        if key not in f.attrs:
            print("FAIL kernel.h5 lacks attribute", key); bad += 1
    scene = json.load(open("scene.json"))
    for s, pos in enumerate(scene["sensors"]["positions"]):
        got = list(f[f"sensor{s + 1:02d}"].attrs["position_mm"])
        if got != pos:
            print("FAIL sensor", s + 1, "position_mm", got, "!=", pos); bad += 1
    nx, ny = len(f["x_mm"]), len(f["y_mm"])
    if (nx, ny) != (321, 321) or f["on_skin"][:].min() != 1:
        print("FAIL grid", nx, ny, "expected 321 x 321 points, all on the 16 mm square"); bad += 1
    if abs(f["x_mm"][1] - f["x_mm"][0] - 0.05) > 1e-12 or abs(f["x_mm"][160]) > 1e-12:
        print("FAIL grid spacing or centring"); bad += 1
vti = open("out/green/kernel.vti", "rb").read()
for name in (b"on_skin", b"g_zz_sensor01_per_mm2", b"g_xx_sensor02_per_mm2"):
    if b'Name="' + name + b'"' not in vti:
        print("FAIL kernel.vti lacks", name.decode()); bad += 1
sys.exit(1 if bad else 0)
PY
rc=$?
# A grid too fine for memory: one line naming --grid, exit 2, before meshing, nothing written.
"$skinfem" green scene.json --grid 0.001 --out out/fine >fine.out 2>fine.err
code=$?
if [ $code -ne 2 ] || ! grep -q -- '--grid = 0.001: .*allowed at most' fine.err || [ -e out/fine ]; then
  echo "FAIL --grid 0.001: exit $code"; cat fine.err; rc=1
fi
exit $rc
