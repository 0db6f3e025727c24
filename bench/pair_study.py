#!/usr/bin/env python3
"""Where the paper's superposition holds: two holes against their spacing, and rows of holes against their
period (docs/contact.md, "Textures and scans").

For each spacing s, the default scene's plate carries two 0.5 mm holes s apart on y = 0, scanned through the
whole zone; `skinfem scan` writes the scan and the sum of the two single-hole scans, and this script tabulates
the largest difference over the largest signal (varsigma_z and varsigma_x, static and sliding) per friction
hypothesis: Coulomb under a hard interface, a shear strength under a hard interface, Coulomb through a rough
(linear) interface.

    $ /usr/bin/python3 bench/pair_study.py build/app/skinfem out/pair_study [pairs|rows|twins|lattices|random|lattice_laws|gratings]
    coulomb_hard         s = 0.60 mm: sliding z 3.7 %, x 3.7 %

Rows: Coulomb under a hard interface, the plate covered by a row of 0.5 mm holes at a period p on y = 0,
scanned 4 mm at 0.05 mm, every hole crossing the zone (rows.csv: period_mm,case,holes,most_holes,rel_diff_z,
rel_diff_x,single_hole_solves,seconds).

Twins: two 0.5 mm holes s apart across the sliding direction (at y = +-s/2), on the whole skin
("symmetry": "none"): the interaction the half model leaves out of a mirror-symmetric texture's superposition
(twins.csv: spacing_mm,case,rel_diff_z,rel_diff_x,max_diff_z_kPa,max_diff_x_kPa,dofs,watched_nodes,seconds).

Lattices and random textures (Coulomb, hard, 4 mm scanned at 0.05 mm): square lattices of 0.5 mm holes
centred on y = 0 against their period, and holes of 0.3 to 0.6 mm drawn at random in mirrored pairs against
their density (two seeds), on the plate's rectangle whose holes reach the zone during the scan. Both are
mirror-symmetric, so the half skin solves them (docs/contact.md, "Textures off the axis"): 93,000-148,000
DOFs, 850-3,700 watched nodes, 10 s to 4 min per texture on 2 cores (lattices.csv, random.csv: texture,label,
density_per_mm2,case,holes,closest_rims_mm,most_holes,rel_diff_z,rel_diff_x,mirror_pair_terms,dofs,
watched_nodes,seconds,peak_mb). lattice_laws: the lattices of 0.9, 1.0 and 1.2 mm (about the 5 % line of
Coulomb, hard) under a shear strength and through a rough interface (lattice_laws.csv, the same columns).

Gratings (Coulomb, hard, 4 mm scanned at 0.05 mm): grooves 0.5 mm wide across the sliding direction, 9 mm
long (beyond the 4 mm zone on both sides of y = 0, so the half skin solves them), against their period, and
one groove alone (gratings.csv: period_mm,case,grooves,most_in_zone,rel_diff_z,rel_diff_x,peak_z_kPa,
peak_x_kPa,dofs,watched_nodes,seconds,peak_mb; the single groove, its period empty, is scanned through the
whole zone, 9 mm).

A run already in OUT with the same scene file is reused.

Writes OUT/pair_study.csv (hypothesis,spacing_mm,case,rel_diff_z,rel_diff_x,max_diff_z_kPa,max_diff_x_kPa,
most_holes,seconds) and OUT/pair_study.png. Every run is a fresh process (mesh and factorization included):
about 25 s per spacing and hypothesis on a 2-core machine.
"""
import csv
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SPACINGS = [0.6, 0.8, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0]
HYPOTHESES = {
    "coulomb_hard": {},
    "shear_strength_hard": {"friction": {"law": "shear_strength"}},
    # A rough interface closing by p/K, K = p_mean / 1 um (p_mean = 0.8 N over a contact 5 mm across).
    "coulomb_linear_K40": {"interface": {"law": "linear", "K": 40.0}},
}


def write_csv(out, name, rows, header):
    with open(os.path.join(out, name), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)


def with_hypothesis(c, extra):
    """The contact section c under a hypothesis of HYPOTHESES (its keys merged into c's)."""
    for k, v in extra.items():
        if isinstance(v, dict) and isinstance(c.get(k), dict):
            c[k].update(v)
        else:
            c[k] = v


def scene(base, spacing, extra):
    s = json.loads(json.dumps(base))
    c = s["contact"]
    c.pop("sweep", None)
    with_hypothesis(c, extra)
    # The pair centred on the plate's origin, scanned from wholly before the zone to wholly after it.
    x0, reach = 0.5, 4.0 + 0.25 + 0.5 * spacing
    c["texture"] = {"holes": [{"center": [-0.5 * spacing, 0.0], "diameter": 0.5},
                              {"center": [0.5 * spacing, 0.0], "diameter": 0.5}], "h": 0.25}
    c["scan"] = {"from": round(x0 - reach, 3), "to": round(x0 + reach, 3), "step": 0.05}
    s["name"] = "pair"
    return s


