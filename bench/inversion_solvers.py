#!/usr/bin/env python3
"""Which sparse solver the inversion should use (issue 55, deliverable 4; docs/perception.md, "The solver"):
non-negative least squares, orthogonal matching pursuit or an l1 penalty, each from a library, on skinfem's
own dictionary and signals.

The fit is `skinfem invert`'s (validation/inversion.hpp) at the nominal offset: a hole at plate position q
with amplitude a gives sensor i the signal a R_i(q + u); the samples are whitened by the noise of the mean of
N passages (0.6 kPa on varsigma_z, 0.4 kPa on varsigma_x per passage), the atoms are the hole on the scan's
grid. The solvers:
- nnls:  scipy.optimize.nnls (Lawson and Hanson's active set, the algorithm skinfem's own nnls implements);
- omp:   sklearn's OrthogonalMatchingPursuit on unit-norm atoms, stopped when the residual's squared norm
         falls to the noise's expected one (the number of samples: the discrepancy principle); negative
         amplitudes are not holes and are dropped;
- lasso: sklearn's Lasso with positive amplitudes, its penalty chosen by the same discrepancy principle
         (bisection on log alpha).
Each solver's amplitudes become features as skinfem's do (adjacent non-zero atoms merge at their weighted
position; a feature below the 1 % false-alarm SNR, 2.326, is dropped).

Two measurements:
- row: `scenes/texture_row.json`'s full FE scan (sliding, 20 holes of 0.5 mm at 0.9 mm, 401 positions),
  noise-free (fitted as the mean of 10,000 passages) and with the paper's noise at N = 14 (10 seeds). Scored as docs/perception.md's table: features
  within 0.45 mm of a hole are its, missed counts the 11 holes that cross the contact's centre. The nnls
  row also checks skinfem's own nnls: on the noise-free signals its least residual must be `skinfem invert`'s
  to 1e-6, its features the same number within half a step.
- pairs: two of the scene's holes s apart, the dictionary's signals superposed plus noise (N = 1, 4, 14,
  20 draws), every second dictionary position (0.05 mm); resolved when each hole has its own feature within
  half the spacing; limit = the smallest spacing from which on 90 % of the draws are resolved.

A third, `fe-pairs`: the pairs scanned by the FE (`skinfem scan`, the full contact, sliding, every 0.05 mm;
spacings as above, a fresh process of about 20 s each) and inverted by NNLS with the same noise: the
resolution on FE signals, against the model's (OUT/fe_pairs.csv: passages,spacing_mm,resolved_fraction).

    $ apt-get install python3-scipy python3-sklearn
    $ /usr/bin/python3 bench/inversion_solvers.py build/app/skinfem out/inversion_solvers [fe-pairs]
    row, noise-free: nnls 20 features, 0 missed, rms 0.033 mm ...

Writes OUT/row.csv (solver,signals,features,missed,false,rms_mm,largest_mm,seconds) and OUT/pairs.csv
(solver,passages,spacing_mm,resolved_fraction,mean_seconds), after `skinfem scan` (OUT/scan, about 50 s) and
`skinfem invert --offset-range 0` on the default scene (OUT/invert, its dictionary.csv; about 15 s).
"""
import csv
import json
import math
import os
import subprocess
import sys
import time
import warnings

import numpy as np

try:
    from scipy.optimize import nnls as scipy_nnls
    from sklearn.exceptions import ConvergenceWarning
    from sklearn.linear_model import Lasso, OrthogonalMatchingPursuit
except ImportError as e:
    sys.exit(f"inversion_solvers: {e}: apt-get install python3-scipy python3-sklearn")

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SIGMA = (0.6, 0.4)  # kPa per passage: varsigma_z, varsigma_x (the paper, section IV)
TAU = 2.326347874  # Phi^-1(0.99)
ROW_HOLES = [-13.3 + 0.9 * k for k in range(20)]  # scenes/texture_row.json's lattice
SPACINGS = [0.6, 0.7, 0.8, 1.0, 1.2, 1.5]
PASSAGES = [1, 4, 14]
DRAWS = 20
# Noise-free signals are fitted as the mean of this many passages: OMP's and the l1 penalty's stopping rule
# needs a noise level, and the paper's (N = 14) would stop them before the signal (its energy is below the
# noise's over the 401 positions).
CLEAN_PASSAGES = 10000


def read_dictionary(path):
    """R[m, s, c]: the response of site s to the hole at x0 + m dx (kPa), and the grid."""
    rows = list(csv.DictReader(open(path)))
    xs = sorted({float(r["x_mm"]) for r in rows})
    sites = sorted({float(r["site_mm"]) for r in rows})
    R = np.zeros((len(xs), len(sites), 2))
    xi = {x: i for i, x in enumerate(xs)}
    si = {s: i for i, s in enumerate(sites)}
    for r in rows:
        R[xi[float(r["x_mm"])], si[float(r["site_mm"])]] = (float(r["R_z_kPa"]), float(r["R_x_kPa"]))
    return R, xs[0], (xs[-1] - xs[0]) / (len(xs) - 1), sites


