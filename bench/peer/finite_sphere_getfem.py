#!/usr/bin/python3
"""Peer benchmark (issue 54 item 6): the finite-strain sphere indentation by skinfem and by GetFEM.

The problem is bench/peer/finite_sphere.json: a rigid frictionless sphere (R = 10 mm) pressed with a force F
on an incompressible neo-Hookean layer (W = mu/2 (I1 - 3), mu = E/3, E = 3 MPa), h = 3.04 mm, bonded to a
rigid base (u = 0 at z = 0), top free at z = h, sides free, laterally a square of half width 30 mm. Units mm,
N, MPa. At the largest force, 35 N, the approach is delta = 0.664 mm, delta/h = 0.218, a = 3.50 mm (a/h =
1.15), the hoop stretch at the contact's edge a/a_ref = 1.055, the peak contact pressure 1.96 MPa ~ 2 mu.

Rows of the table (each run its own subprocess: its wall seconds and its own peak RSS from os.wait4):
  skinfem finite   `skinfem contact SCENE --path 3d` with "model": "neo_hookean" (total Lagrangian, the
                   contact in the current configuration along the sphere's normal, force controlled);
                   one run per force and per mesh level (contact.h and mesh.h_min scaled by --levels)
  skinfem linear   the same scene and meshes with "model": "linear" (small strain; the gap vertical, in the
                   reference configuration, to the exact sphere R - sqrt(R^2 - r^2))
  GetFEM finite    the meridian (r, z) of the layer, a disc of the scene's half width (30 mm, traction free
                   at its rim), TOTAL LAGRANGIAN incompressible neo-Hookean in GetFEM's weak form language,
                   every term x 2 pi r: F = I + Grad u in the meridian, the hoop stretch 1 + u_r/r, I1 = F:F +
                   (1 + u_r/r)^2, J = det F (1 + u_r/r), W = mu/2 (I1 - 3) - mu ln J - p (J - 1) (the ln J
                   term only shifts p by mu, so that p = 0 at rest), Q2/Q1 Taylor-Hood quadrangles, u = 0 on
                   the base, u_r = 0 on the axis (penalized). The contact in the current configuration:
                   gap = |X + u - c| - R, c = (0, h + R - delta), the multiplier lam (a force per unit
                   reference area) pushing along the sphere's normal n = (X + u - c)/|X + u - c|, the
                   Alart-Curnier term of the linear peer (lam = max(lam - r_aug gap, 0) weakly, r_aug =
                   E/hmer), and delta an unknown with 2 pi int r lam (-n_z) dR = F: force controlled. Load
                   steps of at most --max-step (2.5 N) through the forces, each from the last solution, a
                   failed step halved (larger steps can end in spurious states on fine meshes: README).
  GetFEM linear    the linear peer's meridian model (hertz_layer_getfem.py) with this sphere's exact vertical
                   gap in the reference configuration, (R - sqrt(R^2 - r^2)) - delta - u_z, the same meshes.
One GetFEM run per model and mesh level solves every force (the seconds of a row are the whole ramp's).

Read-off. delta: the sphere's approach from first touch (skinfem's indentation_um; GetFEM's unknown). p0: the
contact pressure (force per unit reference area) on the axis (GetFEM: the multiplier's node at r = 0;
skinfem: its p0_kPa). a: the contact radius in the CURRENT configuration (the touching points' radius after
the deformation, r = R + u_r), and a_ref the same points' reference radius R; the linear models have one
radius (a = a_ref). Both codes' a by ONE read-off (the worker `readoff`): contact/metrics.hpp's edge_fit
(p^2 over the points beyond 0.6 of the largest one's radius fitted by alpha + beta r^2 + gamma r^4, the root
nearest that radius) over the points whose pressure is above 2 % of the peak (as the linear peer's 3d_whole
rows read it) - skinfem's pressure.vtp vertices about its force centroid, at X (a_ref) and X + u (a), and
GetFEM's multiplier nodes at R and R + u_r. Kept in the notes: skinfem's own contact_radius_mm (linear runs;
its touching set, not the 2 % one, 0.3 % off this read-off) and GetFEM's meridian read-off of the linear peer
(edge_radius: lam^2 fitted by a quadratic in r over the outer 30 % of the zone, which ends at the first node
with lam <= 0); the read-off alone moves a by up to 0.5 % (README).

Mesh errors: each code is run on a sequence of meshes (skinfem: the scene's contact.h = mesh.h_min scaled by
--levels, default 2, sqrt 2, 1, i.e. 0.5, 0.354, 0.25 mm; GetFEM: --hmer, default 0.1, 0.05, 0.025 mm under
the contact); the mesh error of a code's finest result is taken as its difference to the next coarser one,
and its spread as its largest difference to any coarser one (skinfem's meshes are different TetGen meshes and
its a and p0 do not converge monotonically). The codes agree on a quantity when |skinfem - GetFEM| (finest
meshes) <= the sum of the two mesh errors (column "within mesh errors"), or of the two spreads.

  bench/peer/finite_sphere_getfem.py [--out out/peer] [--skinfem build/app/skinfem]
Writes OUT/peer_finite_sphere.csv (one row per force and run), OUT/finite_sphere/ (the scenes run,
skinfem's outputs, the GetFEM results as JSON, a log per run) and prints the tables. The driver needs only the
standard library; its GetFEM runs and the read-off of skinfem's pressure.vtp use whichever of the running
interpreter and /usr/bin/python3 imports getfem, numpy and vtk. Run with OPENBLAS_NUM_THREADS=1 on a shared
machine; the skinfem runs at the finest level take ~3 min and 3.4 GB each.
"""
import argparse
import csv
import json
import math
import os
import sys
import time
from pathlib import Path

