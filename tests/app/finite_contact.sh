#!/usr/bin/env bash
# `skinfem contact` on the neo-Hookean skin: a plate on a small strongly curved cap (R = 20 mm), solved on its
# half and reported whole. Checks what the command adds to the library's solve (contact/finite_contact.hpp,
# whose physics tests/contact/test_finite_contact.cpp checks): the mirror image's forces, frames and files.
# - Global balance: the base takes back the whole plate's force, friction included, to Newton's tolerance
#   (1e-10 relative): a half counted once, or a sign, would be off by 50 % or 200 %.
# - Symmetry: the whole zone's centroids lie on y = 0.
# - The files: fields.vtu on the whole mesh, pressure.vtp, sensors.csv.
# - A sphere sliding on a flat layer (Coulomb, mu = 1): the base takes back the sphere's summed load (its
#   pressures and drag turn with the surface), its vertical part the force; the drag along x is mu F within
#   (1 + mu) F a/R (the normals' horizontal parts and the drag's tilt, each at most the slope a/R).
# With --against-linear (Release): coupled sliding at mu = 1, against `skinfem contact` on the linear skin (an
# independent path: condensation and the complementarity solve on the small-strain skin, readings by adjoint
# solves). Finite strain changes the contact at first order in the strain scale a/R (the library's
# SmallForcesTendToTheLinearContactAtFirstOrder), so the indentation and every reading must agree within
# a/R relative (a = the contact's area-equivalent radius, 0.96 mm: 4.8 %); the surface moves ahead under the
# traction, so the current frame's force centroid lies ahead of the reference one by at most the largest
# tangential displacement. Then `skinfem defect` about that sliding state and the state at rest (static_ratio
# 0.3; 25 hole positions each; with the sliding state's error bars, whose values must be its own): the tangent's
# own hole-free contact is the finite one (to 1e-9 of the largest pressure: the tangent's gaps are built to
# have it as their solution, so a wrong mirror view or zone would show), each hole acts on material behind
# its centre, by about the largest tangential displacement of the zone's vertices (within 10 %: the top's
# quadratic interpolation between them and u_y add to it), and complementarity holds at every position. (The
# signals' change against the linear skin's has no bound of this kind: it is the surface's shear strain
# μ p / G, 10 % here; pipeline_test_finite_defect checks them against full finite solves.) Then `skinfem
# report` of the same neo-Hookean scene (no error bars): its finite section's readings and hole amplitudes are
# the commands' (finite: `contact`, `defect`; linear: `defect` on the linear skin) to 1e-9, on one mesh, its
# budget ends with the coulomb_finite and shear_strength_finite rows, and the page and figure show them; the
# report's shear-strength sliding state is `contact`'s on the scene with that law (tau0 = mu F / A), whose
# base takes back its tangential force to 1e-9. The sanitizer pass runs the frictionless contact alone (the
# same code).
set -u
skinfem=$1
against=${2:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mode=none
[ "$against" = --against-linear ] && mode=coupled
scene() {  # MODEL FILE
  cat >"$2" <<JSON
{"name": "plate_cap", "geometry": {"type": "cap", "R": 20.0, "h": 3.0, "apex": [0.0, 0.0], "truncation_radius": 6.0},
 "material": {"E": 3.0, "nu": 0.5, "model": "$1"},
 "sensors": {"positions": [[0.0, 0.0], [1.0, 0.0]], "disc_diameter": 0.2},
 "mesh": {"h_min": 0.5, "growth": 1.8, "h_max": 1.5, "refine_sensors": false},
 "contact": {"indenter": {"type": "plane"}, "force": 0.3, "zone_radius": 2.0, "h": 0.5,
             "friction": {"mode": "$mode", "mu": 1.0, "static_ratio": 0.3, "direction": [1.0, 0.0]}}}
JSON
}
scene neo_hookean "$tmp/neo.json"
"$skinfem" contact "$tmp/neo.json" --out "$tmp/neo" >"$tmp/neo.out" 2>"$tmp/err" || { echo "FAIL neo_hookean contact:"; cat "$tmp/err"; exit 1; }
cat "$tmp/neo.out"
# A sphere (R = 20 mm) sliding on a flat layer: its pressures push along the turning normals and its drag
# along the turning tangents, so the balance is against their summed load, horizontal parts included.
cat >"$tmp/sphere.json" <<JSON
{"name": "sphere_layer", "geometry": {"type": "flat", "h": 3.0, "half_width": 5.0, "side": "free"},
 "material": {"E": 3.0, "nu": 0.5, "model": "neo_hookean"},
 "sensors": {"positions": [[0.0, 0.0], [1.0, 0.0]], "disc_diameter": 0.2},
 "mesh": {"h_min": 0.5, "growth": 1.8, "h_max": 1.5, "refine_sensors": false},
 "contact": {"indenter": {"type": "sphere", "R": 20.0, "center": [0.0, 0.0]}, "force": 0.3, "zone_radius": 1.5,
             "h": 0.5, "friction": {"mode": "coupled", "mu": 1.0}}}
JSON
"$skinfem" contact "$tmp/sphere.json" --out "$tmp/sphere" >"$tmp/sphere.out" 2>"$tmp/err" || { echo "FAIL sphere contact:"; cat "$tmp/err"; exit 1; }
cat "$tmp/sphere.out"
if [ -n "$against" ]; then
  scene linear "$tmp/lin.json"
  "$skinfem" contact "$tmp/lin.json" --out "$tmp/lin" >"$tmp/lin.out" 2>"$tmp/err" || { echo "FAIL linear contact:"; cat "$tmp/err"; exit 1; }
  for model in neo lin; do
    /usr/bin/python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); d["contact"]["sweep"] = {"from": [-1.2, 0.0], "to": [1.2, 0.0], "positions": 25, "hole_diameter": 0.5, "h": 0.5}; json.dump(d, open(sys.argv[2], "w"))' "$tmp/$model.json" "$tmp/${model}_sweep.json"
    bars=--no-error-bars
    [ $model = neo ] && bars=  # the finite sliding state's error bars: two coarser levels of this coarse cap
    "$skinfem" defect "$tmp/${model}_sweep.json" $bars --out "$tmp/${model}_defect" >"$tmp/${model}_defect.out" 2>"$tmp/err" || { echo "FAIL $model defect:"; cat "$tmp/err"; exit 1; }
  done
  cat "$tmp/neo_defect.out"
  /usr/bin/python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); d["contact"]["friction"]["law"] = "shear_strength"; json.dump(d, open(sys.argv[2], "w"))' "$tmp/neo.json" "$tmp/shear.json"
  "$skinfem" contact "$tmp/shear.json" --out "$tmp/shear" >"$tmp/shear.out" 2>"$tmp/err" || { echo "FAIL shear-strength contact:"; cat "$tmp/err"; exit 1; }
  cat "$tmp/shear.out"
  "$skinfem" report "$tmp/neo_sweep.json" --no-error-bars --out "$tmp/report" >"$tmp/report.out" 2>"$tmp/err" || { echo "FAIL neo_hookean report:"; cat "$tmp/err"; exit 1; }