PERIODS = [0.6, 0.75, 0.9, 1.2, 1.5, 2.0, 3.0]


def run_scan(skinfem, out, name, scene_json):
    """skinfem scan of the scene into OUT/NAME; a run already there of the same scene file is reused."""
    path = os.path.join(out, name + ".json")
    text = json.dumps(scene_json, indent=1)
    run_dir = os.path.join(out, name)
    summary = os.path.join(run_dir, "summary.json")
    if os.path.exists(path) and open(path).read() == text and os.path.exists(summary):
        done = json.load(open(summary))
        if "closest_rims_mm" in done or done["holes"] < 2:
            return done
    open(path, "w").write(text)
    subprocess.run([skinfem, "scan", path, "--out", run_dir], check=True, stdout=subprocess.DEVNULL,
                   env=dict(os.environ, OPENBLAS_NUM_THREADS="1"))
    return json.load(open(os.path.join(run_dir, "summary.json")))


def main_rows(skinfem, out, base):
    rows = []
    x0, R, L = 0.5, 4.0, 4.0
    for p in PERIODS:
        s = json.loads(json.dumps(base))
        c = s["contact"]
        c.pop("sweep", None)
        count = int((2 * R + L) / p) + 1
        c["texture"] = {"lattice": {"origin": [round(x0 - R - L, 6), 0.0], "period": [p, 1.0],
                                    "count": [count, 1], "diameter": 0.5}, "h": 0.25}
        c["scan"] = {"from": 0.0, "to": L, "step": 0.05}
        s["name"] = "row"
        summary = run_scan(skinfem, out, f"row_{p:.2f}", s)
        for case, k in summary["cases"].items():
            sp = k["superposition"]
            rows.append([p, case, count, k["most_holes_in_zone"], sp["rel_diff_z"], sp["rel_diff_x"],
                         sp["single_hole_solves"], summary["wall_total_s"]])
            print(f"row p = {p:.2f} mm ({count} holes, up to {k['most_holes_in_zone']} in the zone): {case:7s} "
                  f"z {100 * sp['rel_diff_z']:.1f} %, x {100 * sp['rel_diff_x']:.1f} %", flush=True)
    write_csv(out, "rows.csv", rows, [
        "period_mm", "case", "holes", "most_holes", "rel_diff_z", "rel_diff_x", "single_hole_solves",
        "seconds"])


def textured(base, texture, name, extra=None):
    """The default scene, its plate carrying `texture`, scanned 4 mm at 0.05 mm (Coulomb, hard, or the
    hypothesis `extra`), the candidate zone 4 mm in radius, every hole's track watched."""
    s = json.loads(json.dumps(base))
    c = s["contact"]
    c.pop("sweep", None)
    with_hypothesis(c, extra or {})
    c["zone_radius"] = ZONE
    c["texture"] = dict(texture, h=0.25)
    c["scan"] = {"from": 0.0, "to": 4.0, "step": 0.05}
    s["name"] = name
    return s


# The plate's rectangle every hole of which reaches the candidate zone (radius 4 mm about x = 0.5: the
# sliding contact reaches 3.1 mm, and the zone needs an element more) during the 4 mm scan: |y| <= 2.5 mm
# (the contact's half width), x within the zone's caps there (sqrt(4^2 - 2.5^2) = 3.12 mm, less 0.07 mm).
ZONE = 4.0
PLATE = ([0.5 - 4.0 - 3.05, -2.5], [0.5 + 3.05, 2.5])
LATTICE_PERIODS = [0.75, 0.9, 1.0, 1.2, 1.5, 2.0, 3.0]
DENSITIES = [0.25, 0.5, 1.0, 1.5]  # holes per mm^2
SEEDS = [1, 2]


def density_rows(kind, points):
    """One table for lattices and random textures: density, holes, interaction, cost."""
    return [[kind, label, density, case, summary["holes"], summary.get("closest_rims_mm", ""),
             k["most_holes_in_zone"],
             k["superposition"]["rel_diff_z"], k["superposition"]["rel_diff_x"],
             k["superposition"]["mirror_pair_solves"], summary["dofs"], summary["watched_nodes"],
             summary["wall_total_s"], summary["peak_rss_mb"]]
            for label, density, summary in points for case, k in summary["cases"].items()]