import peer_common  # bench/peer/peer_common.py, beside this script

REPO = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
SCENE = HERE / "finite_sphere.json"
COLUMNS = ["code", "model", "mesh", "dofs", "seconds", "peak_mb", "force_N", "delta_um", "a_mm", "a_ref_mm",
           "p0_kPa", "newton", "status", "notes"]
QUANTITIES = (("delta_um", "delta"), ("a_mm", "a"), ("p0_kPa", "p0"))


# ----------------------------------------------------------------------------------------------------------
# Driver (standard library only)
# ----------------------------------------------------------------------------------------------------------
def measured_run(cmd, log_path, cwd=REPO):
    return peer_common.measured_run(cmd, log_path, cwd)


def scene_variant(out, model, level, force):
    """The scene with the material model, the force and the mesh (contact.h = mesh.h_min = the scene's x
    level) set; written to OUT/scenes/. Returns (path, tag, contact.h)."""
    s = json.loads(SCENE.read_text())
    hc = s["contact"]["h"] * level
    s["material"]["model"] = model
    s["contact"]["force"] = force
    s["contact"]["h"] = hc
    s["mesh"]["h_min"] = s["mesh"]["h_min"] * level
    tag = f"{'finite' if model == 'neo_hookean' else 'linear'}_h{hc:.3f}_F{force:g}"
    path = out / "scenes" / f"{tag}.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(s, indent=1))
    return path, tag, hc


def skinfem_runs(binary, out, levels, forces, reuse):
    """One `skinfem contact --path 3d` per model, level and force; returns the rows (a read off later)."""
    rows = []
    for model in ("neo_hookean", "linear"):
        for level in levels:
            for force in forces:
                scene, tag, hc = scene_variant(out, model, level, force)
                out_dir = out / f"skinfem_{tag}"
                row = {"code": "skinfem", "model": "finite" if model == "neo_hookean" else "linear",
                       "mesh": f"h {hc:.3f}", "force_N": force, "out_dir": str(out_dir)}
                meta = out / f"skinfem_{tag}.run.json"
                cmd = [str(binary), "contact", str(scene), "--path", "3d", "--out", str(out_dir)]
                if reuse and meta.is_file() and (out_dir / "summary.json").is_file():
                    rc, wall, peak = json.loads(meta.read_text())
                else:
                    print("running:", " ".join(cmd), flush=True)
                    rc, wall, peak = measured_run(cmd, out / f"skinfem_{tag}.log")
                    meta.write_text(json.dumps([rc, wall, peak]))
                row.update(seconds=wall, peak_mb=peak)
                try:
                    s = json.loads((out_dir / "summary.json").read_text())
                except (OSError, ValueError) as e:
                    last = (out / f"skinfem_{tag}.log").read_text().strip().splitlines()[-1:]
                    rows.append({**row, "status": "failed", "notes": f"exit {rc}; {' '.join(last)} ({e})"})
                    continue
                if rc != 0:
                    rows.append({**row, "status": "failed", "notes": f"exit {rc}"})
                    continue
                newton = s.get("newton", {}).get("factorizations")
                row.update(dofs=s["dofs"], delta_um=s["indentation_um"], p0_kPa=s["p0_kPa"], newton=newton,
                           status="ok", summary=s, notes=f"own wall_total_s {s.get('wall_total_s', 0):.1f}")
                rows.append(row)
    return rows


