#!/usr/bin/python3
"""Peer benchmark (issue 29 §4): the Hertz-layer contact by skinfem and by GetFEM, against the exact solution.

The problem is scenes/hertz_layer.json: a rigid frictionless sphere (R = 129.7 mm) pressed with 0.8 N on an
incompressible (nu = 0.5) elastic layer, E = 3 MPa, h = 3.04 mm, bonded to a rigid base (u = 0 at z = 0),
top free at z = h, laterally as wide as the scene (half width 15 mm, sides free). Units mm, N, MPa. The
exact solution is the unbounded bonded layer's (contact/layer_hertz.hpp, a Fredholm equation solved to
1e-12): contact radius a = 2.4879 mm, peak pressure p0 = 63.75 kPa, approach delta = 28.46 um (more
digits: EXACT below, `--exact`).

Rows of the table:
  skinfem 3d        `skinfem contact scenes/hertz_layer.json --path 3d`        (the binary, not rebuilt)
  skinfem meridian  `skinfem contact scenes/hertz_layer.json --path meridian`
  GetFEM 3d         quarter of the layer (symmetry planes x = 0 and y = 0), a graded tensor mesh of
                    hexahedra, Q2 displacement / Q1 pressure (Taylor-Hood) with the linear
                    incompressibility brick, the rigid sphere through GetFEM's integral contact with a
                    rigid obstacle brick (Alart-Curnier augmented Lagrangian, semi-smooth Newton, a Q1
                    contact-stress multiplier). The brick is depth controlled, so the depth is iterated
                    (secant on ln F against ln delta) until the force is 0.8 N.
  GetFEM meridian   the same problem on the meridian (r, z): the axisymmetric weak form written in GetFEM's
                    weak form language (every term times 2 pi r, the hoop strain u_r / r), Q2/Q1 on a
                    graded mesh of quadrangles, the same Alart-Curnier contact term as the brick, written
                    out, and the depth an unknown with the force equation 2 pi int r p dr = 0.8 N, so one
                    Newton solve is force controlled. Like skinfem's meridian path it takes the unbounded
                    layer as a disc of radius 20 h, traction-free at its rim (the 3D rows: the scene's
                    square, half width 15 mm).
  skinfem 3d_whole  the same on the whole layer ("symmetry": "none"), the mesh GetFEM 3d_whole reads
  GetFEM 3d_whole   skinfem's own mesh of the whole layer (`skinfem mesh`, 10-node tetrahedra as GT_PK(3,2)),
                    P2/P1 Taylor-Hood with the linear incompressibility brick, and the meridian model's
                    force-controlled contact term in 3D (int lam dA = F): one Newton solve. The fair 3D
                    comparison: the same mesh, the same read-off of a as skinfem's (edge_fit_radius).
The contact in every GetFEM row is the exact solution's linear one: the gap is vertical and measured in the
reference configuration, g = r^2 / (2R) - delta - u_z on z = h (the paraboloid of the sphere).

Each run is a subprocess of its own; its seconds are its wall time and its peak memory its own maximum
resident set (os.wait4), so each row has its own peak. GetFEM's rows need python3-getfem (Debian); without
it they are skipped with a message and the table has skinfem's rows only. Only the standard library is
needed here; the GetFEM workers (this file with --worker) need numpy and getfem.

Read off the GetFEM solutions: a where the contact pressure vanishes (the multiplier's nodal pressures along a
radius; the zone ends at the first node with p <= 0, and a is the root of a quadratic in r fitted to p^2 over
the outer 30 % of the zone, at least its last 5 nodes), p0 the pressure on the axis, delta the sphere's
approach (the depth at 0.8 N). DOFs: skinfem's `dofs` from its
summary.json; GetFEM's all unknowns of the model (displacement, pressure, contact multiplier).

Sample run (from the repository root; this 2-core machine):
  $ bench/peer/hertz_layer_getfem.py --out out/peer
  | code | path | DOFs | seconds | peak MB | a mm (rel. error) | p0 kPa (rel. error) | delta um (rel. error) | notes |
  |---|---|---:|---:|---:|---|---|---|---|
  | exact | bonded layer | | | | 2.4878929 | 63.7461 | 28.46396 | contact/layer_hertz |
  | skinfem | 3d | 60,229 | 9.05 | 602 | 2.4861 (-7.2e-04) | 63.854 (+1.7e-03) | 28.472 (+2.7e-04) | ... |
  | skinfem | meridian | 32,069 | 0.78 | 95 | 2.4878 (-2.1e-05) | 63.765 (+2.9e-04) | 28.465 (+3.4e-05) | ... |
  | GetFEM | 3d | 115,383 | 410.37 | 3182 | 2.4693 (-7.5e-03) | 63.830 (+1.3e-03) | 28.470 (+2.3e-04) | ... |
  | GetFEM | meridian | 39,748 | 13.32 | 238 | 2.4875 (-1.5e-04) | 63.747 (+1.4e-05) | 28.464 (-3.8e-06) | ... |
Writes OUT/peer_hertz_layer.csv (one row per run, the same columns plus the run's own figures and notes),
OUT/skinfem_3d/, OUT/skinfem_meridian/ (skinfem's outputs), OUT/getfem_3d.json, OUT/getfem_meridian.json
(the GetFEM runs' readings, mesh and Newton counts, pressure profile) and OUT/*.log (each run's output).
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
SCENE = "scenes/hertz_layer.json"
# Exact bonded layer at 0.8 N: contact/layer_hertz.hpp gives a = 2.4879 mm, p0 = 63.75 kPa, delta = 28.46 um
# (docs/contact_results.md, "Error against cost"); the digits below are the same Fredholm equation solved again by
# exact_layer_hertz() (`--exact` prints it; unchanged when its quadratures are doubled).
EXACT = {"a_mm": 2.4878929, "p0_kPa": 63.74610, "delta_um": 28.46396}
COLUMNS = ["code", "path", "dofs", "seconds", "peak_mb", "a_mm", "a_rel", "p0_kPa", "p0_rel", "delta_um",
           "delta_rel", "own_seconds", "status", "notes"]


# ----------------------------------------------------------------------------------------------------------
# Driver (standard library only)
# ----------------------------------------------------------------------------------------------------------
def measured_run(cmd, log_path, cwd=REPO):
    return peer_common.measured_run(cmd, log_path, cwd)


def with_errors(row):
    for key, rel in (("a_mm", "a_rel"), ("p0_kPa", "p0_rel"), ("delta_um", "delta_rel")):
        if row.get(key) is not None:
            row[rel] = row[key] / EXACT[key] - 1.0
    return row


def whole_scene(out):
    """The scene solved on the whole layer ("symmetry": "none"), as skinfem's 3d_whole row and the GetFEM
    model on skinfem's own mesh take it."""
    scene = json.loads((REPO / SCENE).read_text())
    scene["symmetry"] = "none"
    path = out / "hertz_layer_whole.json"
    path.write_text(json.dumps(scene, indent=1))
    return path