def weights(n):
    return np.array([math.sqrt(n) / SIGMA[0], math.sqrt(n) / SIGMA[1]])


def design(R, nu, w):
    """The whitened fit: atom j reads the dictionary's row j - (nu - 1) + i at sample i (skinfem's layout)."""
    rows, ns = R.shape[0], R.shape[1]
    atoms = rows + nu - 1
    A = np.zeros((nu, ns, 2, atoms))
    for j in range(atoms):
        i0, i1 = max(0, nu - 1 - j), min(nu, rows + nu - 1 - j)
        if i1 > i0:
            A[i0:i1, :, :, j] = R[j - (nu - 1) + i0:j - (nu - 1) + i1] * w
    A = A.reshape(nu * ns * 2, atoms)
    # skinfem's rule: an atom below 1e-6 of the largest response (round-off) is left out.
    norms = np.linalg.norm(A, axis=0)
    A[:, norms <= 1e-6 * norms.max()] = 0
    return A


def solve(name, A, b):
    m = A.shape[0]
    if name == "nnls":
        return scipy_nnls(A, b, maxiter=50 * A.shape[1])[0]
    if name == "omp":
        norms = np.linalg.norm(A, axis=0)
        norms[norms == 0] = 1  # the left-out atoms stay zero
        omp = OrthogonalMatchingPursuit(tol=float(m), fit_intercept=False)
        omp.fit(A / norms, b)
        return omp.coef_ / norms
    # lasso: sklearn minimises |b - A a|^2 / (2 m) + alpha |a|_1; the residual grows with alpha.
    G = A.T @ A
    hi = float(np.max(A.T @ b)) / m
    lo = hi * 1e-7
    best = None
    for _ in range(18):
        alpha = math.sqrt(lo * hi)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ConvergenceWarning)
            fit = Lasso(alpha=alpha, fit_intercept=False, positive=True, precompute=G, max_iter=20000,
                        tol=1e-6).fit(A, b)
        r2 = float(np.sum((b - A @ fit.coef_) ** 2))
        if r2 > m:
            hi = alpha
        else:
            lo, best = alpha, fit.coef_
    return best if best is not None else fit.coef_


def features(a, A, q0, dx):
    """Adjacent positive atoms merged: (position, amplitude, snr), the weak ones dropped."""
    out, j, n = [], 0, len(a)
    while j < n:
        if not a[j] > 0:
            j += 1
            continue
        k = j
        while k < n and a[k] > 0:
            k += 1
        amp = a[j:k].sum()
        pos = float(np.dot(a[j:k], q0 + dx * np.arange(j, k)) / amp)
        snr = float(np.linalg.norm(A[:, j:k] @ a[j:k]))
        if snr >= TAU:
            out.append((pos, amp, snr))
        j = k
    return out


def score(found, truth, reach, counted):
    """skinfem's score_inversion: a feature goes to the nearest hole within reach, a second one is false."""
    best = {}
    false = 0
    for pos, _, _ in found:
        near = min(range(len(truth)), key=lambda k: abs(pos - truth[k]))
        if abs(pos - truth[near]) >= reach:
            false += 1
            continue
        if near in best:
            false += 1
        best[near] = min(best.get(near, 1e300), abs(pos - truth[near]))
    errors = [best[k] for k in counted if k in best]
    missed = sum(1 for k in counted if k not in best)
    rms = math.sqrt(sum(e * e for e in errors) / len(errors)) if errors else float("nan")
    return missed, false, rms, max(errors) if errors else float("nan")