def read_off_all(python, rows, out):
    """a and a_ref of every row by the same read-off (the worker `readoff`, one process): skinfem's from its
    pressure.vtp, GetFEM's from its result's pressure profile."""
    jobs = []
    ok = [r for r in rows if r.get("status") == "ok"]
    for r in ok:
        if r["code"] == "GetFEM":
            jobs.append({"profile": r["result"], "force_N": r["force_N"]})
            continue
        s = r["summary"]
        if r["model"] == "finite":
            c_ref, c_cur = s["reference_frame"]["force_centroid_mm"], s["current_frame"]["force_centroid_mm"]
        else:
            c_ref = c_cur = s.get("pressure_centroid_mm", [s.get("pressure_centroid_x_mm", 0.0), 0.0])
        jobs.append({"vtp": str(Path(r["out_dir"]) / "pressure.vtp"), "c_ref": c_ref, "c_cur": c_cur,
                     "finite": r["model"] == "finite"})
    if not jobs:
        return
    job_path, res_path = out / "readoff_jobs.json", out / "readoff_results.json"
    job_path.write_text(json.dumps(jobs))
    rc, _, _ = measured_run([python, str(Path(__file__).resolve()), "--worker", "readoff", "--jobs", str(job_path),
                             "--result", str(res_path)], out / "readoff.log")
    results = json.loads(res_path.read_text()) if res_path.is_file() else []
    for r, res in zip(ok, results):
        r.update(a_mm=res["a_mm"], a_ref_mm=res["a_ref_mm"])
        own = r.get("summary", {}).get("contact_radius_mm")
        if own is not None:
            r["notes"] += f"; own contact_radius_mm {own:.4f}"


def getfem_python(explicit):
    return peer_common.getfem_python(explicit, "getfem, numpy, vtk")


def getfem_runs(python, out, hmers, forces, args):
    rows = []
    for model in ("finite", "linear"):
        for hmer in hmers:
            tag = f"{model}_hmer{hmer:g}"
            result = out / f"getfem_{tag}.json"
            cmd = [python, str(Path(__file__).resolve()), "--worker", model, "--hmer", str(hmer),
                   "--forces", ",".join(f"{f:g}" for f in forces), "--radius", str(args.radius),
                   "--max-step", str(args.max_step), "--result", str(result)]
            meta = out / f"getfem_{tag}.run.json"
            if args.reuse and meta.is_file() and result.is_file() and \
                    json.loads(result.read_text()).get("status") == "ok":
                rc, wall, peak = json.loads(meta.read_text())
            else:
                result.unlink(missing_ok=True)
                print("running:", " ".join(cmd), flush=True)
                rc, wall, peak = measured_run(cmd, out / f"getfem_{tag}.log")
                meta.write_text(json.dumps([rc, wall, peak]))
            base = {"code": "GetFEM", "model": model, "mesh": f"hmer {hmer:g}", "seconds": wall, "peak_mb": peak}
            try:
                r = json.loads(result.read_text())
            except (OSError, ValueError):
                rows += [{**base, "force_N": f, "status": "failed", "notes": f"worker exit {rc} (see {tag}.log)"}
                         for f in forces]
                continue
            done = {p["force_N"]: p for p in r.get("points", [])}
            for f in forces:
                p = done.get(f)
                if p is None:
                    rows.append({**base, "dofs": r.get("dofs"), "force_N": f, "status": r.get("status", "failed"),
                                 "notes": r.get("notes", "not reached")})
                    continue
                # a multiplier oscillating inside the zone (a spurious converged state, see the README) is
                # not a result: its rows say so and stay out of the comparison
                spurious = p.get("lam_spike_kPa", 0.0) > 0.05 * p["p0_kPa"]
                rows.append({**base, "dofs": r["dofs"], "force_N": f, "delta_um": p["delta_um"],
                             "p0_kPa": p["p0_kPa"], "newton": p["newton"], "result": str(result),
                             "status": "spurious (multiplier oscillates)" if spurious else "ok",
                             "notes": f"ramp {r['solve_seconds']:.1f} s, {r['newton_total']} Newton in all; "
                                      f"edge_radius read-off a {p['a_mm']:.4f} (a_ref {p['a_ref_mm']:.4f}); "
                                      f"lam spike {p.get('lam_spike_kPa', float('nan')):.1f} kPa"})
    return rows


