#!/usr/bin/env bash
# `skinfem contact --path auto|meridian|3d`: the automatic path takes the meridian where every mode contact
# reports is exact there (scenes/hertz_layer.json, frictionless) and says why not elsewhere; an explicit
# meridian run on the default scene solves the frictionless and uncoupled modes and leaves out the static and
# coupled ones, which it names; with --against-3d (Release: two 3D contacts of the default scene) the
# meridian's readings of every sensor and its contact radius, central pressure and indentation are checked
# against the 3D path's, within the 3D path's own error against the exact layer (tests/contact/
# test_contact_fe.cpp: a 2.5 %, p0 1 %, indentation 0.2 %; readings 0.1 % of the peak, README) plus the
# meridian's (tests/contact/test_meridian_contact.cpp: 0.05 % and 1e-4 of the peak).
set -u
skinfem=$1
against_3d=${2:-}
here=$(cd "$(dirname "$0")" && pwd)
scenes=$here/../../scenes
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() {  # name, args...
  local name=$1
  shift
  "$skinfem" contact "$@" --out "$tmp/$name" >"$tmp/$name.out" 2>"$tmp/$name.err" || {
    echo "FAIL contact $name:"; cat "$tmp/$name.err"; exit 1; }
}
run hertz_auto "$scenes/hertz_layer.json"
run cap_meridian "$scenes/candelier2011.json" --friction uncoupled --path meridian
"$skinfem" contact "$scenes/candelier2011.json" --path meridian --out "$tmp/refused" >/dev/null 2>"$tmp/refused.err"
code=$?
if [ -n "$against_3d" ]; then
  run cap_3d "$scenes/candelier2011.json" --friction uncoupled --path 3d
fi
/usr/bin/python3 - "$tmp" "$code" "$against_3d" <<'PY'
import csv, json, os, sys
tmp, code, against = sys.argv[1], int(sys.argv[2]), sys.argv[3]
bad = []
h = json.load(open(f"{tmp}/hertz_auto/summary.json"))
if h["path"] != "meridian": bad.append(f"hertz_layer, --path auto: path {h['path']}, expected meridian")
if h["left_out"]: bad.append(f"hertz_layer is frictionless, yet modes are left out: {h['left_out']}")
if sorted(h["modes"]) != ["coupled", "none", "static", "uncoupled"]: bad.append(f"hertz_layer modes {sorted(h['modes'])}")
if abs(h["force_N"] - 0.8) > 1e-9: bad.append(f"hertz_layer force {h['force_N']}")
if h["complementarity"] > 1e-10: bad.append(f"complementarity {h['complementarity']}")
rows = list(csv.DictReader(open(f"{tmp}/hertz_auto/pressure.csv")))
p = [float(r["pressure_kPa"]) for r in rows]
if min(p) < 0 or abs(p[0] - h["p0_kPa"]) > 1e-9 * h["p0_kPa"]: bad.append("pressure.csv: negative or not p0 on the axis")
m = json.load(open(f"{tmp}/cap_meridian/summary.json"))
if m["path"] != "meridian" or sorted(m["left_out"]) != ["coupled", "static"]:
    bad.append(f"default scene, --path meridian: path {m['path']}, left out {m['left_out']}")
out = open(f"{tmp}/cap_meridian.out").read()
if "left out" not in out or "static, coupled" not in out: bad.append("the left-out modes are not said")
err = open(f"{tmp}/refused.err").read().strip()
if code != 2 or "contact.friction.mu = 3" not in err or len(err.splitlines()) != 1:
    bad.append(f"the coupled default scene on the meridian: exit {code}, '{err}'")
if os.path.exists(f"{tmp}/refused"): bad.append("the refused run wrote output")
print(f"hertz_layer on the meridian: a = {h['contact_radius_mm']:.5f} mm, p0 = {h['p0_kPa']:.4f} kPa, "
      f"{h['dofs']} DOFs, {h['wall_total_s']:.2f} s, {h['peak_rss_mb']:.0f} MB")
if against:
    d = json.load(open(f"{tmp}/cap_3d/summary.json"))
    if d["path"] != "3d": bad.append("--path 3d did not run the 3D path")
    for key, tol in (("contact_radius_mm", 0.025 + 5e-4), ("p0_kPa", 0.01 + 5e-4), ("indentation_um", 0.002 + 5e-4)):
        dev = abs(m[key] / d[key] - 1)
        print(f"{key}: meridian {m[key]:.6g}, 3D {d[key]:.6g}, {dev:.2e} apart (bound {tol:.3g})")
        if dev > tol: bad.append(f"{key} {dev:.2e} apart")
    fe = {r["sensor"]: r for r in csv.DictReader(open(f"{tmp}/cap_3d/sensors.csv"))}
    mr = {r["sensor"]: r for r in csv.DictReader(open(f"{tmp}/cap_meridian/sensors.csv"))}
    peak = max(abs(float(r[c])) for r in fe.values() for c in ("sigma_z_kPa", "sigma_x_kPa"))
    worst = max(abs(float(mr[k][c]) - float(fe[k][c])) for k in fe for c in ("sigma_z_kPa", "sigma_x_kPa"))
    print(f"readings, uncoupled (mu 3), every sensor: largest difference {worst:.4f} kPa = {worst / peak:.2e} of the peak {peak:.3f} kPa (bound 1.1e-3)")
    if worst > 1.1e-3 * peak: bad.append(f"readings {worst / peak:.2e} of the peak apart")
for b in bad: print("FAIL", b)
sys.exit(1 if bad else 0)
PY