def lattice(p):
    """A square lattice of 0.5 mm holes at period p on the plate's rectangle, rows on y = 0, +-p, ..."""
    ny = 2 * int(PLATE[1][1] / p + 1e-9) + 1
    nx = int((PLATE[1][0] - PLATE[0][0]) / p + 1e-9) + 1
    return {"lattice": {"origin": [PLATE[0][0], -(ny // 2) * p], "period": [p, p], "count": [nx, ny],
                        "diameter": 0.5}}


# Lattices about the Coulomb, hard 5 % line under the other friction hypotheses.
LAW_LATTICE_PERIODS = [0.9, 1.0, 1.2]


def main_density(skinfem, out, base, part):
    """Square lattices (rows on y = 0, +-p, ...) against their period, and random textures (0.3 to 0.6 mm,
    mirrored) against their density: mirror-symmetric, so solved on the half; `lattice_laws`: the lattices
    about the 5 % line under the other hypotheses."""
    points = []
    if part == "lattices":
        for p in LATTICE_PERIODS:
            summary = run_scan(skinfem, out, f"lattice_{p:.2f}", textured(base, lattice(p), "lattice"))
            points.append((f"p = {p:.2f} mm", 1 / p ** 2, summary))
    elif part == "lattice_laws":
        for name, extra in list(HYPOTHESES.items())[1:]:
            for p in LAW_LATTICE_PERIODS:
                s = textured(base, lattice(p), "lattice", extra)
                summary = run_scan(skinfem, out, f"lattice_{name}_{p:.2f}", s)
                points.append((f"{name} p = {p:.2f} mm", 1 / p ** 2, summary))
    else:
        for d in DENSITIES:
            for seed in SEEDS:
                tex = {"random": {"from": PLATE[0], "to": PLATE[1], "density": d, "diameter": [0.3, 0.6],
                                  "seed": seed, "mirror": True}}
                summary = run_scan(skinfem, out, f"random_{d:.2f}_{seed}", textured(base, tex, "random"))
                points.append((f"seed {seed}", d, summary))
    rows = density_rows(part, points)
    for r in rows:
        print(f"{part} {r[1]} ({r[2]:.2f} /mm^2, {r[4]} holes, rims {r[5]:.3f} mm apart at the closest, up to "
              f"{r[6]} in the zone): {r[3]:7s} z {100 * r[7]:.1f} %, x {100 * r[8]:.1f} %  ({r[10]} DOFs, "
              f"{r[11]} watched nodes, {r[12]:.0f} s, {r[13]:.0f} MB)", flush=True)
    write_csv(out, part + ".csv", rows, [
        "texture", "label", "density_per_mm2", "case", "holes", "closest_rims_mm", "most_holes", "rel_diff_z",
        "rel_diff_x", "mirror_pair_terms", "dofs", "watched_nodes", "seconds", "peak_mb"])


# A hole and its mirror image s apart across the sliding direction, on the whole skin: the interaction the
# half model leaves out of a mirror-symmetric texture's superposition (its terms are such pairs).
TWIN_SPACINGS = [0.6, 1.0, 1.5, 2.0, 3.0]


def main_twins(skinfem, out, base):
    rows = []
    for sp in TWIN_SPACINGS:
        s = scene(base, 0.0, {})
        s["symmetry"] = "none"
        s["contact"]["texture"]["holes"] = [{"center": [0.0, 0.5 * sp], "diameter": 0.5},
                                            {"center": [0.0, -0.5 * sp], "diameter": 0.5}]
        x0, reach = 0.5, 4.0 + 0.25
        s["contact"]["scan"] = {"from": round(x0 - reach, 3), "to": round(x0 + reach, 3), "step": 0.05}
        s["name"] = "twins"
        summary = run_scan(skinfem, out, f"twins_{sp:.2f}", s)
        for case, k in summary["cases"].items():
            p = k["superposition"]
            rows.append([sp, case, p["rel_diff_z"], p["rel_diff_x"], p["max_diff_z_kPa"], p["max_diff_x_kPa"],
                         summary["dofs"], summary["watched_nodes"], summary["wall_total_s"]])
            print(f"twins s = {sp:.2f} mm: {case:7s} z {100 * p['rel_diff_z']:.2f} %, x {100 * p['rel_diff_x']:.2f} % "
                  f"({summary['dofs']} DOFs, {summary['watched_nodes']} watched nodes, "
                  f"{summary['wall_total_s']:.0f} s)", flush=True)
    write_csv(out, "twins.csv", rows, [
        "spacing_mm", "case", "rel_diff_z", "rel_diff_x", "max_diff_z_kPa", "max_diff_x_kPa", "dofs",
        "watched_nodes", "seconds"])


GRATING_PERIODS = [0.75, 1.0, 1.5, 2.0, 3.0]


def main_gratings(skinfem, out, base):
    rows = []
    x0, L = 0.5, 4.0
    for p in [None] + GRATING_PERIODS:
        # Every groove crosses the zone during the scan; one groove crosses it at the scan's middle.
        count = 1 if p is None else int((2 * ZONE + L) / p) + 1
        origin = x0 if p is None else x0 - ZONE - L
        tex = {"grooves": {"origin": [round(origin, 6), 0.0], "width": 0.5, "length": 2 * ZONE + 1,
                           "count": count, "period": p if p else 1.0}}
        s = textured(base, tex, "grating")
        if p is None:  # the groove from before the zone to past it
            s["contact"]["scan"] = {"from": -ZONE - 0.5, "to": ZONE + 0.5, "step": 0.05}
        summary = run_scan(skinfem, out, f"grating_{p:.2f}" if p else "groove", s)
        for case, k in summary["cases"].items():
            sp = k.get("superposition", {})
            pz = max(x["peak_abs_varsigma_z_kPa"] for x in k["sensors"])
            px = max(x["peak_abs_varsigma_x_kPa"] for x in k["sensors"])
            rows.append([p or "", case, count, k["most_holes_in_zone"], sp.get("rel_diff_z", ""),
                         sp.get("rel_diff_x", ""), pz, px, summary["dofs"], summary["watched_nodes"],
                         summary["wall_total_s"], summary["peak_rss_mb"]])
            what = f"grating p = {p:.2f} mm ({count} grooves)" if p else "one groove"
            diff = f", sum z {100 * sp['rel_diff_z']:.1f} %, x {100 * sp['rel_diff_x']:.1f} %" if sp else ""
            print(f"{what}, up to {k['most_holes_in_zone']} in the zone: {case:7s} peak z {pz:.2f} kPa, "
                  f"x {px:.2f} kPa{diff} ({summary['dofs']} DOFs, {summary['watched_nodes']} watched nodes, "
                  f"{summary['wall_total_s']:.0f} s, {summary['peak_rss_mb']:.0f} MB)", flush=True)
    write_csv(out, "gratings.csv", rows, [
        "period_mm", "case", "grooves", "most_in_zone", "rel_diff_z", "rel_diff_x", "peak_z_kPa", "peak_x_kPa",
        "dofs", "watched_nodes", "seconds", "peak_mb"])


def main():
    skinfem, out = sys.argv[1], sys.argv[2]
    part = sys.argv[3] if len(sys.argv) > 3 else "pairs"
    os.makedirs(out, exist_ok=True)
    base = json.load(open(os.path.join(HERE, "..", "scenes", "candelier2011.json")))
    if part == "rows":
        return main_rows(skinfem, out, base)
    if part in ("lattices", "random", "lattice_laws"):
        return main_density(skinfem, out, base, part)
    if part == "twins":
        return main_twins(skinfem, out, base)
    if part == "gratings":
        return main_gratings(skinfem, out, base)
    rows = []
    for name, extra in HYPOTHESES.items():
        for s in SPACINGS:
            summary = run_scan(skinfem, out, f"{name}_{s:.2f}", scene(base, s, extra))
            for case, c in summary["cases"].items():
                sp = c["superposition"]
                rows.append([name, s, case, sp["rel_diff_z"], sp["rel_diff_x"], sp["max_diff_z_kPa"],
                             sp["max_diff_x_kPa"], c["most_holes_in_zone"], summary["wall_total_s"]])
                print(f"{name:20s} s = {s:.2f} mm: {case:7s} z {100 * sp['rel_diff_z']:.1f} %, "
                      f"x {100 * sp['rel_diff_x']:.1f} %", flush=True)
    write_csv(out, "pair_study.csv", rows, [
        "hypothesis", "spacing_mm", "case", "rel_diff_z", "rel_diff_x", "max_diff_z_kPa", "max_diff_x_kPa",
        "most_holes", "seconds"])
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
    for ax, case in zip(axes, ["static", "sliding"]):
        for name in HYPOTHESES:
            r = [x for x in rows if x[0] == name and x[2] == case]
            ax.plot([x[1] for x in r], [100 * x[3] for x in r], "o-", label=name + " (z)")
        ax.axhline(5, color="gray", ls=":", label="5 % of the peak")
        ax.set_xlabel("spacing (mm)")
        ax.set_title(case)
    axes[0].set_ylabel("max |scan - sum| / max |scan|, varsigma_z (%)")
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pair_study.png"), dpi=110)


if __name__ == "__main__":
    main()