def cell(value, fmt):
    return "–" if value is None else format(value, fmt)


def print_runs(rows):
    print("| code | model | mesh | DOFs | seconds | peak MB | F N | delta um | a mm (a_ref) | p0 kPa | Newton |")
    print("|---|---|---|---:|---:|---:|---:|---:|---|---:|---:|")
    for r in rows:
        a = "–" if r.get("a_mm") is None else (f"{r['a_mm']:.4f}" + (f" ({r['a_ref_mm']:.4f})"
                                                                    if r["model"] == "finite" else ""))
        tail = "" if r.get("status") == "ok" else f" **{r.get('status')}**: {r.get('notes', '')}"
        print(f"| {r['code']} | {r['model']} | {r['mesh']} | {cell(r.get('dofs'), ',')} | "
              f"{cell(r.get('seconds'), '.1f')} | {cell(r.get('peak_mb'), '.0f')} | {r['force_N']:g} | "
              f"{cell(r.get('delta_um'), '.2f')} | {a} | {cell(r.get('p0_kPa'), '.1f')} | "
              f"{cell(r.get('newton'), 'd')} |{tail}")


def finest_and_error(rows, code, model, force, key):
    """A code's finest value of `key` at `force` and its mesh error (the difference to the next coarser
    mesh; and its largest difference to any coarser one), from rows in coarse-to-fine order."""
    vals = [r[key] for r in rows if r["code"] == code and r["model"] == model and r["force_N"] == force
            and r.get("status") == "ok" and r.get(key) is not None]
    if not vals:
        return None, None, None
    return spread(vals)


def spread(vals):
    """(finest, its difference to the next coarser, its largest difference to any coarser) of a sequence."""
    if len(vals) < 2:
        return vals[-1], None, None
    return vals[-1], abs(vals[-1] - vals[-2]), max(abs(vals[-1] - v) for v in vals[:-1])


def compare(rows, forces):
    """Per force and quantity: skinfem's and GetFEM's finest values, their mesh errors and the difference,
    for the finite model, the linear one and finite - linear. Returns the comparison rows."""
    out = []
    for f in forces:
        for key, name in QUANTITIES:
            v = {}
            for code in ("skinfem", "GetFEM"):
                for model in ("finite", "linear"):
                    v[code, model] = finest_and_error(rows, code, model, f, key)
                fin, lin = v[code, "finite"], v[code, "linear"]
                if None not in (fin[0], lin[0]):
                    # finite - linear on the same meshes: its mesh error is that of the difference
                    fr = [r for r in rows if r["code"] == code and r["force_N"] == f and r.get(key) is not None]
                    diffs = [a[key] - b[key] for a in fr if a["model"] == "finite"
                             for b in fr if b["model"] == "linear" and b["mesh"] == a["mesh"]]
                    v[code, "diff"] = spread(diffs)
                else:
                    v[code, "diff"] = (None, None, None)
            for model in ("finite", "linear", "diff"):
                (s, es, ss), (g, eg, sg) = v["skinfem", model], v["GetFEM", model]
                if s is None or g is None:
                    continue
                ref = abs(v["GetFEM", "finite"][0]) if model == "diff" else abs(g)
                d = s - g
                both = es is not None and eg is not None
                out.append({"force_N": f, "quantity": name, "model": model, "skinfem": s, "skinfem_err": es,
                            "skinfem_spread": ss, "getfem": g, "getfem_err": eg, "getfem_spread": sg, "diff": d,
                            "diff_rel": d / ref, "agree": abs(d) <= es + eg if both else None,
                            "agree_spread": abs(d) <= ss + sg if both else None})
    return out