def skinfem_row(binary, path, out):
    row = {"code": "skinfem", "path": path}
    out_dir = out / f"skinfem_{path}"
    scene, solver_path = (whole_scene(out), "3d") if path == "3d_whole" else (REPO / SCENE, path)
    cmd = [str(binary), "contact", str(scene), "--path", solver_path, "--out", str(out_dir)]
    print("running:", " ".join(cmd), flush=True)
    if not Path(binary).is_file():
        return {**row, "status": "skipped", "notes": f"no skinfem binary at {binary}"}
    rc, wall, peak = measured_run(cmd, out / f"skinfem_{path}.log")
    row.update(seconds=wall, peak_mb=peak)
    try:
        s = json.loads((out_dir / "summary.json").read_text())
    except (OSError, ValueError) as e:
        return {**row, "status": "failed", "notes": f"exit {rc}; no summary.json ({e})"}
    if rc != 0:
        return {**row, "status": "failed", "notes": f"exit {rc}"}
    row.update(dofs=s["dofs"], a_mm=s["contact_radius_mm"], p0_kPa=s["p0_kPa"], delta_um=s["indentation_um"],
               own_seconds=s.get("wall_total_s"), status="ok",
               notes=f"its own peak_rss_mb {s.get('peak_rss_mb', float('nan')):.0f}")
    return with_errors(row)


def getfem_python(explicit):
    return peer_common.getfem_python(explicit)


def getfem_row(python, case, args, out):
    row = {"code": "GetFEM", "path": case}
    result_path = out / f"getfem_{case}.json"
    result_path.unlink(missing_ok=True)
    cmd = [python, str(Path(__file__).resolve()), "--worker", case, "--result", str(result_path),
           "--h3d", str(args.h3d), "--hmer", str(args.hmer)]
    if case == "3d_whole":  # skinfem's own mesh of the whole layer, as its 3d_whole row solves it
        mesh_dir = out / "skinfem_mesh_whole"
        rc, _, _ = measured_run([str(REPO / args.skinfem), "mesh", str(whole_scene(out)), "--out", str(mesh_dir)],
                                out / "skinfem_mesh_whole.log")
        if rc != 0:
            return {**row, "status": "failed", "notes": f"skinfem mesh exit {rc} (see skinfem_mesh_whole.log)"}
        cmd += ["--mesh", str(mesh_dir / "mesh.vtu")]
    print("running:", " ".join(cmd), flush=True)
    rc, wall, peak = measured_run(cmd, out / f"getfem_{case}.log")
    row.update(seconds=wall, peak_mb=peak)
    try:
        r = json.loads(result_path.read_text())
    except (OSError, ValueError):
        return {**row, "status": "failed", "notes": f"worker exit {rc}, no result (see getfem_{case}.log)"}
    row.update(dofs=r.get("dofs"), own_seconds=r.get("solve_seconds"), status=r["status"], notes=r.get("notes", ""))
    if r["status"] == "ok":
        row.update(a_mm=r["a_mm"], p0_kPa=r["p0_kPa"], delta_um=r["delta_um"])
    return with_errors(row)