def run(cmd):
    print("  $", " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def resolved(found, truth, s):
    """Each hole's nearest feature within half the spacing, and not the same one."""
    mine = [min((abs(p - h), p) for p, _, _ in found)[1] if found else None for h in truth]
    return all(m is not None and abs(m - h) < s / 2 for m, h in zip(mine, truth)) and mine[0] != mine[1]


def limit_of(fractions):
    """The smallest spacing from which on every one is resolved on 90 % of the draws."""
    k = len(fractions)
    while k > 0 and fractions[k - 1][1] >= 0.9:
        k -= 1
    if k == len(fractions):
        return "none resolved on 90 %"
    return f"<= {fractions[0][0]:.2f} mm" if k == 0 else f"{fractions[k][0]:.2f} mm"


def read_scan(path, case="sliding"):
    sig = {}
    for r in csv.DictReader(open(path)):
        if r.get("case", case) == case:
            sig.setdefault(float(r["u_mm"]), {})[int(r["sensor"])] = (float(r["varsigma_z_kPa"]),
                                                                      float(r["varsigma_x_kPa"]))
    u = sorted(sig)
    return u, np.array([[sig[v][s] for s in sorted(sig[v])] for v in u])  # nu x ns x 2


def fe_pairs(exe, out, R, x0, dx):
    """Two 0.5 mm holes s apart on the default scene, scanned by the FE (full contact, sliding, every
    0.05 mm), with the paper's noise, inverted by NNLS: the resolution on FE signals, against the model's."""
    base = json.load(open(os.path.join(ROOT, "scenes/candelier2011.json")))
    Rp, dxp = R[::2], 2 * dx
    rows = []
    for s in SPACINGS:
        scene = json.loads(json.dumps(base))
        c = scene["contact"]
        c.pop("sweep", None)
        reach = 4.0 + 0.25 + 0.5 * s
        c["texture"] = {"holes": [{"center": [-0.5 * s, 0.0], "diameter": 0.5},
                                  {"center": [0.5 * s, 0.0], "diameter": 0.5}], "h": 0.25}
        c["scan"] = {"from": round(0.5 - reach, 2), "to": round(0.5 + reach, 2), "step": dxp}
        scene["name"] = "pair"
        d = os.path.join(out, f"pair_{s:.2f}")
        if not os.path.exists(os.path.join(d, "scan.csv")):
            path = d + ".json"
            json.dump(scene, open(path, "w"), indent=1)
            run([exe, "scan", path, "--no-superposition", "--out", d])
        u, y = read_scan(os.path.join(d, "scan.csv"))
        nu = len(u)
        q0 = x0 - u[0] - (nu - 1) * dxp
        truth = [-0.5 * s, 0.5 * s]
        for n in PASSAGES:
            w = weights(n)
            A = design(Rp, nu, w)
            rng = np.random.default_rng(2000 + n)
            hits = sum(resolved(features(solve("nnls", A, ((y + rng.standard_normal(y.shape) * np.array(SIGMA) /
                                                               math.sqrt(n)) * w).reshape(-1)), A, q0, dxp),
                                truth, s) for _ in range(DRAWS))
            rows.append([n, s, hits / DRAWS])
        print(f"FE pair s = {s:.2f} mm: resolved " + ", ".join(f"N = {r[0]} {r[2]:.0%}" for r in rows[-3:]),
              flush=True)
    with open(os.path.join(out, "fe_pairs.csv"), "w", newline="") as fh:
        wr = csv.writer(fh)
        wr.writerow(["passages", "spacing_mm", "resolved_fraction"])
        wr.writerows(rows)
    for n in PASSAGES:
        print(f"limit on FE signals, N = {n:2d}: {limit_of([(r[1], r[2]) for r in rows if r[0] == n])}")


def main():
    if len(sys.argv) not in (3, 4) or (len(sys.argv) == 4 and sys.argv[3] != "fe-pairs"):
        sys.exit("usage: bench/inversion_solvers.py SKINFEM OUT [fe-pairs]")
    exe, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    scan_dir, inv_dir = os.path.join(out, "scan"), os.path.join(out, "invert")
    if not os.path.exists(os.path.join(scan_dir, "scan.csv")):
        run([exe, "scan", os.path.join(ROOT, "scenes/texture_row.json"), "--out", scan_dir])
    if not os.path.exists(os.path.join(inv_dir, "dictionary.csv")):
        run([exe, "invert", os.path.join(scan_dir, "scan.csv"), os.path.join(ROOT, "scenes/candelier2011.json"),
             "--offset-range", "0", "--out", inv_dir])
    R, x0, dx, sites = read_dictionary(os.path.join(inv_dir, "dictionary.csv"))
    if len(sys.argv) == 4 and sys.argv[3] == "fe-pairs":
        return fe_pairs(exe, out, R, x0, dx)

    # The row: the FE scan's sliding signals.
    u, y = read_scan(os.path.join(scan_dir, "scan.csv"))
    nu = len(u)
    w14, wclean = weights(14), weights(CLEAN_PASSAGES)
    A = design(R, nu, w14)
    Aclean = design(R, nu, wclean)
    q0 = x0 - u[0] - (nu - 1) * dx
    crossing = [k for k, p in enumerate(ROW_HOLES) if p + u[0] <= 0.5 <= p + u[-1]]  # the apex at x = 0.5
    ours = [float(r["position_mm"]) for r in csv.DictReader(open(os.path.join(inv_dir, "features.csv")))]
    ours_r2 = json.load(open(os.path.join(inv_dir, "summary.json")))["weighted_residuals"][0]
    rng = np.random.default_rng(14)
    noises = [rng.standard_normal(y.shape) * np.array(SIGMA) / math.sqrt(14) for _ in range(10)]
    row_rows = []
    for solver in ["nnls", "omp", "lasso"]:
        if solver == "nnls":
            # skinfem's own nnls on the same fit (the paper's noise, N = 14).
            b = (y * w14).reshape(-1)
            a = solve("nnls", A, b)
            f = features(a, A, q0, dx)
            # The same convex problem: the same least residual (its minimiser may differ along near-null
            # directions of A, shifting the features within the step).
            r2 = float(np.sum((b - A @ a) ** 2))
            diff = max((min(abs(p - o) for o in ours) for p, _, _ in f), default=0)
            print(f"nnls against skinfem's: residual {r2:.6g} against {ours_r2:.6g}, {len(f)} features "
                  f"against {len(ours)}, positions within {diff:.1e} mm")
            if abs(r2 - ours_r2) > 1e-6 * ours_r2 or len(f) != len(ours) or diff > dx / 2:
                sys.exit("inversion_solvers: scipy's nnls and skinfem's disagree")
        for label, Af, w, draws in [("noise-free", Aclean, wclean, [np.zeros_like(y)]),
                                    ("N=14, 10 seeds", A, w14, noises)]:
            tallies = []
            for noise in draws:
                b = ((y + noise) * w).reshape(-1)
                t = time.perf_counter()
                a = solve(solver, Af, b)
                seconds = time.perf_counter() - t
                f = features(a, Af, q0, dx)
                tallies.append((len(f),) + score(f, ROW_HOLES, 0.45, crossing) + (seconds,))
            t = np.array(tallies, dtype=float)
            # A row with no hole matched has no position error (nan): averaged over the others.
            mean = [float(np.nanmean(c)) if np.isfinite(c).any() else float("nan") for c in t.T]
            row_rows.append([solver, label, *mean])
            print(f"row, {label}: {solver:5s} {mean[0]:5.1f} features, {mean[1]:.1f} missed, {mean[2]:.1f} false, "
                  f"rms {mean[3]:.3f} mm, largest {mean[4]:.3f} mm, {mean[5]:.2f} s", flush=True)
    with open(os.path.join(out, "row.csv"), "w", newline="") as fh:
        wr = csv.writer(fh)
        wr.writerow(["solver", "signals", "features", "missed", "false", "rms_mm", "largest_mm", "seconds"])
        for r in row_rows:
            wr.writerow(r[:2] + [f"{v:.4g}" for v in r[2:]])

    # Pairs on the dictionary model, every second position.
    Rp, dxp = R[::2], 2 * dx
    rows = Rp.shape[0]
    pair_rows = []
    for n in PASSAGES:
        w = weights(n)
        rng = np.random.default_rng(1000 + n)
        for s in SPACINGS:
            gap = round(s / dxp)
            nu = rows + gap
            # Hole 1 enters the grid at the first sample, hole 2 (gap behind) leaves it at the last.
            y = np.zeros((nu, Rp.shape[1], 2))
            y[:rows] += Rp
            y[gap:] += Rp
            A = design(Rp, nu, w)
            q0 = x0 - (nu - 1) * dxp  # u starts at 0
            truth = [x0, x0 - gap * dxp]
            counts = {name: [0, 0.0] for name in ["nnls", "omp", "lasso"]}
            for _ in range(DRAWS):
                b = ((y + rng.standard_normal(y.shape) * np.array(SIGMA) / math.sqrt(n)) * w).reshape(-1)
                for name in counts:
                    t = time.perf_counter()
                    f = features(solve(name, A, b), A, q0, dxp)
                    counts[name][1] += time.perf_counter() - t
                    counts[name][0] += resolved(f, truth, s)
            for name, (resolved, seconds) in counts.items():
                pair_rows.append([name, n, gap * dxp, resolved / DRAWS, seconds / DRAWS])
            print(f"pairs, N = {n}, s = {gap * dxp:.2f} mm: " +
                  ", ".join(f"{k} {v[0] / DRAWS:.0%}" for k, v in counts.items()), flush=True)
    with open(os.path.join(out, "pairs.csv"), "w", newline="") as fh:
        wr = csv.writer(fh)
        wr.writerow(["solver", "passages", "spacing_mm", "resolved_fraction", "mean_seconds"])
        for r in pair_rows:
            wr.writerow([r[0], r[1], f"{r[2]:.3f}", f"{r[3]:.2f}", f"{r[4]:.3g}"])
    for name in ["nnls", "omp", "lasso"]:
        for n in PASSAGES:
            print(f"limit {name:5s} N = {n:2d}: {limit_of([(r[2], r[3]) for r in pair_rows if r[0] == name and r[1] == n])}")


if __name__ == "__main__":
    main()