def print_comparison(comp):
    print("| F N | quantity | model | skinfem (mesh err; spread) | GetFEM (mesh err; spread) | "
          "skinfem - GetFEM (rel.) | within mesh errors | within spreads |")
    print("|---:|---|---|---|---|---|---|---|")
    e = lambda x: "–" if x is None else f"{x:.2g}"
    yn = lambda x: "–" if x is None else ("yes" if x else "**no**")
    for c in comp:
        print(f"| {c['force_N']:g} | {c['quantity']} | {'finite - linear' if c['model'] == 'diff' else c['model']} | "
              f"{c['skinfem']:.5g} ({e(c['skinfem_err'])}; {e(c['skinfem_spread'])}) | "
              f"{c['getfem']:.5g} ({e(c['getfem_err'])}; {e(c['getfem_spread'])}) | "
              f"{c['diff']:+.3g} ({c['diff_rel']:+.1e}) | {yn(c['agree'])} | {yn(c['agree_spread'])} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--skinfem", default="build/app/skinfem", help="skinfem binary (relative to the repo root)")
    ap.add_argument("--out", default="out/peer", help="output directory (relative to the repo root)")
    ap.add_argument("--python", help="interpreter with getfem, numpy, vtk (default: this one, else /usr/bin/python3)")
    ap.add_argument("--forces", default="5,10,20,35", help="forces, N (comma separated)")
    ap.add_argument("--levels", default="2,1.41421356,1",
                    help="skinfem meshes: the scene's contact.h and mesh.h_min times these, coarse to fine")
    ap.add_argument("--hmer", default="0.1,0.05,0.025", help="GetFEM meshes: cell size under the contact, mm, "
                    "coarse to fine")
    ap.add_argument("--radius", type=float, default=0.0,
                    help="GetFEM: the disc's radius, mm (default: the scene's half width)")
    ap.add_argument("--max-step", type=float, default=2.5, help="GetFEM: the largest load step, N")
    ap.add_argument("--skip-skinfem", action="store_true")
    ap.add_argument("--skip-getfem", action="store_true")
    ap.add_argument("--reuse", action="store_true",
                    help="take a run's outputs and measured seconds from OUT when present instead of running it")
    # internal: one GetFEM solve (finite, linear) or skinfem's pressure.vtp read-off (readoff) in this process
    ap.add_argument("--worker", choices=["finite", "linear", "readoff"], help=argparse.SUPPRESS)
    ap.add_argument("--jobs", help=argparse.SUPPRESS)
    ap.add_argument("--result", help=argparse.SUPPRESS)
    args = ap.parse_args()
    forces = [float(f) for f in args.forces.split(",") if f]
    if args.worker:
        return worker(args, forces)

    out = REPO / args.out
    work = out / "finite_sphere"
    work.mkdir(parents=True, exist_ok=True)
    python = getfem_python(args.python)
    rows = []
    if not args.skip_skinfem:
        binary = REPO / args.skinfem
        if not binary.is_file():
            print(f"no skinfem binary at {binary}: the skinfem rows are skipped")
        else:
            rows += skinfem_runs(binary, work, [float(x) for x in args.levels.split(",")], forces, args.reuse)
    if not args.skip_getfem:
        if python is None:
            print("GetFEM is not installed (Debian package python3-getfem): the GetFEM rows are skipped.")
        else:
            rows += getfem_runs(python, work, [float(x) for x in args.hmer.split(",")], forces, args)
    if python is None:
        print("no interpreter with numpy and vtk: the contact radii are not read off")
    else:
        read_off_all(python, rows, work)
    # rows in the order: code, model, force, mesh coarse to fine (the mesh order of the runs)
    order = {("skinfem", "finite"): 0, ("skinfem", "linear"): 1, ("GetFEM", "finite"): 2, ("GetFEM", "linear"): 3}
    rows.sort(key=lambda r: (order[r["code"], r["model"]], r["force_N"]))  # stable: meshes stay coarse to fine
    with open(out / "peer_finite_sphere.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in COLUMNS})
    print()
    print_runs(rows)
    comp = compare(rows, forces)
    print()
    print_comparison(comp)
    (work / "comparison.json").write_text(json.dumps(comp, indent=1))
    print(f"\nwrote {out / 'peer_finite_sphere.csv'}")
    return 0


# ----------------------------------------------------------------------------------------------------------
# Workers (numpy + getfem / vtk), one per process
# ----------------------------------------------------------------------------------------------------------
def LOG(msg):
    print(msg, flush=True)


def load_problem(radius):
    s = json.loads(SCENE.read_text())
    g, m, c = s["geometry"], s["material"], s["contact"]
    assert c["indenter"]["type"] == "sphere" and tuple(c["indenter"]["center"]) == (0.0, 0.0)
    return {"h": g["h"], "W": radius if radius > 0 else g["half_width"], "E": m["E"], "R": c["indenter"]["R"]}


def solve_meridian(p, model, hmer, forces, max_step):
    """The layer's meridian, Q2/Q1, finite (total Lagrangian neo-Hookean, the contact in the current
    configuration) or linear (small strain, the vertical gap in the reference configuration); load steps
    through `forces`, force controlled. Returns the result dict with one point per force."""
    import numpy as np
    import getfem as gf
    sys.path.insert(0, str(HERE))
    from hertz_layer_getfem import graded_ticks, z_ticks, edge_radius
    h, W, R, E = p["h"], p["W"], p["R"], p["E"]
    mu = E / 3
    rt = graded_ticks(W, hmer, 4.5, 1.2, 1.0)  # a <= 3.5 mm at 35 N (current), a margin
    z = z_ticks(h, hmer, 1.2, 0.4)
    m = gf.Mesh("cartesian", rt, z)
    TOP, BASE, AXIS = 1, 2, 3
    for rid, v in ((TOP, [0, 1]), (BASE, [0, -1]), (AXIS, [-1, 0])):
        m.set_region(rid, m.outer_faces_with_direction(v, 0.01))
    mfu = gf.MeshFem(m, 2)
    mfu.set_classical_fem(2)
    mfp = gf.MeshFem(m, 1)
    mfp.set_classical_fem(1)
    mfl_all = gf.MeshFem(m, 1)
    mfl_all.set_classical_fem(1)
    ldof = mfl_all.basic_dof_on_region(TOP)
    mfl = gf.MeshFem("partial", mfl_all, ldof)
    mim = gf.MeshIm(m, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,6)"))
    mimc = gf.MeshIm(m, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,10)"))
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)  # (u_r, u_z)
    md.add_fem_variable("p", mfp)
    md.add_fem_variable("lam", mfl)  # contact pressure per unit reference area, >= 0
    md.add_variable("delta", 1)
    md.add_initialized_data("F", [forces[0]])
    for name, v in (("mu", mu), ("Rs", R), ("zc", h + R), ("W", W), ("raug", E / hmer)):
        md.add_initialized_data(name, [v])
    w = "2*pi*X(1)"
    if model == "finite":
        # P = mu F - (mu + p J) F^-T in the meridian, the hoop stretch ft; the constraint J = 1.
        md.add_macro("Fr", "(Id(2)+Grad_u)")
        md.add_macro("ft", "(1+u(1)/X(1))")
        md.add_macro("J", "(Det(Fr)*ft)")
        md.add_nonlinear_term(mim, "2*pi*(X(1)*mu*(Fr:Grad_Test_u) + mu*ft*Test_u(1)"
                                   " - (mu + p*J)*(X(1)*(Inv(Fr)':Grad_Test_u) + Test_u(1)/ft)"
                                   " - X(1)*Test_p*(J-1))")
        md.add_macro("dv", "(X + u - [0; zc - delta])")  # from the sphere's centre to the current point
        md.add_macro("nrm", "(dv/Norm(dv))")
        md.add_macro("gap", "(Norm(dv) - Rs)")
        md.add_nonlinear_term(mimc, f"-{w}*lam*(nrm.Test_u)", TOP)
        md.add_nonlinear_term(mimc, f"-{w}/raug*(lam - pos_part(lam - raug*gap))*Test_lam", TOP)
        md.add_nonlinear_term(mimc, f"({w}*lam*(-nrm(2)) - F/W)*Test_delta", TOP)  # vertical force = F
    else:
        md.add_linear_term(mim, "2*pi*(2*mu*(X(1)*(Sym(Grad_u):Grad_Test_u) + u(1)*Test_u(1)/X(1))"
                                " - p*(X(1)*Div_Test_u + Test_u(1)) - Test_p*(X(1)*Div_u + u(1)))")
        md.add_macro("gap", "(sqr(X(1))/(Rs + sqrt(sqr(Rs) - sqr(X(1)))) - delta - u(2))")
        md.add_nonlinear_term(mimc, f"{w}*lam*Test_u(2)", TOP)
        md.add_nonlinear_term(mimc, f"-{w}/raug*(lam - pos_part(lam - raug*gap))*Test_lam", TOP)
        md.add_nonlinear_term(mimc, f"({w}*lam - F/W)*Test_delta", TOP)
    md.add_Dirichlet_condition_with_simplification("u", BASE)
    md.add_linear_term(mim, "1e8*u(1)*Test_u(1)", AXIS)  # u_r = 0 on the axis, penalized
    # the first depth: the half-space Hertz approach (E* = 4 MPa) at the first step's force (from a depth
    # guessed for a larger force Newton failed at hmer 0.025 and the halved steps led to a spurious state)
    a0 = (3 * min(forces[0], max_step) * R / 16) ** (1 / 3)
    md.set_variable("delta", [a0 * a0 / R])
    res = {"model": model, "dofs": int(md.nbdof()), "points": [], "steps": [],
           "mesh": {"cells": int(m.nbcvs()), "hmer_mm": hmer, "r_ticks": len(rt), "z_ticks": len(z),
                    "radius_mm": W}}
    LOG(f"{model}, hmer {hmer}: {md.nbdof()} unknowns, {m.nbcvs()} cells")
    nodes = mfl_all.basic_dof_nodes(ldof)
    R0 = nodes[0]
    # Steps of at most max_step: from larger steps Newton (semi-smooth, through changing contact sets) can
    # land on a spurious converged state on fine meshes (hmer 0.025: a single-node spike of the multiplier,
    # p0 535 kPa instead of 1958 at 35 N after 10 -> 20 -> 35 N steps); with steps of 2.5 N every mesh's
    # pressure is smooth (lam_spike_kPa below: the largest second difference of lam inside the zone).
    targets, fcur, step, total = sorted(forces), 0.0, min(sorted(forces)[0], max_step), 0
    since_target = 0
    while targets:
        ft = min(fcur + step, targets[0])
        saved = md.from_variables()
        md.set_variable("F", [ft])
        out = md.solve("max_iter", 25, "max_res", 1e-9, "lsolver", "mumps", "lsearch", "default")
        it, conv = (int(out[0]), bool(out[1])) if isinstance(out, (tuple, list)) else (int(out), True)
        total += it
        res["steps"].append({"force_N": ft, "iterations": it, "converged": conv})
        LOG(f"  F {ft:.4f} N: {it} Newton iterations, converged {conv}, delta {md.variable('delta')[0]:.6f} mm")
        if not conv:
            md.to_variables(saved)
            step /= 2
            if step < 1e-3 * forces[-1]:
                res.update(status="not converged", notes=f"load step below {step:.2e} N at {fcur:g} N")
                break
            continue
        fcur, since_target = ft, since_target + it
        if ft == targets[0]:
            targets.pop(0)
            lam = md.variable("lam")
            ur = md.interpolation("u(1)", nodes, m) if model == "finite" else 0.0 * R0
            a_ref = edge_radius(R0, lam)
            a_cur = edge_radius(R0 + ur, lam) if model == "finite" else a_ref
            fz = gf.asm_generic(mimc, 0, f"{w}*lam*(-nrm(2))" if model == "finite" else f"{w}*lam", TOP, md)
            order = np.argsort(R0)
            res["points"].append({
                "force_N": ft, "delta_um": 1e3 * float(md.variable("delta")[0]), "a_mm": float(a_cur[0]),
                "a_ref_mm": float(a_ref[0]), "a_linear_crossing_mm": float(a_cur[1]), "edge_fit_nodes": a_cur[3],
                "p0_kPa": 1e3 * float(lam[np.argmin(R0)]), "force_check_N": float(fz), "newton": since_target,
                "lam_spike_kPa": 1e3 * float(np.max(np.abs(np.diff(lam[order], 2))[R0[order][1:-1] < a_ref[0] - 0.2],
                                                    initial=0.0)),
                "profile": {"R_mm": R0[order].tolist(), "r_mm": (R0 + ur)[order].tolist(),
                            "p_kPa": (1e3 * lam[order]).tolist()}})
            since_target = 0
        step = min(step * 1.5, max_step)
    else:
        res.update(status="ok", notes="")
    res["newton_total"] = total
    return res