fi
/usr/bin/python3 - "$tmp" "$against" <<'PY'
import csv, json, os, re, sys
tmp, against = sys.argv[1], sys.argv[2]
s = json.load(open(f"{tmp}/neo/summary.json"))
bad = []
F, T = s["force_N"], s["tangential_force_N"]
base = s["base_force_N"]
held = [-T, 0.0, F]  # the base holds the skin against the plate's (T, 0, -F)
err = sum((b - h) ** 2 for b, h in zip(base, held)) ** 0.5 / (F * F + T * T) ** 0.5
print(f"base force {base} against {held}: {err:.1e}")
if not err < 1e-9: bad.append(f"global balance {err:.1e}")
for frame in ("reference_frame", "current_frame"):
    for key in ("zone_centroid_mm", "force_centroid_mm"):
        if abs(s[frame][key][1]) > 1e-12: bad.append(f"{frame}.{key} off y = 0: {s[frame][key]}")
for step in s["newton"]["steps"]:
    if not step["residuals"][-1] < 1e-7: bad.append(f"a step ended at residual {step['residuals'][-1]}")
vtu = open(f"{tmp}/neo/fields.vtu", "rb").read(4000).decode("latin-1")
m = re.search(r'NumberOfPoints="(\d+)"', vtu)
if not m or int(m.group(1)) != s["nodes"]: bad.append(f"fields.vtu points {m and m.group(1)} against {s['nodes']} nodes")
if not os.path.getsize(f"{tmp}/neo/pressure.vtp") > 0: bad.append("pressure.vtp empty")
sp = json.load(open(f"{tmp}/sphere/summary.json"))
print(f"sphere: base force balance {sp['base_force_balance_rel']:.1e}, indentation {sp['indentation_um']:.3f} um")
if sp["indenter"] != "sphere": bad.append(f"sphere summary says indenter {sp['indenter']}")
if not sp["base_force_balance_rel"] < 1e-9: bad.append(f"sphere balance {sp['base_force_balance_rel']:.1e}")
if abs(sp["base_force_N"][2] - sp["force_N"]) > 1e-8 * sp["force_N"]: bad.append(f"sphere vertical force {sp['base_force_N']}")
Fs, Ts, a = sp["force_N"], sp["tangential_force_N"], sp["reference_frame"]["equivalent_radius_mm"]
print(f"sphere: drag {Ts:.5f} N against mu F = {Fs:.5f} N, bound (1 + mu) F a/R = {2 * Fs * a / 20:.5f} N")
if abs(sp["base_force_N"][0] + Ts) > 1e-8 * Fs: bad.append(f"sphere drag {Ts} against the base's {sp['base_force_N']}")
if not abs(Ts - Fs) < 2 * Fs * a / 20: bad.append(f"sphere drag {Ts} beyond mu F's bound")
if against:
    lin = json.load(open(f"{tmp}/lin/summary.json"))
    bound = s["reference_frame"]["equivalent_radius_mm"] / 20.0
    d = s["indentation_um"] / lin["indentation_um"] - 1
    print(f"a/R = {bound:.4f}; indentation {s['indentation_um']:.4f} against {lin['indentation_um']:.4f} um ({d:+.2e})")
    if not abs(d) < bound: bad.append(f"indentation {d:+.2e} beyond a/R")
    rows = lambda k: list(csv.DictReader(open(f"{tmp}/{k}/sensors.csv")))
    scale = max(abs(float(r[c])) for r in rows("lin") for c in ("sigma_z_kPa", "sigma_x_kPa"))
    for a, b in zip(rows("neo"), rows("lin")):
        for c in ("sigma_z_kPa", "sigma_x_kPa"):
            g = (float(a[c]) - float(b[c])) / scale
            print(f"sensor {a['sensor']} {c}: {float(a[c]):.4f} against {float(b[c]):.4f} ({g:+.2e} of the largest)")
            if not abs(g) < bound: bad.append(f"sensor {a['sensor']} {c} beyond a/R")
    ahead = s["frame_shift_mm"]["force_centroid"][0]
    print(f"force centroid ahead in the current frame by {ahead:.4f} mm, largest u_t {s['max_tangential_displacement_mm']:.4f} mm")
    if not 0 < ahead <= s["max_tangential_displacement_mm"]: bad.append(f"frame shift {ahead}")
    d = json.load(open(f"{tmp}/neo_defect/summary.json"))
    dl = json.load(open(f"{tmp}/lin_defect/summary.json"))
    peak = lambda case: max(x["peak_abs_varsigma_z_kPa"] for x in case["sensors"])
    if sorted(d["cases"]) != ["sliding", "static"]: bad.append(f"defect cases {sorted(d['cases'])}")
    for name, c in d["cases"].items():
        shift, ut = c["largest_material_shift_mm"], c["state"]["max_tangential_displacement_mm"]
        print(f"defect {name} (ratio {c['ratio']}): tangent baseline {c['tangent_baseline_rel']:.1e}, material shift {shift:.4f} mm against the largest u_t {ut:.4f} mm")
        if not c["tangent_baseline_rel"] < 1e-9: bad.append(f"{name} tangent baseline {c['tangent_baseline_rel']}")
        if not 0.9 * ut < shift < 1.1 * ut: bad.append(f"{name} material shift {shift} against {ut}")
        if not c["max_complementarity"] < 1e-12: bad.append(f"{name} complementarity {c['max_complementarity']}")
        g = peak(c) / peak(dl["cases"][name]) - 1
        print(f"largest {name} |varsigma_z|: {peak(c):.4f} against the linear skin's {peak(dl['cases'][name]):.4f} kPa ({g:+.2e})")
    # The error bars are the sliding state's own numbers, with their levels coarse to fine.
    bars = {b["quantity"]: b for b in d["error_bars"]}
    sl = d["cases"]["sliding"]
    for q, want in (("hole_signal", peak(sl)), ("indentation", sl["state"]["indentation_um"])):
        if abs(bars[q]["value"] - want) > 1e-9 * want: bad.append(f"error bar {q} {bars[q]['value']} against {want}")
    if sorted(bars) != ["contact_p0", "contact_radius", "hole_signal", "indentation"]: bad.append(f"error bars {sorted(bars)}")
    if not all(0 <= b["error"] < b["value"] for b in bars.values()): bad.append(f"error bars {bars}")
    if [l["scale"] for l in d["levels"]] != [2, 1.41, 1] or not d["levels"][0]["dofs"] < d["levels"][1]["dofs"] < d["levels"][2]["dofs"]: bad.append(f"levels {d['levels']}")
    # At rest the plate pulls less (0.3 p against p), so the surface moves less: its state's u_t is smaller.
    ut = {n: c["state"]["max_tangential_displacement_mm"] for n, c in d["cases"].items()}
    if not ut["static"] < ut["sliding"]: bad.append(f"u_t at rest {ut['static']} not below sliding {ut['sliding']}")
    # The report of the neo-Hookean scene: its finite section is the commands' finite and linear runs again.
    r = json.load(open(f"{tmp}/report/report.json"))
    fd = r["finite_deformation"]
    if not fd["same_mesh"]: bad.append("the report's linear and finite skins differ")
    for row, finite in zip(fd["cases"]["sliding"]["readings"], rows("neo")):
        for c in ("sigma_z_kPa", "sigma_x_kPa"):
            if abs(row[c]["finite"] - float(finite[c])) > 1e-9 * scale: bad.append(f"report sensor {row['sensor']} {c} {row[c]['finite']} against contact's {finite[c]}")
    for name in ("static", "sliding"):
        for a, f, l in zip(fd["cases"][name]["hole_amplitudes"], d["cases"][name]["sensors"], dl["cases"][name]["sensors"]):
            for got, want in ((a["z"]["finite_kPa"], f["peak_abs_varsigma_z_kPa"]), (a["z"]["linear_kPa"], l["peak_abs_varsigma_z_kPa"])):
                if abs(got - want) > 1e-9 * want: bad.append(f"report {name} sensor {a['sensor']} amplitude {got} against defect's {want}")
    print(f"report: {fd['answer']}")
    finite_rows = [h for h in r["hole_budget"]["hypotheses"] if h["name"].endswith("_finite")]
    if [h["name"] for h in finite_rows] != ["coulomb_finite", "shear_strength_finite"]: bad.append(f"finite budget rows {[h['name'] for h in finite_rows]}")
    for row in finite_rows:
        if row["facts_met"] != sum(v["met"] for v in row["facts"].values()): bad.append(f"budget row {row['name']} facts")
    sh, ss = fd["shear_strength"], json.load(open(f"{tmp}/shear/summary.json"))
    print(f"shear strength: tau0 {ss['tau_kPa']:.4f} kPa, {ss['tangential_force_N']:.6f} N tangential, base balance {ss['base_force_balance_rel']:.1e}; report {sh['tau0_kPa']:.4f} kPa, {sh['tangential_force_N']:.6f} N")
    if not ss["base_force_balance_rel"] < 1e-9: bad.append(f"shear-strength balance {ss['base_force_balance_rel']:.1e}")
    for got, want in ((sh["tau0_kPa"], ss["tau_kPa"]), (sh["tangential_force_N"], ss["tangential_force_N"]), (sh["indentation_um"], ss["indentation_um"])):
        if abs(got - want) > 1e-9 * abs(want): bad.append(f"report's shear-strength state {got} against contact's {want}")
    if "Does finite deformation matter at the paper's load?" not in open(f"{tmp}/report/index.html").read(): bad.append("page lacks the finite section")
    if not os.path.getsize(f"{tmp}/report/figures/budget_coulomb_finite.png") > 0: bad.append("no budget_coulomb_finite.png")
for b in bad: print("FAIL", b)
sys.exit(1 if bad else 0)
PY