def cell(value, fmt):
    return "–" if value is None else format(value, fmt)


def print_table(rows):
    print("| code | path | DOFs | seconds | peak MB | a mm (rel. error) | p0 kPa (rel. error) | "
          "delta um (rel. error) | notes |")
    print("|---|---|---:|---:|---:|---|---|---|---|")
    print(f"| exact | bonded layer | | | | {EXACT['a_mm']} | {EXACT['p0_kPa']} | {EXACT['delta_um']} | "
          "contact/layer_hertz |")
    for r in rows:
        val = lambda k, rel, f: "–" if r.get(k) is None else f"{r[k]:{f}} ({r[rel]:+.1e})"
        note = r.get("notes", "") if r.get("status") == "ok" else f"**{r.get('status')}**: {r.get('notes', '')}"
        print(f"| {r['code']} | {r['path']} | {cell(r.get('dofs'), ',')} | {cell(r.get('seconds'), '.2f')} | "
              f"{cell(r.get('peak_mb'), '.0f')} | {val('a_mm', 'a_rel', '.4f')} | {val('p0_kPa', 'p0_rel', '.3f')} | "
              f"{val('delta_um', 'delta_rel', '.3f')} | {note} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--skinfem", default="build/app/skinfem", help="skinfem binary (relative to the repo root)")
    ap.add_argument("--out", default="out/peer", help="output directory (relative to the repo root)")
    ap.add_argument("--python", help="interpreter with getfem for the GetFEM runs (default: this one, "
                    "else /usr/bin/python3)")
    ap.add_argument("--h3d", type=float, default=0.2, help="GetFEM 3D: cell size under the contact, mm")
    ap.add_argument("--hmer", type=float, default=0.02, help="GetFEM meridian: cell size under the contact, mm")
    ap.add_argument("--skip-skinfem", action="store_true")
    ap.add_argument("--skip-getfem", action="store_true")
    ap.add_argument("--cases", default="3d,meridian,3d_whole",
                    help="which paths to run (comma separated): 3d (skinfem's half; GetFEM's hexahedral quarter), "
                    "meridian, 3d_whole (skinfem's whole layer; GetFEM on skinfem's own tetrahedral mesh of it)")
    ap.add_argument("--exact", action="store_true", help="solve the exact layer again (numpy) and print it")
    # internal: one GetFEM solve in this process
    ap.add_argument("--worker", choices=["3d", "meridian", "3d_whole"], help=argparse.SUPPRESS)
    ap.add_argument("--mesh", help=argparse.SUPPRESS)
    ap.add_argument("--result", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.worker:
        return worker(args)
    if args.exact:
        for n in (48, 96):
            a, p0, delta = exact_layer_hertz(load_problem(), n)
            print(f"exact bonded layer ({n} Nystrom nodes): a = {a:.7f} mm, p0 = {1e3 * p0:.5f} kPa, "
                  f"delta = {1e3 * delta:.5f} um")
        return 0

    out = REPO / args.out
    out.mkdir(parents=True, exist_ok=True)
    binary = REPO / args.skinfem
    cases = [c for c in args.cases.split(",") if c]
    rows = []
    if not args.skip_skinfem:
        rows += [skinfem_row(binary, path, out) for path in cases]
    if not args.skip_getfem:
        python = getfem_python(args.python)
        if python is None:
            print("GetFEM is not installed (Debian package python3-getfem): the GetFEM rows are skipped.")
        else:
            rows += [getfem_row(python, case, args, out) for case in cases]
    with open(out / "peer_hertz_layer.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in COLUMNS})
    print()
    print_table(rows)
    print(f"\nwrote {out / 'peer_hertz_layer.csv'}")
    return 0


# ----------------------------------------------------------------------------------------------------------
# GetFEM workers (numpy + getfem), one solve per process
# ----------------------------------------------------------------------------------------------------------
def load_problem():
    s = json.loads((REPO / SCENE).read_text())
    g, m, c = s["geometry"], s["material"], s["contact"]
    assert c["indenter"]["type"] == "sphere" and tuple(c["indenter"]["center"]) == (0.0, 0.0)
    return {"h": g["h"], "W": g["half_width"], "E": m["E"], "nu": m["nu"], "R": c["indenter"]["R"],
            "F": c["force"]}


def exact_layer_hertz(p, n=48):
    """contact/layer_hertz.hpp's equation, solved by Gauss-Legendre Nystrom: on 0 <= t <= a,
    (pi/2) g(t) + int_0^a K(t, tau) g(tau) dtau = (E*/2)(delta - t^2/R), K = int_0^inf [M(sh) - 1] cos(st)
    cos(s tau) ds, M(t) = (2k sinh 2t - 4t)/(2k cosh 2t + 1 + k^2 + 4t^2), k = 3 - 4 nu; g(a) = 0 gives delta,
    F = 2 pi int g, p(0) = -int_0^a g'(t)/t dt; a from F by secant. Returns (a, p0, delta) in mm, MPa."""
    import numpy as np
    es, kap, h, R, F = p["E"] / (1 - p["nu"] ** 2), 3 - 4 * p["nu"], p["h"], p["R"], p["F"]
    xs, ws = np.polynomial.legendre.leggauss(25 * n)
    s, ws = (xs + 1) * 15 / h, ws * 15 / h  # wavenumbers up to 30/h, where M - 1 ~ 1e-23
    e2 = np.exp(-2 * s * h)
    m1 = (kap * (1 - e2 * e2) - 4 * s * h * e2) / (kap * (1 + e2 * e2) + (1 + kap * kap + 4 * (s * h) ** 2) * e2) - 1
    xg, wg = np.polynomial.legendre.leggauss(n)

    def solve(a):
        t, w = (xg + 1) * a / 2, wg * a / 2
        C = np.cos(np.outer(t, s))
        A = (math.pi / 2) * np.eye(n) + ((C * (ws * m1)) @ C.T) * w
        g1, g2 = np.linalg.solve(A, np.full(n, es / 2)), np.linalg.solve(A, es / 2 * t * t / R)
        Ka = (np.cos(a * s) * (ws * m1)) @ C.T  # g at t = a through the equation
        delta = (es / 2 * a * a / R - Ka @ (w * g2)) / (es / 2 - Ka @ (w * g1))
        g = delta * g1 - g2
        dK = -(np.sin(np.outer(t, s)) * (ws * m1 * s)) @ C.T
        p0 = -np.sum(w * (2 / math.pi) * (-es / R - (dK @ (w * g)) / t))
        return 2 * math.pi * np.sum(w * g), delta, p0

    la = [math.log((3 * F * R / (4 * es)) ** (1 / 3))]  # from the half-space radius
    la.append(la[0] - 0.1)
    lf = [math.log(solve(math.exp(x))[0]) for x in la]
    for _ in range(50):
        la.append(la[-1] + (math.log(F) - lf[-1]) * (la[-1] - la[-2]) / (lf[-1] - lf[-2]))
        f, delta, p0 = solve(math.exp(la[-1]))
        lf.append(math.log(f))
        if abs(f / F - 1) < 1e-13:
            break
    return math.exp(la[-1]), p0, delta


def graded_ticks(length, fine, zone, growth, coarse):
    """0..length: cells of size `fine` on [0, zone], then growing by `growth` (at most `coarse`)."""
    import numpy as np
    n = max(1, int(round(zone / fine)))
    t = list(np.linspace(0.0, n * fine, n + 1))
    s = fine
    while t[-1] < length - 1e-9:
        s = min(s * growth, coarse)
        t.append(t[-1] + s)
    t = np.array(t)
    t[n:] = t[n] + (t[n:] - t[n]) * (length - t[n]) / (t[-1] - t[n])  # end exactly at length
    return t


def z_ticks(h, fine, growth, coarse):
    """0..h, cells of `fine` at the top z = h, growing by `growth` toward the base."""
    d = graded_ticks(h, fine, fine, growth, coarse)
    return (h - d)[::-1].copy()


def hertz_halfspace_delta(p):
    """Half-space Hertz approach (the starting depth): a^3 = 3FR / (4E*), delta = a^2 / R."""
    e_star = p["E"] / (1 - p["nu"] ** 2)
    a = (3 * p["F"] * p["R"] / (4 * e_star)) ** (1 / 3)
    return a * a / p["R"]


def edge_radius(r, pr):
    """Contact radius from the nodal pressures along a radius. The multiplier's weak complementarity leaves a
    small oscillating tail outside the contact, so the zone ends at the first node where p <= 0 (index k+1);
    a is the root of a least-squares quadratic in r fitted to p^2 over the outer 30 % of the zone (p^2 is
    quadratic in r for Hertz and linear at a square-root edge). Also returned: the plain linear crossing
    between nodes k and k+1, and the cell size at the edge."""
    import numpy as np
    order = np.argsort(r)
    r, pr = r[order], pr[order]
    k = int(np.argmax(pr <= 0)) - 1
    if k < 2:
        raise RuntimeError("contact zone not bounded by the mesh's nodes")
    a_lin = r[k] + (r[k + 1] - r[k]) * pr[k] / (pr[k] - pr[k + 1])
    idx = np.arange(len(r))
    band = (r >= 0.7 * r[k + 1]) & (idx <= k)
    if band.sum() < 5:  # a coarse mesh: the last 5 nodes of the zone
        band = (idx > k - 5) & (idx <= k)
    roots = np.roots(np.polyfit(r[band], pr[band] ** 2, 2))
    roots = roots[np.isreal(roots)].real
    a_fit = roots[np.argmin(np.abs(roots - a_lin))] if len(roots) else float("nan")
    return float(a_fit), float(a_lin), float(r[k + 1] - r[k]), int(band.sum())


def newton(md, label, log):
    """md.solve with GetFEM's Newton (MUMPS); returns (iterations, converged)."""
    res = md.solve("noisy", "max_iter", 60, "max_res", 1e-10, "lsolver", "mumps", "lsearch", "default")
    it, conv = (res[0], bool(res[1])) if isinstance(res, (tuple, list)) and len(res) > 1 else (res, True)
    log(f"{label}: {it} Newton iterations, converged {conv}")
    return int(it), conv


def add_force_controlled_contact(md, mimc, top, w, r2, z, force_density):
    """Contact on z = h: the Alart-Curnier term of GetFEM's integral brick (option 1, with the pressure's
    sign) written out, with the depth an unknown. The pressure lam pushes the top down; lam = max(lam - raug
    gap, 0) weakly, gap = r^2/(2R) - delta - u_z (r2: r^2, z: u_z's component); and delta is the unknown of
    int w lam = F, written as int (w lam - force_density) over the top (w: the measure's weight, 2 pi r on
    the meridian)."""
    md.add_nonlinear_term(mimc, f"{w}*lam*Test_u({z})", top)
    md.add_nonlinear_term(mimc, f"-{w}/raug*(lam - pos_part(lam - raug*({r2}/(2*R) - delta - u({z}))))*Test_lam",
                          top)
    md.add_nonlinear_term(mimc, f"({w}*lam - {force_density})*Test_delta", top)


def taylor_hood_spaces(m, dim, top):
    """Q2 displacement (dim components), Q1 pressure, and the Q1 contact multiplier on region `top` (its
    whole-mesh space, its DOFs there, and the partial space over them), as both GetFEM models use them."""
    import getfem as gf

    mfu = gf.MeshFem(m, dim)
    mfu.set_classical_fem(2)
    mfp = gf.MeshFem(m, 1)
    mfp.set_classical_fem(1)
    mfl_all = gf.MeshFem(m, 1)
    mfl_all.set_classical_fem(1)
    ldof = mfl_all.basic_dof_on_region(top)
    return mfu, mfp, mfl_all, ldof, gf.MeshFem("partial", mfl_all, ldof)


def solve_3d(p, h3d):
    import numpy as np
    import getfem as gf
    h, W, R, F = p["h"], p["W"], p["R"], p["F"]
    mu = p["E"] / (2 * (1 + p["nu"]))
    xy = graded_ticks(W, h3d, 3.0, 1.4, 1.5)  # fine over the contact (a ~ 2.5 mm) and a margin
    z = z_ticks(h, h3d, 1.4, 1.0)
    m = gf.Mesh("cartesian", xy, xy, z)
    TOP, BASE, SYMX, SYMY = 1, 2, 3, 4
    for rid, v in ((TOP, [0, 0, 1]), (BASE, [0, 0, -1]), (SYMX, [-1, 0, 0]), (SYMY, [0, -1, 0])):
        m.set_region(rid, m.outer_faces_with_direction(v, 0.01))
    mfu, mfp, mfl_all, ldof, mfl = taylor_hood_spaces(m, 3, TOP)
    mfobs = gf.MeshFem(m, 1)
    mfobs.set_classical_fem(2)
    mim = gf.MeshIm(m, gf.Integ("IM_GAUSS_PARALLELEPIPED(3,4)"))
    mimc = gf.MeshIm(m, gf.Integ("IM_GAUSS_PARALLELEPIPED(3,8)"))

    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_fem_variable("p", mfp)
    md.add_fem_variable("lam", mfl)
    md.add_initialized_data("mu", [mu])
    md.add_initialized_data("lmb", [0.0])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lmb", "mu")
    md.add_linear_incompressibility_brick(mim, "u", "p")
    md.add_Dirichlet_condition_with_simplification("u", BASE)
    md.add_linear_term(mim, "1e8*u(1)*Test_u(1)", SYMX)  # u_x = 0 on x = 0, penalized
    md.add_linear_term(mim, "1e8*u(2)*Test_u(2)", SYMY)  # u_y = 0 on y = 0
    # The obstacle: on z = h its value is the vertical gap r^2/(2R) - delta; off the surface it grows by
    # C (h - z), C large, so the normal the brick takes from its gradient is vertical to 1e-6 as in the
    # linear theory (Q2 holds this quadratic exactly).
    X = mfobs.basic_dof_nodes()
    rr2, zz = X[0] ** 2 + X[1] ** 2, X[2]
    obstacle = lambda delta: 1e4 * (h - zz) + rr2 / (2 * R) - delta
    md.add_initialized_fem_data("obs", mfobs, obstacle(0.0))
    md.add_initialized_data("r", [p["E"] / h3d])
    md.add_integral_contact_with_rigid_obstacle_brick(mimc, "u", "lam", "obs", "r", TOP, 1)

    def force_at(delta):
        md.set_variable("obs", obstacle(delta))
        it, conv = newton(md, f"delta = {1e3 * delta:.5f} um", LOG)
        lam_int = gf.asm_generic(mimc, 0, "lam", TOP, md)
        return 4.0 * abs(lam_int), -1.0 if lam_int < 0 else 1.0, it, conv

    # depth control: secant on ln F(ln delta) until the force is F
    deltas, forces, iters = [], [], 0
    delta = hertz_halfspace_delta(p)
    status, notes = "ok", ""
    for k in range(12):
        f, sign, it, conv = force_at(delta)
        iters += it
        if not conv:
            status, notes = "not converged", f"Newton did not converge at delta = {1e3 * delta:.4f} um"
            break
        deltas.append(delta)
        forces.append(f)
        LOG(f"  force {f:.8f} N at delta {1e3 * delta:.6f} um")
        if abs(f / F - 1) < 1e-6:
            break
        if len(deltas) == 1:
            delta *= (F / f) ** 0.5
        else:
            slope = (math.log(forces[-1]) - math.log(forces[-2])) / (math.log(deltas[-1]) - math.log(deltas[-2]))
            delta = deltas[-1] * math.exp((math.log(F) - math.log(forces[-1])) / slope)
    else:
        status, notes = "not converged", f"force {forces[-1]:.6f} N after 12 depths"
    res = {"status": status, "notes": notes, "dofs": int(md.nbdof()), "newton_iterations": iters,
           "depths_solved": len(deltas), "mesh": {"cells": int(m.nbcvs()), "h_contact_mm": h3d,
                                                  "xy_ticks": len(xy), "z_ticks": len(z), "half_width_mm": W}}
    if status != "ok":
        return res
    # The brick's multiplier is the normal stress (<= 0 in compression): the pressure is sign * lam, with
    # sign that of its integral.
    pressure = sign * md.variable("lam")
    nodes = mfl_all.basic_dof_nodes(ldof)
    on_x = np.abs(nodes[1]) < 1e-9  # the radius along the symmetry plane y = 0
    if failed := read_pressure(res, nodes[0][on_x], pressure[on_x]):
        return {**res, "status": "failed", "notes": failed}
    res.update(delta_um=1e3 * deltas[-1], force_N=forces[-1],
               notes=f"quarter, Q2/Q1 hexahedra, {h3d} mm under the contact; {len(deltas)} depths, {iters} Newton")
    return res


def edge_fit_radius(r, p):
    """skinfem's read-off of a (contact/metrics.hpp edge_fit_radius), for a scattered top: p^2 at the active
    nodes with r >= 0.6 of the largest active r, fitted by alpha + beta r^2 + gamma r^4; the root nearest
    the largest active r. Active: p above 2 % of its peak, for the weak complementarity's tail outside the
    contact (up to 1 % of the peak at the first nodes out, alternating in sign; skinfem's LCP has none)."""
    import numpy as np
    act = p > 0.02 * p.max()
    r_max = r[act].max()
    band = act & (r >= 0.6 * r_max)
    c = np.polyfit(r[band] ** 2, p[band] ** 2, 2)
    roots = np.roots(c)
    roots = roots[np.isreal(roots) & (roots.real > 0)].real
    return float(np.sqrt(roots[np.argmin(np.abs(roots - r_max ** 2))])), int(band.sum())


def solve_3d_tet(p, mesh_vtu):
    """The whole layer on skinfem's own mesh (10-node tetrahedra, graded toward the contact zone and the
    sensors as skinfem meshes it): P2 displacement / P1 pressure, u = 0 on the base, and the meridian
    model's force-controlled Alart-Curnier contact term on the top (a P1 multiplier, the depth an unknown
    with the force equation int lam dA = F): one Newton solve."""
    import numpy as np
    import getfem as gf
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    h, W, R, F = p["h"], p["W"], p["R"], p["F"]
    mu = p["E"] / (2 * (1 + p["nu"]))
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(mesh_vtu)
    reader.Update()
    grid = reader.GetOutput()
    X = vtk_to_numpy(grid.GetPoints().GetData())
    cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 10)
    # VTK's quadratic tetrahedron: vertices 0-3, then edges 01, 12, 20, 03, 13, 23; GetFEM's GT_PK(3,2): the
    # lattice points, x fastest: v0, 01, v1, 02, 12, v2, 03, 13, 23, v3.
    pts = X[cells[:, [0, 4, 1, 6, 5, 2, 7, 8, 9, 3]]]  # cells x 10 x 3
    m = gf.Mesh("empty", 3)
    m.add_convex(gf.GeoTrans("GT_PK(3,2)"), np.ascontiguousarray(pts.transpose(2, 1, 0)))
    TOP, BASE = 1, 2
    for rid, v in ((TOP, [0, 0, 1]), (BASE, [0, 0, -1])):
        m.set_region(rid, m.outer_faces_with_direction(v, 0.01))
    mfu, mfp, mfl_all, ldof, mfl = taylor_hood_spaces(m, 3, TOP)
    mim = gf.MeshIm(m, gf.Integ("IM_TETRAHEDRON(5)"))
    mimc = gf.MeshIm(m, gf.Integ("IM_TETRAHEDRON(8)"))
    volume = gf.asm_generic(mim, 0, "1", -1)
    if abs(volume / (4 * W * W * h) - 1) > 1e-9:
        raise RuntimeError(f"the imported mesh's volume {volume} is not the layer's {4 * W * W * h}")
    # The cell size under the contact, for the augmentation: the mean edge of the top faces within 3 mm.
    top_nodes = mfl_all.basic_dof_nodes(ldof)
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_fem_variable("p", mfp)
    md.add_fem_variable("lam", mfl)  # contact pressure, >= 0
    md.add_variable("delta", 1)
    md.set_variable("delta", [hertz_halfspace_delta(p)])
    h_top = 2 * W / math.sqrt(len(ldof))  # rough: only sets the augmentation's scale
    for name, v in (("mu", mu), ("lmb", 0.0), ("R", R), ("F", F), ("A", 4 * W * W), ("raug", p["E"] / h_top)):
        md.add_initialized_data(name, [v])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lmb", "mu")
    md.add_linear_incompressibility_brick(mim, "u", "p")
    md.add_Dirichlet_condition_with_simplification("u", BASE)
    add_force_controlled_contact(md, mimc, TOP, "1", "(sqr(X(1))+sqr(X(2)))", 3, "F/A")
    it, conv = newton(md, "3d, skinfem's mesh", LOG)
    res = {"dofs": int(md.nbdof()), "newton_iterations": it,
           "mesh": {"cells": int(m.nbcvs()), "nodes": int(len(X)), "top_multipliers": int(len(ldof)),
                    "source": mesh_vtu, "half_width_mm": W}}
    if not conv:
        return {**res, "status": "not converged", "notes": f"Newton did not converge ({it} iterations)"}
    lam = md.variable("lam")
    r = np.hypot(top_nodes[0], top_nodes[1])
    order = np.argsort(r)
    res["pressure_profile"] = {"r_mm": r[order].tolist(), "p_kPa": (1e3 * lam[order]).tolist()}
    a, nfit = edge_fit_radius(r, lam)
    force = gf.asm_generic(mimc, 0, "lam", TOP, md)
    res.update(status="ok", a_mm=a, edge_fit_nodes=nfit, p0_kPa=1e3 * float(lam.max()),
               delta_um=1e3 * float(md.variable("delta")[0]), force_N=float(force),
               notes=f"skinfem's whole mesh, P2/P1 tetrahedra, force controlled; {it} Newton")
    return res


def read_pressure(res, r, pr):
    """The nodal pressure pr (MPa) at radii r (mm) into res: its profile sorted by r, p0 (the innermost node)
    and the edge fit's contact radius. Returns why the edge could not be fitted, or None."""
    import numpy as np
    order = np.argsort(r)
    res["pressure_profile"] = {"r_mm": r[order].tolist(), "p_kPa": (1e3 * pr[order]).tolist()}
    try:
        a_fit, a_lin, hc, nfit = edge_radius(r, pr)
    except RuntimeError as e:
        return f"reading a: {e}"
    res.update(a_mm=a_fit, edge_fit_nodes=nfit, a_linear_crossing_mm=a_lin, p0_kPa=1e3 * float(pr[order][0]),
               edge_cell_mm=hc)
    return None


def solve_meridian(p, hmer, growth=1.2, r_coarse=1.0, z_coarse=0.5):
    import getfem as gf
    # The unbounded layer as skinfem's meridian path takes it: radius 20 h, traction-free there (at the
    # scene's 15 mm the free rim softens the layer: delta +5e-4, a and p0 within 1e-4 of this).
    h, R, F = p["h"], p["R"], p["F"]
    W = 20 * h
    mu = p["E"] / (2 * (1 + p["nu"]))
    rt = graded_ticks(W, hmer, 3.0, growth, r_coarse)
    z = z_ticks(h, hmer, growth, z_coarse)
    m = gf.Mesh("cartesian", rt, z)
    TOP, BASE, AXIS = 1, 2, 3
    for rid, v in ((TOP, [0, 1]), (BASE, [0, -1]), (AXIS, [-1, 0])):
        m.set_region(rid, m.outer_faces_with_direction(v, 0.01))
    mfu, mfp, mfl_all, ldof, mfl = taylor_hood_spaces(m, 2, TOP)
    mim = gf.MeshIm(m, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,6)"))
    mimc = gf.MeshIm(m, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,10)"))

    md = gf.Model("real")
    md.add_fem_variable("u", mfu)  # (u_r, u_z)
    md.add_fem_variable("p", mfp)
    md.add_fem_variable("lam", mfl)  # contact pressure, >= 0
    md.add_variable("delta", 1)
    md.set_variable("delta", [hertz_halfspace_delta(p)])
    for name, v in (("mu", mu), ("R", R), ("F", F), ("W", W), ("raug", p["E"] / hmer)):
        md.add_initialized_data(name, [v])
    # Incompressible elasticity on the meridian, all terms x 2 pi r: strain (Sym(Grad_u), u_r / r), divergence
    # Div_u + u_r / r, stress 2 mu eps - p I.
    md.add_linear_term(mim, "2*pi*(2*mu*(X(1)*(Sym(Grad_u):Grad_Test_u) + u(1)*Test_u(1)/X(1))"
                            " - p*(X(1)*Div_Test_u + Test_u(1)) - Test_p*(X(1)*Div_u + u(1)))")
    md.add_Dirichlet_condition_with_simplification("u", BASE)
    md.add_linear_term(mim, "1e8*u(1)*Test_u(1)", AXIS)  # u_r = 0 on the axis, penalized
    add_force_controlled_contact(md, mimc, TOP, "2*pi*X(1)", "sqr(X(1))", 2, "F/W")
    it, conv = newton(md, "meridian", LOG)
    res = {"dofs": int(md.nbdof()), "newton_iterations": it,
           "mesh": {"cells": int(m.nbcvs()), "h_contact_mm": hmer, "r_ticks": len(rt), "z_ticks": len(z),
                    "half_width_mm": W}}
    if not conv:
        return {**res, "status": "not converged", "notes": f"Newton did not converge ({it} iterations)"}
    if failed := read_pressure(res, mfl_all.basic_dof_nodes(ldof)[0], md.variable("lam")):
        return {**res, "status": "failed", "notes": failed}
    force = gf.asm_generic(mimc, 0, "2*pi*X(1)*lam", TOP, md)
    res.update(status="ok", delta_um=1e3 * float(md.variable("delta")[0]), force_N=float(force),
               notes=f"axisymmetric weak form, Q2/Q1 quadrangles, {hmer} mm under the contact; {it} Newton")
    return res


def LOG(msg):
    print(msg, flush=True)


def worker(args):
    p = load_problem()
    t0 = time.perf_counter()
    try:
        if args.worker == "3d":
            res = solve_3d(p, args.h3d)
        elif args.worker == "3d_whole":
            res = solve_3d_tet(p, args.mesh)
        else:
            res = solve_meridian(p, args.hmer)
    except Exception as e:  # a failed GetFEM run is a row that says so
        res = {"status": "failed", "notes": f"{type(e).__name__}: {e}"}
    res["solve_seconds"] = time.perf_counter() - t0
    Path(args.result).write_text(json.dumps(res, indent=1))
    LOG(json.dumps({k: v for k, v in res.items() if k != "pressure_profile"}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