def read_off(jobs):
    """a (current configuration) and a_ref (reference) by one read-off for both codes: contact/metrics.hpp's
    edge_fit (p^2 over the points beyond 0.6 of the largest one's radius fitted by alpha + beta r^2 +
    gamma r^4, the root nearest that radius) over the points whose pressure is above 2 % of the peak (the
    linear peer's 3d_whole convention: it drops GetFEM's weak-complementarity tail and skinfem's hats at the
    rim that carry almost nothing). A job is skinfem's pressure.vtp (its top vertices, the radius about the
    given centroid, at X and X + u) or a GetFEM result's profile at one force (R and R + u_r)."""
    import numpy as np

    def edge_fit(r, p):
        act = p > 0.02 * p.max()
        r, p = r[act], p[act]
        r_max = r.max()
        band = r >= 0.6 * r_max
        if band.sum() < 6:
            return float("nan")
        X = (r[band] / r_max) ** 2
        A = np.stack([np.ones_like(X), X, X * X], axis=1)
        co = np.linalg.lstsq(A, p[band] ** 2, rcond=None)[0]
        roots = np.roots(co[::-1]) if abs(co[2]) > 1e-12 * abs(co[1]) else np.array([-co[0] / co[1]])
        roots = roots[np.isreal(roots)].real
        roots = roots[roots > 0]
        return float(r_max * math.sqrt(roots[np.argmin(np.abs(roots - 1))])) if len(roots) else float("nan")

    results = []
    for job in jobs:
        if "profile" in job:  # GetFEM
            res = json.loads(Path(job["profile"]).read_text())
            pr = next(q for q in res["points"] if q["force_N"] == job["force_N"])["profile"]
            R, r, p = (np.array(pr[k]) for k in ("R_mm", "r_mm", "p_kPa"))
            results.append({"a_ref_mm": edge_fit(R, p), "a_mm": edge_fit(r, p)})
            continue
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(job["vtp"])
        reader.Update()
        g = reader.GetOutput()
        X = vtk_to_numpy(g.GetPoints().GetData())
        pd = g.GetPointData()
        p = vtk_to_numpy(pd.GetArray("pressure_kPa"))
        xu = X + vtk_to_numpy(pd.GetArray("displacement_mm")) if job["finite"] else X
        rr = np.hypot(X[:, 0] - job["c_ref"][0], X[:, 1] - job["c_ref"][1])
        rc = np.hypot(xu[:, 0] - job["c_cur"][0], xu[:, 1] - job["c_cur"][1])
        results.append({"a_ref_mm": edge_fit(rr, p), "a_mm": edge_fit(rc, p)})
    return results


def worker(args, forces):
    if args.worker == "readoff":
        res = read_off(json.loads(Path(args.jobs).read_text()))
        Path(args.result).write_text(json.dumps(res, indent=1))
        LOG(json.dumps(res))
        return 0
    t0 = time.perf_counter()
    try:
        res = solve_meridian(load_problem(args.radius), args.worker, float(args.hmer), forces, args.max_step)
    except Exception as e:  # a failed GetFEM run is a row that says so
        res = {"status": "failed", "notes": f"{type(e).__name__}: {e}"}
    res["solve_seconds"] = time.perf_counter() - t0
    Path(args.result).write_text(json.dumps(res, indent=1))
    LOG(json.dumps({k: v for k, v in res.items() if k != "points"}))
    for pt in res.get("points", []):
        LOG(json.dumps({k: v for k, v in pt.items() if k != "profile"}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
