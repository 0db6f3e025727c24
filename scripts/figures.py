#!/usr/bin/python3
# scripts/figures.py — the figures of `skinfem report`, drawn from the CSV/JSON files it writes under DIR.
#
#   $ /usr/bin/python3 scripts/figures.py out/candelier2011
#   figures: wrote figures/fig1_calibration.png
#   ...
#   figures: skipped pareto.png: missing study/chain_study.csv
#   figures: 6 written, 1 skipped
#   $ /usr/bin/python3 scripts/figures.py out/candelier2011 --except k_sweep.png,pareto.png
#   $ /usr/bin/python3 scripts/figures.py out/candelier2011 --only k_sweep.png,pareto.png
# --only NAMES / --except NAMES (comma-separated figure names): draw just those, or all but those, and delete
# no other PNG: `skinfem report` draws the figures whose inputs are final while its later stages compute,
# and the rest at its end. --wait-for-go: read one line from stdin first and draw only if it says go (the
# report starts the interpreter, whose imports take a third of a second, before the inputs are written).
#
# Needs the standard library, numpy and matplotlib (Debian's /usr/bin/python3; Agg backend), and for the VTK
# files the vtk module (python3-vtk9, which libvtk9-dev installs). No randomness and no version string in the
# PNGs (savefig metadata Software=None): same inputs, same bytes.
#
# Inputs (under DIR; numbers in plain decimal or exponent notation, finite):
#   green/green.csv          sensor,component,offset_x_mm,offset_y_mm,g_point_per_mm2,g_disc_per_mm2
#                            [,g_exact_point_per_mm2,g_exact_disc_per_mm2]; component in zz, zx, xz, xx
#                            (force direction, then reading); offset = load position − sensor position;
#                            only the rows with offset_y_mm = 0 are drawn.
#   kfit/kfit.json           numbers "h_mm" (thickness above sensor #1), "k_lsq_line", "paper_k".
#   crosscheck/readings.csv  case,variant,sensor,x_mm,sigma_z_kPa,sigma_x_kPa; case in static, sliding.
#   crosscheck/defect.csv    case,variant,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa; case in static, sliding.
#   crosscheck/pressure.csv  x_mm,p_hertz_halfspace_kPa,p_layer_exact_kPa,p_fe_frictionless_kPa,
#                            p_fe_coupled_kPa,q_fe_coupled_kPa[,p_meridian_frictionless_kPa]; an empty cell
#                            (not x_mm) = no value there.
#   study/chain_study.csv    stage,level,dofs,seconds,error (error relative, > 0; seconds > 0). Optional.
#   perception/row.csv       u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa,superposed_z_kPa,superposed_x_kPa
#                            [,noisy_z_kPa,noisy_x_kPa]; perception/pairs.csv case,spacing_mm,rel_diff_z,
#                            rel_diff_x; perception/detection.csv case,diameter_mm,array_snr,best_sensor_snr;
#                            perception/detection_map.csv case,passages[,array_mm,best_sensor_mm] (empty:
#                            outside the ladder); perception/features.csv source,sensor,position_mm,diameter_mm
#                            (source truth, multi or naive); perception/summary.json (objects "row",
#                            "detection", "inversion"). Optional: the report's perception section.
#   crosscheck/hole_budget.csv  hypothesis,case,sensor,component,fe_peak_kPa,model_peak_kPa,ratio (component
#                            z or x; ratio = FE/model amplitude); crosscheck/hole_budget_facts.csv
#                            hypothesis,fact,met (F1-F5, met 0 or 1).
#   contact/sensors.csv      sensor,x_mm,y_mm (the sensors' centres on the base, z = 0).
#   contact/summary.json     "friction": the mode drawn (uncoupled and coupled slide).
#   mesh/mesh.vtu            VTK XML (read with Debian's python3-vtk9): the tetrahedra (10-node, VTK type 24, or
#                            4-node); mesh/boundary.vtu its boundary triangles (6- or 3-node), cell array
#                            boundary_marker (2: the top).
#   contact/pressure.vtp     VTK XML: the contact zone's triangles on the top, point arrays pressure_kPa,
#                            traction_kPa (3 components), in_contact (1 at the active nodes).
#   contact/fields.vtu       VTK XML: the tetrahedra with point array stress_MPa (9 components, row-major).
#   Without the vtk module the figures reading a VTK file are skipped, each with one line saying so.
#   Sensors are numbered 1, 2, ...; extra columns are ignored.
#
# Outputs (DIR/figures/, 120 dpi), each written only if all its inputs exist:
#   fig1_calibration.png     green.csv, kfit.json: g_disc vs offset for every sensor, 2×2 (zz, zx, xz, xx),
#                            with the half-space Green tensor at sensor #1's depth h rescaled as
#                            g_k(x) = c·k·g_half(√k·x) for k = paper_k (dashed) and the component's own
#                            fitted k (dotted), c the reading's gain (kfit.json "gains": a post's; else 1).
#   fig2_static_sliding.png  readings.csv: σ_z and σ_x vs sensor x, static and sliding, one line per variant.
#   fig3_varsigma_z.png      defect.csv, readings.csv (sensor x): ς_z vs hole position u per sensor, one row
#   fig4_varsigma_x.png      per case (sliding, then static): FE | paper_model | FE × s against the model for
#                            sensors #5, #7, s = max|model| / max|FE| over all sensors of that row.
#   pressure_profiles.png    pressure.csv: every column with a value vs x (q dotted).
#   green_vs_halfspace.png   green.csv, kfit.json: sensor #1 g_zz, g_xx (disc) against the rescaled
#                            half-space at the paper's k and at the component's own fitted k, times the
#                            reading's gain (and the exact layer if given), and (model − FE) / FE peak.
#   k_sweep.png              kfit/k_sweep.csv (parameter,value,k_central,k_lsq_line), kfit.json: the exact
#                            layer's k as one protocol reading changes at a time, against the paper's k ± 0.01,
#                            and the FE k per mesh scale (rows mesh_scale) when the report computed error bars.
#   budget_<hypothesis>.png  crosscheck/hole_budget_signals.csv (hypothesis,case,u_mm,sensor,varsigma_z_kPa,
#                            varsigma_x_kPa), crosscheck/defect.csv: per hypothesis of the hole-signal budget,
#                            sliding ς_z (top) and ς_x (bottom) against u, one panel per sensor, FE against the
#                            paper_model variant, titled with the amplitude ratio FE/model.
#   finite_path.png          contact/finite_path.csv (model,frame,ratio,tangential_force_N,indentation_um,
#                            front_edge_mm,back_edge_mm,force_centroid_x_mm,moment_radius_mm,
#                            moment_anisotropy, other columns ignored; model linear or finite, frame material
#                            or spatial), written for a neo-Hookean scene only (no file, no figure and no
#                            "skipped" line): the contact zone against the tangential load.
#   pareto.png               study/chain_study.csv (the report's error levels, or skinfem study --chain --out
#                            DIR/study): error vs seconds (log-log), one series per stage, labelled by DOFs.
#   perception_scan.png      row.csv: the row's ς_z (top) and ς_x (bottom) per sensor against u, the full
#                            contact (left) against the superposition (right), on shared y scales.
#   perception_superposition.png  pairs.csv: max |ς − Σ ς_k| / max |ς| against the spacing, per case and
#                            component, the row's at its period, the 5 % line.
#   perception_detection.png detection.csv, detection_map.csv: SNR against the diameter (log-log) with the
#                            required SNR, and the smallest hole detected against N.
#   perception_inversion.png row.csv, features.csv: the noisy ς_z inverted, then the features found by every
#                            sensor together and by each alone against the true holes (dotted).
#   skin_mesh.png            boundary.vtu, mesh.vtu, pressure.vtp, sensors.csv: the top's triangles from above
#                            with the contact zone (the level 1/2 of in_contact) and the sensors; the section
#                            y = 0 (faces lying in it, or the cut of the tetrahedra it crosses) over the sensors
#                            and the contact ± 1.5 mm, z stretched 2×.
#   contact_pressure_map.png pressure.vtp, summary.json: p from above around the contact zone, its outline, the
#                            sliding direction (the traction's resultant) when the mode slides; p at the nodes on
#                            y = 0 against x.
#   skin_stress.png          fields.vtu, pressure.vtp, sensors.csv, summary.json: σ_zz (kPa) on the section y = 0,
#                            as skin_mesh.png's, with the sensors and the contact on y = 0.
#   budget_summary.png       hole_budget.csv, hole_budget_facts.csv: the sliding FE/model ratio per sensor, ς_z
#                            and ς_x, one line per hypothesis labelled with the facts it meets, with the bands
#                            of the paper's facts F2 (0.5–2) and F3 (up to 4).
# Each PNG is written to a hidden temporary name in DIR/figures and renamed into place. A figure whose inputs
# are missing prints `figures: skipped <name>.png: missing <file>` (one needing vtk without it: `missing the
# vtk module …`). The PNGs this run selects (all, without --only or --except) are deleted first, so
# DIR/figures never keeps one from an earlier run that this run skipped or did not reach.
# Prints `figures: wrote figures/<name>.png` per figure and `figures: N written, M skipped`; exit 0.
# Malformed input (unreadable, empty, missing column or key, wrong field count, bad or non-finite value, a
# case/component outside the lists above): one line `figures: error: <file>: line N, column 'c': ...` on
# stderr and exit 2 at once; the figures drawn before it stay, that one and the later ones are not written.
# Colours: sensor #n is tab10 colour n (#1 blue ... #10 cyan) in every figure.
import csv
import json
import math
import multiprocessing
import os
import sys

import matplotlib

matplotlib.use("Agg")  # before pyplot: no display
import matplotlib.collections  # noqa: E402
import matplotlib.lines  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import matplotlib.transforms  # noqa: E402
import matplotlib.tri  # noqa: E402
import numpy as np  # noqa: E402

# Titles at the top of their axes: placed automatically, each one measures its axes' decorations at every
# draw, a tenth of the figures' time; fig. 2, whose top row has a second x axis above, keeps it.
plt.rcParams.update({"axes.grid": True, "grid.alpha": 0.3, "legend.fontsize": 9, "figure.dpi": 120,
                     "axes.titley": 1.0})
COMPONENTS = ("zz", "zx", "xz", "xx")
COMPONENT_TEXT = {"zz": "normal force → σ_z", "zx": "normal force → σ_x",
                  "xz": "tangential force (x) → σ_z", "xx": "tangential force (x) → σ_x"}
CASES = ("static", "sliding")
G_UNIT = "g (mm⁻² = MPa/N)"


class InputError(Exception):
    pass


# ---- input ----------------------------------------------------------------------------------------------
def number(s):
    try:
        v = float(s)
    except ValueError:
        raise ValueError(f"{s!r} is not a number") from None
    if not math.isfinite(v):
        raise ValueError(f"{s!r} is not a finite number")
    return v


def number_or_nan(s):
    return math.nan if s == "" else number(s)


def positive(s):
    v = number(s)
    if v <= 0:
        raise ValueError(f"{s!r} is not > 0")
    return v


def integer(s):
    v = number(s)
    if v != int(v):
        raise ValueError(f"{s!r} is not an integer")
    return int(v)


def sensor_number(s):
    v = integer(s)
    if v < 1:
        raise ValueError(f"{s!r} is not a sensor number (1, 2, ...)")
    return v


def text(s):
    if s == "":
        raise ValueError("empty")
    return s


def one_of(*choices):
    def parse(s):
        if s not in choices:
            raise ValueError(f"{s!r} is not one of {', '.join(choices)}")
        return s
    return parse


def read_csv(path, spec, optional=()):
    """Columns of `path` as numpy arrays: `spec` maps each required column to its parser; `optional` columns
    (numbers, empty = NaN) are returned when present. Raises InputError naming the file, line and column."""
    try:
        with open(path, newline="") as f:
            rows = csv.reader(f)
            header = [h.strip() for h in next(rows, [])]
            if not header:
                raise InputError(f"{path}: empty file (no header)")
            for c in spec:
                if c not in header:
                    raise InputError(f"{path}: missing column '{c}' (header: {','.join(header)})")
            parsers = dict(spec, **{c: number_or_nan for c in optional if c in header})
            index = {c: header.index(c) for c in parsers}
            data = {c: [] for c in parsers}
            for row in rows:
                if not row:
                    continue
                if len(row) != len(header):
                    raise InputError(f"{path}: line {rows.line_num}: {len(row)} fields, header has {len(header)}")
                for c, parse in parsers.items():
                    try:
                        data[c].append(parse(row[index[c]].strip()))
                    except ValueError as e:
                        raise InputError(f"{path}: line {rows.line_num}, column '{c}': {e}") from None
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise InputError(f"{path}: {e}") from None
    if not data[next(iter(spec))]:
        raise InputError(f"{path}: no data rows")
    return {c: np.array(v) for c, v in data.items()}


def read_json_numbers(path, keys):
    try:
        with open(path) as f:
            obj = json.load(f)
    except (OSError, UnicodeDecodeError, ValueError) as e:
        raise InputError(f"{path}: {e}") from None
    out = {}
    for k in keys:
        v = obj.get(k) if isinstance(obj, dict) else None
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
            raise InputError(f"{path}: key '{k}' is missing or not a finite number")
        out[k] = float(v)
    return out


def read_green(d):
    return read_csv(os.path.join(d, "green/green.csv"),
                    {"sensor": sensor_number, "component": one_of(*COMPONENTS), "offset_x_mm": number,
                     "offset_y_mm": number, "g_point_per_mm2": number, "g_disc_per_mm2": number},
                    optional=("g_exact_point_per_mm2", "g_exact_disc_per_mm2"))


def read_kfit(d):
    """kfit.json's numbers, with the model's gain per reading (gain_z, gain_x: a post's computed gains, else 1)
    and each component's own fitted k (k_zz, …; k_lsq_line where absent)."""
    path = os.path.join(d, "kfit/kfit.json")
    kf = read_json_numbers(path, ("h_mm", "k_lsq_line", "paper_k"))
    with open(path) as f:
        obj = json.load(f)
    finite = lambda v, default: float(v) if isinstance(v, (int, float)) and math.isfinite(v) else default
    gains = obj.get("gains", {}) if isinstance(obj.get("gains"), dict) else {}
    for reading in ("z", "x"):
        kf["gain_" + reading] = finite(gains.get("sigma_" + reading), 1.0)
    components = obj.get("components", {}) if isinstance(obj.get("components"), dict) else {}
    for c in COMPONENTS:
        own = components.get(c, {})
        kf["k_" + c] = finite(own.get("k") if isinstance(own, dict) else None, kf["k_lsq_line"])
    return kf


def gain_of(kf, c):
    """The model's gain for component c: its reading's (zz, xz read σ_z; zx, xx σ_x)."""
    return kf["gain_z" if c in ("zz", "xz") else "gain_x"]


def read_readings(d):
    return read_csv(os.path.join(d, "crosscheck/readings.csv"),
                    {"case": one_of(*CASES), "variant": text, "sensor": sensor_number, "x_mm": number,
                     "sigma_z_kPa": number, "sigma_x_kPa": number})


# ---- helpers --------------------------------------------------------------------------------------------
def inch_margins(fig, left, right, bottom, top, wspace, hspace):
    """Margins in inches, as tight_layout finds them on the default scene, with room to spare: tight_layout
    measures every tick label of every axes, a third of a many-panel figure's time (0.36 of 1.08 s for
    fig. 3), and the figures drawn after the report's last stage are what it waits for."""
    w, h = fig.get_size_inches()
    fig.subplots_adjust(left=left / w, right=1 - right / w, bottom=bottom / h, top=1 - top / h, wspace=wspace,
                        hspace=hspace)


def sensor_color(s):
    return plt.get_cmap("tab10")((s - 1) % 10)


def g_half(component, x, h, k=1.0):
    """Half-space Green tensor at depth h for a unit force at offset x (y = 0), rescaled: k·g_half(√k·x)."""
    x = np.sqrt(k) * np.asarray(x, dtype=float)
    rho5 = (x * x + h * h) ** 2.5
    num = {"zz": 3 * h**3, "zx": -3 * x * h * h, "xz": -3 * x * h * h, "xx": 3 * x * x * h}[component]
    return k * num / (2 * np.pi * rho5)


def scan(g, sensor, component, column):
    """(offset_x, values) of one sensor's calibration scan along y = 0, sorted by offset."""
    m = (g["sensor"] == sensor) & (g["component"] == component) & (np.abs(g["offset_y_mm"]) < 1e-9)
    o = np.argsort(g["offset_x_mm"][m], kind="stable")
    return g["offset_x_mm"][m][o], g[column][m][o]


def series(table, mask, xcol, ycol):
    o = np.argsort(table[xcol][mask], kind="stable")
    return table[xcol][mask][o], table[ycol][mask][o]


def in_order(values):
    """Distinct values in order of first appearance (deterministic legend order)."""
    return list(dict.fromkeys(values.tolist()))


def no_data(ax, message):
    ax.text(0.5, 0.5, message, transform=ax.transAxes, ha="center", va="center", color="0.4")


def paper_label(kf):
    return f"half-space, k = paper_k = {kf['paper_k']:.3g}"


# ---- figures --------------------------------------------------------------------------------------------
def fig1_calibration(d):
    g, kf = read_green(d), read_kfit(d)
    sensors = sorted(set(g["sensor"].tolist()))
    x = np.linspace(g["offset_x_mm"].min(), g["offset_x_mm"].max(), 801)
    lab_paper = paper_label(kf)
    fig, axes = plt.subplots(2, 2, figsize=(14, 9.5), sharex=True)
    for ax, c in zip(axes.flat, COMPONENTS):
        for s in sensors:
            ax.plot(*scan(g, s, c, "g_disc_per_mm2"), color=sensor_color(s), lw=1.3, label=f"FE sensor #{s}")
        gain, k = gain_of(kf, c), kf["k_" + c]
        ax.plot(x, gain * g_half(c, x, kf["h_mm"], kf["paper_k"]), "k--", lw=1.6, zorder=3, label=lab_paper)
        ax.plot(x, gain * g_half(c, x, kf["h_mm"], k), "k:", lw=1.8, zorder=3,
                label="half-space, k fitted to the component (in its title)")
        ax.set_title(f"g_{c}: {COMPONENT_TEXT[c]} (fitted k {k:.4g})")
        ax.set_ylabel(G_UNIT)
    for ax in axes[1]:
        ax.set_xlabel("offset x = load position − sensor position (mm)")
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="center right", title="FE: disc mean, solid")
    fig.suptitle("Calibration scans (paper fig. 1): FE Green tensor of every sensor along y = 0, against the\n"
                 f"rescaled half-space model at sensor #1's depth h = {kf['h_mm']:.3f} mm")
    inch_margins(fig, left=0.95, right=3.8, bottom=0.6, top=0.9, wspace=0.2, hspace=0.12)
    return fig


def variant_style(v, i):
    fixed = {"fe": dict(color="k", ls="-", marker="o"), "paper_model": dict(color="tab:red", ls="--", marker="s")}
    others = [("tab:blue", "-."), ("tab:green", ":"), ("tab:orange", "-."), ("tab:purple", ":"),
              ("tab:brown", "-."), ("tab:cyan", ":"), ("tab:olive", "-."), ("tab:pink", ":")]
    markers = "^vD<>PXh*"
    color, ls = others[i % len(others)]
    return fixed.get(v, dict(color=color, ls=ls, marker=markers[i % len(markers)]))


def fig2_static_sliding(d):
    with plt.rc_context({"axes.titley": None}):  # titles above the secondary x axes
        return _fig2_static_sliding(d)


def _fig2_static_sliding(d):
    r = read_readings(d)
    variants = in_order(r["variant"])
    others = [v for v in variants if v not in ("fe", "paper_model")]
    fig, axes = plt.subplots(2, 2, figsize=(13, 9), sharex=True)
    for row, (comp, col) in enumerate((("σ_z", "sigma_z_kPa"), ("σ_x", "sigma_x_kPa"))):
        for j, case in enumerate(CASES):
            ax = axes[row, j]
            for v in variants:
                m = (r["case"] == case) & (r["variant"] == v)
                if m.any():
                    style = variant_style(v, others.index(v) if v in others else 0)
                    ax.plot(*series(r, m, "x_mm", col), lw=2 if v == "fe" else 1.3, ms=5, label=v,
                            zorder=3 if v == "fe" else 2, **style)
            if not (r["case"] == case).any():
                no_data(ax, f"no {case} rows")
            ax.set_title(f"{comp}, {case}")
            ax.set_ylabel(f"mean sensor {comp} (kPa)")
            if row == 1:
                ax.set_xlabel("sensor position x (mm)")
            if row == 0:
                first = {}
                for s, xs in zip(r["sensor"].tolist(), r["x_mm"].tolist()):
                    first.setdefault(s, xs)
                top = ax.secondary_xaxis("top")
                top.set_xticks(list(first.values()), [f"#{s}" for s in first])
    handles = {}
    for ax in axes.flat:
        for h, lab in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(lab, h)
    fig.legend(list(handles.values()), list(handles), loc="lower center", ncol=min(len(handles), 7),
               title="variant (fe: full FE; paper_model: the paper's convolution model)")
    fig.suptitle("Mean sensor stresses under the plate, static and sliding (paper fig. 2): FE and model variants")
    inch_margins(fig, left=0.85, right=0.2, bottom=1.3, top=0.95, wspace=0.13, hspace=0.13)
    return fig


def fig_varsigma(d, comp):
    col = f"varsigma_{comp}_kPa"
    t = defect_table(d)
    r = read_readings(d)
    xpos = {}
    for s, xs in zip(r["sensor"].tolist(), r["x_mm"].tolist()):
        xpos.setdefault(s, xs)
    sensors = sorted(set(t["sensor"].tolist()))
    cases = [c for c in ("sliding", "static") if (t["case"] == c).any()]
    sym = f"ς_{comp}"
    fig, axes = plt.subplots(len(cases), 3, figsize=(18, 5.2 * len(cases) + 1.2), squeeze=False)
    for row, case in enumerate(cases):
        ax_fe, ax_model, ax_both = axes[row]
        peak = {}
        for ax, variant, what in ((ax_fe, "fe", "FE"), (ax_model, "paper_model", "paper's model")):
            m = (t["case"] == case) & (t["variant"] == variant)
            peak[variant] = np.abs(t[col][m]).max() if m.any() else 0.0
            for s in sensors:
                ms = m & (t["sensor"] == s)
                if ms.any():
                    ax.plot(*series(t, ms, "u_mm", col), color=sensor_color(s), lw=1.4,
                            label=f"#{s}" + (f" (x = {xpos[s]:.2g} mm)" if s in xpos else ""))
                if s in xpos:
                    ax.plot([xpos[s]], [0.03], "o", ms=8, color=sensor_color(s), mec="k", mew=0.5,
                            transform=ax.get_xaxis_transform(), clip_on=False)
            if not m.any():
                no_data(ax, f"no {case} rows of variant {variant}")
            ax.set_title(f"{sym}, {case}: {what} (variant {variant})")
        scale = peak["paper_model"] / peak["fe"] if peak["fe"] > 0 and peak["paper_model"] > 0 else None
        for s in (5, 7):
            for variant, ls, f, lab in (("fe", "-", scale, f"#{s} FE × {scale:.3g}" if scale else ""),
                                        ("paper_model", "--", 1.0, f"#{s} paper's model")):
                ms = (t["case"] == case) & (t["variant"] == variant) & (t["sensor"] == s)
                if ms.any() and f:
                    u, v = series(t, ms, "u_mm", col)
                    ax_both.plot(u, f * v, ls=ls, color=sensor_color(s), lw=1.6, label=lab)
            if s in xpos:
                ax_both.plot([xpos[s]], [0.03], "o", ms=8, color=sensor_color(s), mec="k", mew=0.5,
                             transform=ax_both.get_xaxis_transform(), clip_on=False)
        if ax_both.lines and scale:
            ax_both.legend(loc="best")
            ax_both.set_title(f"{sym}, {case}: #5, #7, FE × (max|model| / max|FE|)")
        else:
            no_data(ax_both, "needs non-zero fe and paper_model signals")
            ax_both.set_title(f"{sym}, {case}: #5, #7, FE × (max|model| / max|FE|)")
        for ax in axes[row]:
            ax.margins(y=0.1)
            ax.set_xlabel("hole position u (mm)")
            ax.set_ylabel(f"{sym} (kPa)")
    handles, labels = axes[0, 0].get_legend_handles_labels()
    if not handles:
        handles, labels = axes[0, 1].get_legend_handles_labels()
    fig.legend(handles, labels, loc="center right", title="sensor (dot: its x)")
    fig.suptitle(f"Hole signals {sym}(u) as the hole in the plate crosses the contact (paper fig. "
                 f"{3 if comp == 'z' else 4}); FE and model panels have their own y scales")
    inch_margins(fig, left=0.95, right=2.15, bottom=0.6, top=0.75, wspace=0.2, hspace=0.16)
    return fig


def pressure_profiles(d):
    cols = {"p_hertz_halfspace_kPa": ("p, Hertz on a half-space", "tab:gray", "--"),
            "p_layer_exact_kPa": ("p, Hertz on the bonded layer (exact)", "tab:red", "-."),
            "p_meridian_frictionless_kPa": ("p, FE frictionless on the meridian (2D, cells graded to the edge)",
                                            "tab:blue", "-"),
            "p_fe_frictionless_kPa": ("p, FE frictionless in 3D (the hole sweep's mesh)",
                                      "tab:cyan", "-"),
            "p_fe_coupled_kPa": ("p, FE with coupled friction", "k", "-"),
            "q_fe_coupled_kPa": ("q (tangential), FE with coupled friction", "k", ":")}
    optional = ("p_meridian_frictionless_kPa",)
    t = read_csv(os.path.join(d, "crosscheck/pressure.csv"),
                 dict({"x_mm": number}, **{c: number_or_nan for c in cols if c not in optional}), optional)
    fig, ax = plt.subplots(figsize=(10, 6))
    o = np.argsort(t["x_mm"], kind="stable")
    for c, (label, color, ls) in cols.items():
        if c not in t:
            continue
        v = t[c][o]
        if np.isfinite(v).any():
            ax.plot(t["x_mm"][o], v, ls=ls, color=color, lw=1.0 if c == "p_fe_frictionless_kPa" else 1.8,
                    label=label)
    if not ax.lines:
        no_data(ax, "no values")
    else:
        # Headroom above the curves for the legend.
        ax.set_ylim(top=1.5 * max(np.nanmax(line.get_ydata()) for line in ax.lines))
        ax.legend(loc="upper left")
    ax.axhline(0, color="0.5", lw=0.8)
    ax.set_xlabel("x (mm), along y = 0")
    ax.set_ylabel("contact traction (kPa)")
    ax.set_title("Contact pressure p (and tangential traction q) along the line y = 0 through the contact")
    inch_margins(fig, left=0.8, right=0.2, bottom=0.6, top=0.45, wspace=0.2, hspace=0.2)
    return fig


def green_vs_halfspace(d):
    g, kf = read_green(d), read_kfit(d)
    lab_paper = paper_label(kf)
    fig, axes = plt.subplots(2, 2, figsize=(13, 8.5), sharex="col", gridspec_kw={"height_ratios": (2.2, 1)})
    for j, c in enumerate(("zz", "xx")):
        x, fe = scan(g, 1, c, "g_disc_per_mm2")
        top, bottom = axes[0, j], axes[1, j]
        if not len(x):
            no_data(top, f"no sensor #1 {c} rows")
            continue
        gain, k = gain_of(kf, c), kf["k_" + c]  # the gain: the model's integral, the reading of a uniform load
        models = [(lab_paper, gain * g_half(c, x, kf["h_mm"], kf["paper_k"]), "--", "tab:red"),
                  (f"half-space, k fitted to g_{c} = {k:.4g}", gain * g_half(c, x, kf["h_mm"], k), ":",
                   "tab:blue")]
        if "g_exact_disc_per_mm2" in g:
            exact = scan(g, 1, c, "g_exact_disc_per_mm2")[1]
            if np.isfinite(exact).any():
                models.append(("exact bonded layer (disc mean)", exact, "-.", "tab:green"))
        top.plot(x, fe, "k-", lw=2, label="FE sensor #1 (disc mean)")
        peak = np.abs(fe).max()
        for label, v, ls, color in models:
            top.plot(x, v, ls=ls, color=color, lw=1.8, label=label)
            bottom.plot(x, 100 * (v - fe) / peak if peak > 0 else v * np.nan, ls=ls, color=color, lw=1.6,
                        label=label)
        top.set_title(f"sensor #1, g_{c}: {COMPONENT_TEXT[c]}")
        top.set_ylabel(G_UNIT)
        top.legend()
        bottom.axhline(0, color="0.5", lw=0.8)
        bottom.set_ylabel("(model − FE) / FE peak (%)")
        bottom.set_xlabel("offset x = load position − sensor position (mm)")
    fig.suptitle(f"FE Green tensor of sensor #1 against the rescaled half-space c·k·g_half(√k·x) at h = "
                 f"{kf['h_mm']:.3f} mm")
    inch_margins(fig, left=0.85, right=0.2, bottom=0.6, top=0.75, wspace=0.15, hspace=0.06)
    return fig


def k_sweep(d):
    t = read_csv(os.path.join(d, "kfit/k_sweep.csv"),
                 {"parameter": text, "value": number, "k_central": number, "k_lsq_line": number})
    paper = read_json_numbers(os.path.join(d, "kfit/kfit.json"), ("paper_k",))["paper_k"]
    groups = [("nu", "Poisson's ratio ν"), ("punch_diameter_mm", "punch diameter (mm)"),
              ("disc_diameter_mm", "sensor averaging disc (mm)"), ("h_mm", "layer thickness h (mm)"),
              ("load", "load model (0 point, 1 uniform disc, 2 punch)")]
    if np.any(t["parameter"] == "mesh_scale"):
        groups.append(("mesh_scale", "FE mesh scale (sensor #1 of the scene)"))
    fig, axes = plt.subplots(1, len(groups), figsize=(3.6 * len(groups), 4.5), sharey=True)
    for ax, (name, label) in zip(axes, groups):
        m = t["parameter"] == name
        o = np.argsort(t["value"][m], kind="stable")
        for crit, style in (("k_central", "o-"), ("k_lsq_line", "s--")):
            ax.plot(t["value"][m][o], t[crit][m][o], style, label=crit)
        ax.axhspan(paper - 0.01, paper + 0.01, color="tab:red", alpha=0.15)
        ax.axhline(paper, color="tab:red", lw=1, label=f"paper k = {paper:g} ± 0.01")
        ax.set_xlabel(label)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("k (exact bonded layer; mesh-scale panel: FE)")
    axes[0].legend(fontsize=8)
    fig.suptitle("Which reading of the calibration protocol gives the paper's k: one parameter at a time")
    inch_margins(fig, left=0.85, right=0.2, bottom=0.6, top=0.55, wspace=0.08, hspace=0.2)
    return fig


def pareto(d):
    t = read_csv(os.path.join(d, "study/chain_study.csv"),
                 {"stage": text, "level": number, "dofs": integer, "seconds": positive, "error": positive})
    fig, ax = plt.subplots(figsize=(10, 7))
    markers = "osD^vPX*h"
    labelled = []  # (log10 s, log10 e, DOFs) of the labels placed so far
    for i, stage in enumerate(in_order(t["stage"])):
        m = t["stage"] == stage
        o = np.argsort(t["level"][m], kind="stable")
        sec, err, dofs = t["seconds"][m][o], t["error"][m][o], t["dofs"][m][o]
        ax.plot(sec, err, marker=markers[i % len(markers)], ms=8, lw=1, color=plt.get_cmap("Dark2")(i % 8),
                label=stage)
        for s, e, n in zip(sec, err, dofs):
            # Stages of one level share its solve, so their points can coincide: one label for the same DOFs
            # at the same place, and labels of others near it stacked below instead of on top.
            x, y = np.log10(s), np.log10(e)
            near = [(a, b, k) for a, b, k in labelled if abs(a - x) < 0.06 and abs(b - y) < 0.06]
            if any(k == n for _, _, k in near):
                continue
            ax.annotate(f"{n:,}", (s, e), textcoords="offset points", xytext=(6, 5 - 11 * len(near)), fontsize=8)
            labelled.append((x, y, n))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.margins(0.1)
    plain = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
    for axis in (ax.xaxis, ax.yaxis):  # ticks at 1, 2, 5 × 10^n in plain numbers: a study spans few decades
        axis.set_minor_locator(matplotlib.ticker.LogLocator(subs=(2, 5)))
        axis.set_major_formatter(plain)
        axis.set_minor_formatter(plain)
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel("relative error (–)")
    ax.legend(title="stage (labels: DOFs)")
    ax.set_title("Cost against accuracy of each stage over the refinement levels")
    fig.tight_layout()
    return fig


_BUDGET_TABLES = {}
_DEFECT_TABLES = {}
_BUDGET_AXES = {}  # per process: budget_axes's figures, by number of sensors


def defect_table(d):
    """crosscheck/defect.csv, read once for figs. 3 and 4 and the budget figures (main() reads it before the
    workers fork, which then share it)."""
    if d not in _DEFECT_TABLES:
        _DEFECT_TABLES[d] = read_csv(os.path.join(d, "crosscheck/defect.csv"),
                                     {"case": one_of(*CASES), "variant": text, "u_mm": number,
                                      "sensor": sensor_number, "varsigma_z_kPa": number, "varsigma_x_kPa": number})
    return _DEFECT_TABLES[d]


def budget_tables(d):
    """The hypotheses' signals and the paper's model, read once for every budget figure (3.6 MB of CSV on the
    default scene; main() reads them before the workers fork, which then share them)."""
    if d not in _BUDGET_TABLES:
        _BUDGET_TABLES[d] = (
            read_csv(os.path.join(d, "crosscheck/hole_budget_signals.csv"),
                     {"hypothesis": text, "case": one_of(*CASES), "u_mm": number, "sensor": sensor_number,
                      "varsigma_z_kPa": number, "varsigma_x_kPa": number}),
            defect_table(d))
    return _BUDGET_TABLES[d]


def budget_axes(n):
    """A figure of 2 × n axes for the budget figures, emptied: one per worker process, drawn over again for
    each hypothesis (creating the twenty axes and their ticks was half of each figure's time)."""
    if n not in _BUDGET_AXES:
        fig, axes = plt.subplots(2, n, figsize=(2.3 * n + 1, 5.4), squeeze=False, sharex=True)
        _BUDGET_AXES[n] = fig, axes
    fig, axes = _BUDGET_AXES[n]
    for ax in axes.flat:
        for artist in ax.lines[:] + ax.texts[:]:
            artist.remove()
        if ax.get_legend():
            ax.get_legend().remove()
        ax.set_title("")
        # Limits as a new axes has them: (0, 1) until a line comes, then the data's.
        ax.dataLim.set(matplotlib.transforms.Bbox.null())
        ax.ignore_existing_data_limits = True
        ax.set_xlim(0, 1, auto=True)
        ax.set_ylim(0, 1, auto=True)
    return fig, axes


def fig_budget(d, hypothesis):
    t, m = budget_tables(d)
    sensors = sorted(set(t["sensor"].tolist()))
    fig, axes = budget_axes(len(sensors))
    for row, comp in enumerate(("z", "x")):
        col = f"varsigma_{comp}_kPa"
        for i, s in enumerate(sensors):
            ax = axes[row, i]
            fe = (t["hypothesis"] == hypothesis) & (t["case"] == "sliding") & (t["sensor"] == s)
            model = (m["case"] == "sliding") & (m["variant"] == "paper_model") & (m["sensor"] == s)
            if fe.any():
                ax.plot(*series(t, fe, "u_mm", col), color=sensor_color(s), lw=1.4, label="FE")
            if model.any():
                ax.plot(*series(m, model, "u_mm", col), color="k", ls="--", lw=1.0, label="paper's model")
            if fe.any() and model.any():
                ratio = np.abs(t[col][fe]).max() / max(np.abs(m[col][model]).max(), 1e-300)
                ax.set_title(f"#{s} ς_{comp}: FE/model {ratio:.2f}", fontsize=9)
            else:
                no_data(ax, "no rows")
            ax.tick_params(labelsize=7)
            if row == 1:
                ax.set_xlabel("u (mm)", fontsize=8)
        axes[row, 0].set_ylabel(f"ς_{comp} sliding (kPa)")
    axes[0, 0].legend(fontsize=7, loc="best")
    fig.suptitle(f"Hole signals under hypothesis '{hypothesis}' (sliding, coupled) against the paper's model, "
                 "laid out like the paper's fig. 3")
    inch_margins(fig, left=0.8, right=0.15, bottom=0.55, top=0.95, wspace=0.35, hspace=0.25)
    return fig


def budget_figures(d):
    """(name, inputs, draw) per hypothesis of crosscheck/hole_budget_signals.csv, in file order."""
    path = os.path.join(d, "crosscheck/hole_budget_signals.csv")
    if not os.path.isfile(path):
        return []
    names = []
    with open(path, newline="") as f:
        rows = csv.DictReader(f)
        for row in rows:
            h = row.get("hypothesis") or ""
            # The name becomes part of a file name: letters, digits and underscores only.
            if not h or not all(c.isascii() and (c.isalnum() or c == "_") for c in h):
                raise InputError(f"{path}: line {rows.line_num}: hypothesis {h!r}: must be letters, digits, _")
            if f"budget_{h}.png" in {f[0] for f in FIGURES}:
                raise InputError(f"{path}: line {rows.line_num}: hypothesis {h!r}: its figure's name is taken")
            if h not in names:
                names.append(h)
    inputs = ("crosscheck/hole_budget_signals.csv", "crosscheck/defect.csv")
    return [(f"budget_{h}.png", inputs, lambda d, h=h: fig_budget(d, h)) for h in names]


def finite_path(d):
    t = read_csv(os.path.join(d, "contact/finite_path.csv"),
                 {"model": one_of("linear", "finite"), "frame": one_of("material", "spatial"), "ratio": number,
                  "tangential_force_N": number, "indentation_um": number, "front_edge_mm": number,
                  "back_edge_mm": number, "force_centroid_x_mm": number, "moment_radius_mm": number,
                  "moment_anisotropy": number})
    # Colour: the quantity; line and marker: the skin and frame. The edges are the outermost touching
    # vertices: they step by the mesh's size as one enters or leaves (drawn as steps); the force centroid and
    # the pressure's moments are smooth.
    series = [("linear", "material", "-", "", "linear skin (material frame)"),
              ("finite", "material", "-", "o", "neo-Hookean, material frame"),
              ("finite", "spatial", "--", "s", "neo-Hookean, spatial frame")]
    edges = [("front_edge_mm", "front edge (outermost touching vertex)", "steps-post"),
             ("back_edge_mm", "back edge (outermost touching vertex)", "steps-post"),
             ("force_centroid_x_mm", "force centroid", "default")]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.8))
    for model, frame, style, marker, _ in series:
        m = (t["model"] == model) & (t["frame"] == frame)
        o = np.argsort(t["tangential_force_N"][m], kind="stable")
        T = t["tangential_force_N"][m][o]
        for i, (column, _, steps) in enumerate(edges):
            axes[0].plot(T, t[column][m][o], style, marker=marker, color=f"C{i}", ms=5,
                         drawstyle=steps if model == "linear" else "default")
        axes[1].plot(T, t["moment_radius_mm"][m][o], style, marker=marker, color="C0", ms=5)
        axes[2].plot(T, t["moment_anisotropy"][m][o], style, marker=marker, color="C0", ms=5)
    quantity = [matplotlib.lines.Line2D([], [], color=f"C{i}", label=label) for i, (_, label, _) in enumerate(edges)]
    kind = [matplotlib.lines.Line2D([], [], color="0.3", ls=style, marker=marker, label=label)
            for _, _, style, marker, label in series]
    axes[0].legend(handles=quantity + kind, fontsize=7, loc="center right", bbox_to_anchor=(1, 0.36))
    axes[0].set_ylabel("along the sliding direction from first touch (mm)")
    axes[1].set_ylabel("radius √(5/2 ⟨r²⟩_p) (mm)")
    axes[2].set_ylabel("anisotropy √(⟨x_t²⟩_p / ⟨x_n²⟩_p)")
    for ax in axes:
        ax.set_xlabel("tangential load (N)")
        ax.grid(alpha=0.3)
    fig.suptitle("The contact zone against the tangential load at the full normal force: linear skin against "
                 "neo-Hookean")
    fig.tight_layout()
    return fig


def finite_figures(d):
    """finite_path.png when the report solved a neo-Hookean scene's finite deformation."""
    inputs = ("contact/finite_path.csv",)
    return [("finite_path.png", inputs, finite_path)] if os.path.isfile(os.path.join(d, inputs[0])) else []


def post_design(d):
    t = read_csv(os.path.join(d, "green/post_design.csv"),
                 {"row": one_of("post", "disc", "sweep"), "diameter_mm": positive, "height_mm": number,
                  "g_zz_half_width_mm": number, "g_zz_integral": number, "g_xx_half_width_mm": number,
                  "g_xx_integral": number})
    s = t["row"] == "sweep"
    panels = [("g_zz_integral", "∫ g_zz dA (uniform vertical load per base area)"),
              ("g_zz_half_width_mm", "half width of g_zz (mm)"),
              ("g_xx_integral", "∫ g_xx dA (uniform shear per base area)"),
              ("g_xx_half_width_mm", "half width of g_xx (mm)")]
    fig, axes = plt.subplots(2, 2, figsize=(11, 8), sharex=True)
    for ax, (column, label) in zip(axes.flat, panels):
        for i, dia in enumerate(in_order(t["diameter_mm"][s])):
            m = s & (t["diameter_mm"] == dia)
            o = np.argsort(t["height_mm"][m], kind="stable")
            ax.plot(t["height_mm"][m][o], t[column][m][o], "o-", color=plt.get_cmap("viridis")(i / 4),
                    label=f"diameter {dia:g} mm")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("post height (mm; 0: the disc of that diameter)")
    axes[0][0].legend(fontsize=8)
    fig.suptitle("Post sensor design at the skin's axis (meridian solves): integral and spatial resolution")
    fig.tight_layout()
    return fig


def read_perception_summary(d):
    path = os.path.join(d, "perception/summary.json")
    try:
        with open(path) as f:
            obj = json.load(f)
    except (OSError, UnicodeDecodeError, ValueError) as e:
        raise InputError(f"{path}: {e}") from None
    if not isinstance(obj, dict) or not isinstance(obj.get("row"), dict):
        raise InputError(f"{path}: key 'row' is missing or not an object")
    return obj


def read_row(d):
    return read_csv(os.path.join(d, "perception/row.csv"),
                    {"u_mm": number, "sensor": sensor_number, "varsigma_z_kPa": number, "varsigma_x_kPa": number,
                     "superposed_z_kPa": number, "superposed_x_kPa": number},
                    optional=("noisy_z_kPa", "noisy_x_kPa"))


def plain_log_ticks(axis):
    """Ticks of a log axis written as plain numbers (0.1, 0.2, 0.5, 1, 2, 5, ...)."""
    axis.set_major_locator(matplotlib.ticker.LogLocator(base=10, subs=(1, 2, 5)))
    axis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
    axis.set_minor_formatter(matplotlib.ticker.NullFormatter())


def perception_scan(d):
    t = read_row(d)
    row = read_perception_summary(d)["row"]
    sensors = sorted(set(t["sensor"].tolist()))
    fig, axes = plt.subplots(2, 2, figsize=(15, 9), sharex=True, squeeze=False)
    for r, comp in enumerate(("z", "x")):
        for c, (col, what) in enumerate(((f"varsigma_{comp}_kPa", "full contact, every hole in the zone"),
                                         (f"superposed_{comp}_kPa", "superposition Σ_k ς_k of single holes"))):
            ax = axes[r, c]
            for s in sensors:
                ax.plot(*series(t, t["sensor"] == s, "u_mm", col), color=sensor_color(s), lw=1.2, label=f"#{s}")
            ax.set_title(f"ς_{comp}: {what}")
            ax.set_ylabel(f"ς_{comp} (kPa)")
            ax.margins(y=0.08)
        low = min(axes[r, 0].get_ylim()[0], axes[r, 1].get_ylim()[0])
        high = max(axes[r, 0].get_ylim()[1], axes[r, 1].get_ylim()[1])
        for ax in axes[r]:
            ax.set_ylim(low, high)
    for ax in axes[1]:
        ax.set_xlabel("plate displacement u (mm)")
    holes = row.get("holes_mm", [])
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="center right", title="sensor")
    fig.suptitle(f"A row of {len(holes)} holes at a {row.get('period_mm', 0):.3g} mm period scanned across the "
                 f"contact, sliding: FE (left) against the paper's linear prediction (right)\nlargest "
                 f"difference {100 * row.get('superposition_rel_diff_z', 0):.2g} % (ς_z) and "
                 f"{100 * row.get('superposition_rel_diff_x', 0):.2g} % (ς_x) of the largest signal")
    inch_margins(fig, left=0.9, right=1.3, bottom=0.6, top=0.9, wspace=0.25, hspace=0.3)
    return fig


def perception_superposition(d):
    t = read_csv(os.path.join(d, "perception/pairs.csv"),
                 {"case": one_of(*CASES), "spacing_mm": positive, "rel_diff_z": number, "rel_diff_x": number})
    summary = read_perception_summary(d)
    diameter = summary.get("hole_diameter_mm", 0)
    fig, ax = plt.subplots(figsize=(9, 5.5))
    for case, color in (("static", "tab:blue"), ("sliding", "tab:red")):
        m = t["case"] == case
        for comp, ls, mk in (("z", "-", "o"), ("x", "--", "s")):
            if m.any():
                x, y = series(t, m, "spacing_mm", f"rel_diff_{comp}")
                ax.plot(x, 100 * y, ls=ls, marker=mk, color=color, label=f"two holes, {case}, ς_{comp}")
    row = summary["row"]
    for comp, mk in (("z", "*"), ("x", "P")):
        v = row.get(f"superposition_rel_diff_{comp}")
        if isinstance(v, (int, float)):
            ax.plot([row.get("period_mm", 0)], [100 * v], mk, ms=13, color="k",
                    label=f"the row at its period, sliding, ς_{comp}")
    ax.axhline(5, color="0.3", ls=":", lw=1.5, label="5 % of the largest signal")
    ax.set_yscale("log")
    plain_log_ticks(ax.yaxis)
    ax.set_xlabel(f"spacing of the holes' centres (mm); hole diameter {diameter:.3g} mm")
    ax.set_ylabel("max |ς − Σ_k ς_k| / max |ς|  (%)")
    ax.set_title("Where superposition holds: two holes against their spacing")
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    return fig


def perception_detection(d):
    t = read_csv(os.path.join(d, "perception/detection.csv"),
                 {"case": one_of(*CASES), "diameter_mm": positive, "array_snr": number, "best_sensor_snr": number})
    mp = read_csv(os.path.join(d, "perception/detection_map.csv"), {"case": one_of(*CASES), "passages": integer},
                  optional=("array_mm", "best_sensor_mm"))
    det = read_perception_summary(d).get("detection", {})
    need = det.get("required_snr", 0)
    noise = det.get("noise", {})
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(14, 5.5))
    colors = {"static": "tab:blue", "sliding": "tab:red"}
    for case in CASES:
        m = t["case"] == case
        if not m.any():
            continue
        ax.loglog(*series(t, m, "diameter_mm", "array_snr"), "-o", ms=4, color=colors[case],
                  label=f"{case}, the array")
        ax.loglog(*series(t, m, "diameter_mm", "best_sensor_snr"), "--s", ms=4, color=colors[case],
                  label=f"{case}, the best sensor")
        n = mp["case"] == case
        for col, ls, what in (("array_mm", "-o", "the array"), ("best_sensor_mm", "--s", "the best sensor")):
            x, y = series(mp, n, "passages", col)
            ok = np.isfinite(y)
            if ok.any():
                bx.semilogx(x[ok], y[ok], ls, color=colors[case], label=f"{case}, {what}")
    if need:
        ax.axhline(need, color="0.3", ls=":",
                   label=f"required SNR {need:.3g} (p_fa {det.get('p_fa')}, p_d {det.get('p_d')})")
    plain_log_ticks(ax.xaxis)
    plain_log_ticks(ax.yaxis)
    ax.set_xlabel("hole diameter (mm)")
    ax.set_ylabel("matched-filter SNR")
    ax.set_title(f"SNR against the hole's diameter; noise {noise.get('sigma_z_kPa')} / "
                 f"{noise.get('sigma_x_kPa')} kPa, N = {noise.get('passages')}")
    ax.legend(fontsize=8)
    plain_log_ticks(bx.xaxis)
    bx.set_xlabel("passages N")
    bx.set_ylabel("smallest hole detected (mm)")
    bx.set_title("Smallest hole detected against N (outside the ladder: no point)")
    if bx.lines:
        bx.legend(fontsize=8)
    else:
        no_data(bx, "every N falls outside the ladder")
    fig.tight_layout()
    return fig


def perception_inversion(d):
    t = read_row(d)
    f = read_csv(os.path.join(d, "perception/features.csv"),
                 {"source": one_of("truth", "multi", "naive"), "sensor": integer, "position_mm": number,
                  "diameter_mm": number}, optional=("snr",))
    inv = read_perception_summary(d).get("inversion", {})
    sensors = sorted(set(t["sensor"].tolist()))
    # The three sensors with the largest ς_z: ten noisy curves hide one another.
    loudest = sorted(sorted(sensors, key=lambda s: -np.abs(t["varsigma_z_kPa"][t["sensor"] == s]).max())[:3])
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(13, 9.5), gridspec_kw={"height_ratios": [3, 2]})
    if "noisy_z_kPa" in t and np.isfinite(t["noisy_z_kPa"]).any():
        for s in loudest:
            m = t["sensor"] == s
            ax.plot(*series(t, m, "u_mm", "noisy_z_kPa"), color=sensor_color(s), lw=0.6, alpha=0.6)
            ax.plot(*series(t, m, "u_mm", "varsigma_z_kPa"), color=sensor_color(s), lw=1.6, label=f"#{s}")
        ax.legend(loc="center left", bbox_to_anchor=(1.0, 0.5), title="sensor")
    else:
        no_data(ax, "no noisy signals")
    ax.set_xlabel("plate displacement u (mm)")
    ax.set_ylabel("ς_z (kPa)")
    ax.set_title(f"The signals inverted (the {len(loudest)} loudest of {len(sensors)} sensors shown): the row's FE "
                 f"scan (thick) with the paper's noise (thin)")
    for x in f["position_mm"][f["source"] == "truth"]:
        bx.axvline(x, color="0.5", ls=":", lw=1.2)
    m = f["source"] == "multi"
    bx.plot(f["position_mm"][m], np.zeros(m.sum()), "kD", ms=9, label="every sensor, the offset fitted")
    for s in sensors:
        m = (f["source"] == "naive") & (f["sensor"] == s)
        bx.plot(f["position_mm"][m], np.full(m.sum(), s), "o", color=sensor_color(s), ms=6)
    bx.set_yticks([0] + sensors)
    bx.set_yticklabels(["all"] + [f"#{s} alone" for s in sensors])
    bx.set_ylim(len(sensors) + 0.7, -0.7)
    bx.set_xlabel("feature position on the plate at u = 0 (mm); dotted: the true holes")
    ms = inv.get("multi_sensor", {})
    bx.set_title(f"Features found: every sensor together, rms error {ms.get('rms_error_mm', float('nan')):.2g} mm, "
                 f"{ms.get('missed', '?')} missed, {ms.get('false_features', '?')} false; below, the paper's "
                 f"naive inversion, one sensor at a time")
    bx.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    return fig


# ---- the mesh and the contact's fields (VTK XML files, read with Debian's python3-vtk9) --------------------
class MissingModule(Exception):
    """A module a figure needs is not installed: the figure is skipped with the reason, the others drawn."""


VTK_TETRA, VTK_QUADRATIC_TETRA = 10, 24
VTK_TRIANGLE, VTK_QUADRATIC_TRIANGLE = 5, 22
TET_EDGES = ((0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3))  # a quadratic tetra's mid-edge nodes 4..9
TET_MID = np.full((4, 4), -1)
for _e, (_i, _j) in enumerate(TET_EDGES):
    TET_MID[_i, _j] = TET_MID[_j, _i] = 4 + _e
BOUNDARY_TOP = 2  # mesh.vtu / boundary.vtu boundary_marker: 1 base, 2 top, 4 side


def read_vtk(path, point_arrays=(), cell_arrays=()):
    """Points (n × 3), cells (connectivity, offsets, types; a .vtp's polygons) and the named point and cell
    arrays of a VTK XML file. Raises MissingModule without vtk, InputError for an unreadable file or a missing
    or non-finite array."""
    try:
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkCommonCore import vtkObject
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader
    except ImportError as e:
        raise MissingModule(f"the vtk module (Debian's python3-vtk9): {e}") from None
    vtkObject.GlobalWarningDisplayOff()  # a bad file is reported below in one line, not by VTK's window
    poly = path.endswith(".vtp")
    reader = vtkXMLPolyDataReader() if poly else vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if reader.GetErrorCode() or data is None or data.GetPoints() is None or data.GetNumberOfPoints() == 0:
        raise InputError(f"{path}: not a readable VTK XML {'poly data' if poly else 'unstructured grid'} file "
                         "with points")
    cells = data.GetPolys() if poly else data.GetCells()
    out = {"points": vtk_to_numpy(data.GetPoints().GetData()).astype(float),
           "connectivity": vtk_to_numpy(cells.GetConnectivityArray()).astype(np.int64),
           "offsets": vtk_to_numpy(cells.GetOffsetsArray()).astype(np.int64),
           "types": None if poly else vtk_to_numpy(data.GetCellTypesArray()).astype(int)}
    for where, names in ((data.GetPointData(), point_arrays), (data.GetCellData(), cell_arrays)):
        for name in names:
            a = where.GetArray(name)
            if a is None:
                raise InputError(f"{path}: missing array '{name}'")
            v = vtk_to_numpy(a).astype(float)
            if not np.isfinite(v).all():
                raise InputError(f"{path}: array '{name}': a non-finite value")
            out[name] = v
    return out


def cells_of(mesh, path, kinds):
    """The cells as an array (cells × nodes), all of one of `kinds` ((VTK type, nodes) pairs, or nodes per
    polygon for a .vtp)."""
    sizes = np.diff(mesh["offsets"])
    for kind, n in kinds:
        if sizes.size and (sizes == n).all() and (mesh["types"] is None or (mesh["types"] == kind).all()):
            return mesh["connectivity"].reshape(-1, n)
    raise InputError(f"{path}: cells are not all of one of the VTK types {', '.join(str(k) for k, _ in kinds)}")


def tetrahedra(mesh, path):
    return cells_of(mesh, path, ((VTK_QUADRATIC_TETRA, 10), (VTK_TETRA, 4)))


def triangles_of(mesh, path):
    return cells_of(mesh, path, ((VTK_QUADRATIC_TRIANGLE, 6), (VTK_TRIANGLE, 3)))


def section_y(points, tets, values=None, y0=0.0):
    """The cut of the tetrahedra by the plane y = y0 in (x, z): (xz, triangles, vals, segments). A face lying
    in the plane (a mirrored half mesh's cut: every face there is one) is taken once and split at its mid-edge
    nodes into 4; a tetrahedron the plane crosses gives its polygon, fanned into triangles. vals (vertices × k):
    `values` (points × k) at the vertices, nodal on a face, along a crossed edge the edge's quadratic through
    its mid node. segments: the cut polygons' edges, through the mid-edge nodes (the mesh the section shows)."""
    values = np.zeros((len(points), 0)) if values is None else values.reshape(len(points), -1)
    d = points[:, 1] - y0
    side = np.where(np.abs(d) <= 1e-9 * np.ptp(points, axis=0).max(), 0, np.sign(d)).astype(int)
    corners = tets[:, :4]
    quadratic = tets.shape[1] == 10
    s = side[corners]
    xz, tris, vals, segs = [np.zeros((0, 2))], [np.zeros((0, 3), dtype=int)], [np.zeros((0, values.shape[1]))], []
    n = 0
    on = np.where((s == 0).sum(axis=1) == 3)[0]
    if on.size:
        local = np.argsort(s[on] != 0, axis=1, kind="stable")[:, :3]  # the three corners in the plane
        faces = np.take_along_axis(corners[on], local, axis=1)
        _, first = np.unique(np.sort(faces, axis=1), axis=0, return_index=True)
        first.sort()
        on, local, faces = on[first], local[first], faces[first]
        if quadratic:
            a, b, c = local.T
            mids = np.stack([tets[on, TET_MID[a, b]], tets[on, TET_MID[b, c]], tets[on, TET_MID[c, a]]], axis=1)
            nodes = np.concatenate([faces, mids], axis=1)  # a, b, c, ab, bc, ca
            sub = np.array([[0, 3, 5], [3, 1, 4], [5, 4, 2], [3, 4, 5]])
            loops = np.array([0, 3, 1, 4, 2, 5, 0])
        else:
            nodes, sub, loops = faces, np.array([[0, 1, 2]]), np.array([0, 1, 2, 0])
        used, inverse = np.unique(nodes, return_inverse=True)
        local_nodes = inverse.reshape(nodes.shape)
        xz.append(points[used][:, [0, 2]])
        vals.append(values[used])
        tris.append(local_nodes[:, sub].reshape(-1, 3))
        p = points[nodes][:, loops][:, :, [0, 2]]
        segs.append(np.stack([p[:, :-1], p[:, 1:]], axis=2).reshape(-1, 2, 2))
        n = len(used)
    for t in np.where((s.max(axis=1) > 0) & (s.min(axis=1) < 0))[0]:
        c, st = corners[t], s[t]
        pts = [points[c[i]] for i in range(4) if st[i] == 0]
        pv = [values[c[i]] for i in range(4) if st[i] == 0]
        for e, (i, j) in enumerate(TET_EDGES):
            if st[i] * st[j] < 0:
                f = d[c[i]] / (d[c[i]] - d[c[j]])
                pts.append(points[c[i]] + f * (points[c[j]] - points[c[i]]))
                vi, vj = values[c[i]], values[c[j]]
                pv.append(vi * (1 - f) * (1 - 2 * f) + 4 * values[tets[t, 4 + e]] * f * (1 - f) + vj * f * (2 * f - 1)
                          if quadratic else vi + f * (vj - vi))
        q = np.array(pts)[:, [0, 2]]
        o = np.argsort(np.arctan2(q[:, 1] - q[:, 1].mean(), q[:, 0] - q[:, 0].mean()), kind="stable")
        q = q[o]
        xz.append(q)
        vals.append(np.array(pv)[o])
        tris.append(n + np.array([[0, k, k + 1] for k in range(1, len(q) - 1)]))
        segs.append(np.stack([q, np.roll(q, -1, axis=0)], axis=1))
        n += len(q)
    segs = np.concatenate(segs) if segs else np.zeros((0, 2, 2))
    return np.concatenate(xz), np.concatenate(tris), np.concatenate(vals), segs


def read_sensor_positions(d):
    t = read_csv(os.path.join(d, "contact/sensors.csv"), {"sensor": sensor_number, "x_mm": number, "y_mm": number})
    return [(int(s), x, y) for s, x, y in zip(t["sensor"].tolist(), t["x_mm"].tolist(), t["y_mm"].tolist())]


def read_contact_zone(d):
    """contact/pressure.vtp: points, triangles and the named arrays; `zone` the active nodes' mask."""
    path = os.path.join(d, "contact/pressure.vtp")
    pr = read_vtk(path, point_arrays=("pressure_kPa", "traction_kPa", "in_contact"))
    pr["triangles"] = cells_of(pr, path, ((VTK_TRIANGLE, 3),))
    pr["zone"] = pr["in_contact"] > 0.5
    if not pr["zone"].any():
        raise InputError(f"{path}: no node in contact (in_contact)")
    return pr


def contact_outline(ax, pr, **style):
    """The contact zone's outline seen from above: the level 1/2 of in_contact (1 at the active nodes) on the
    zone's triangles, halfway between the last active node and the first free one."""
    tri = matplotlib.tri.Triangulation(pr["points"][:, 0], pr["points"][:, 1], pr["triangles"])
    return ax.tricontour(tri, pr["in_contact"], levels=[0.5], **style)


def contact_on_section(pr, y0=0.0):
    """The active nodes on the line y = y0 of the top, sorted along x: (x, z), or None."""
    p = pr["points"]
    m = pr["zone"] & (np.abs(p[:, 1] - y0) <= 1e-9 * np.ptp(p, axis=0).max())
    if not m.any():
        return None
    o = np.argsort(p[m, 0], kind="stable")
    return p[m][o][:, 0], p[m][o][:, 2]


def section_window(points, sensors, contact, margin=1.5):
    """The x range of the section drawn: the sensors on y = 0 and the contact on it, with a margin, inside the
    skin."""
    xs = [x for _, x, y in sensors if abs(y) < 1e-9]
    if contact is not None:
        xs += [contact[0].min(), contact[0].max()]
    lo, hi = points[:, 0].min(), points[:, 0].max()
    if not xs:
        return lo, hi
    return max(lo, min(xs) - margin), min(hi, max(xs) + margin)


def sliding_direction(d, pr):
    """The unit tangential traction's resultant (the plate's motion) when contact/summary.json's friction mode
    slides (uncoupled, coupled) and the traction is not zero; else None."""
    path = os.path.join(d, "contact/summary.json")
    try:
        with open(path) as f:
            mode = json.load(f).get("friction")
    except (OSError, UnicodeDecodeError, ValueError, AttributeError) as e:
        raise InputError(f"{path}: {e}") from None
    r = pr["traction_kPa"].reshape(len(pr["points"]), -1)[:, :2].sum(axis=0)
    if mode not in ("uncoupled", "coupled") or np.hypot(*r) == 0:
        return None
    return r / np.hypot(*r)


def mark_sensors(ax, sensors, on_line=False, **style):
    """Every sensor at its (x, y) from above, or (on_line) those on y = 0 at their x, below the base line."""
    for s, x, y in sensors:
        if not on_line:
            ax.plot([x], [y], "o", color=sensor_color(s), mec="k", mew=0.6, zorder=5, **style)
        elif abs(y) < 1e-9:
            ax.plot([x], [0], "^", color=sensor_color(s), mec="k", mew=0.6, clip_on=False, zorder=5,
                    transform=ax.transData + matplotlib.transforms.ScaledTranslation(0, -4.5 / 72,
                                                                                     ax.figure.dpi_scale_trans),
                    **style)


def section_axes(x0, x1, height_mm, exaggeration, width_in, left, right, bottom, top):
    """A figure whose one axes shows x0..x1 (mm) across width_in inches and 0..height_mm with z stretched
    `exaggeration` times: its height follows from the window (no blank band beside an equal-aspect axes)."""
    h = width_in * exaggeration * height_mm / (x1 - x0)
    fig = plt.figure(figsize=(left + width_in + right, bottom + h + top))
    w, H = fig.get_size_inches()
    ax = fig.add_axes([left / w, bottom / H, width_in / w, h / H])
    ax.set_xlim(x0, x1)
    ax.set_ylim(0, height_mm)
    return fig, ax


def skin_mesh(d):
    bpath, mpath = os.path.join(d, "mesh/boundary.vtu"), os.path.join(d, "mesh/mesh.vtu")
    b = read_vtk(bpath, cell_arrays=("boundary_marker",))
    faces = triangles_of(b, bpath)[b["boundary_marker"] == BOUNDARY_TOP]
    if not len(faces):
        raise InputError(f"{bpath}: no top face (boundary_marker {BOUNDARY_TOP})")
    m = read_vtk(mpath)
    tets = tetrahedra(m, mpath)
    pr, sensors = read_contact_zone(d), read_sensor_positions(d)
    # The top's triangle edges, each once, through its mid-edge node when quadratic.
    pairs = ((0, 1, 3), (1, 2, 4), (2, 0, 5)) if faces.shape[1] == 6 else ((0, 1, 0), (1, 2, 1), (2, 0, 2))
    edges = np.concatenate([faces[:, [i, j, k]] for i, j, k in pairs])
    _, first = np.unique(np.sort(edges[:, :2], axis=1), axis=0, return_index=True)
    edges = edges[np.sort(first)]
    xy = b["points"][:, :2]
    top = np.concatenate([np.stack([xy[edges[:, 0]], xy[edges[:, 2]]], axis=1),
                          np.stack([xy[edges[:, 2]], xy[edges[:, 1]]], axis=1)])
    contact = contact_on_section(pr)
    x0, x1 = section_window(m["points"], sensors, contact)
    _, _, _, segs = section_y(m["points"], tets)
    keep = (segs[:, :, 0].max(axis=1) >= x0) & (segs[:, :, 0].min(axis=1) <= x1)
    fig = plt.figure(figsize=(9, 4.3))
    ax = fig.add_axes([0.6 / 9, 0.5 / 4.3, 3.5 / 9, 3.5 / 4.3])
    ax.add_collection(matplotlib.collections.LineCollection(top, colors="0.25", linewidths=0.25))
    contact_outline(ax, pr, colors="tab:red", linewidths=1.4)
    mark_sensors(ax, sensors, ms=3.5)
    lo, hi = xy.min(axis=0) - 0.5, xy.max(axis=0) + 0.5
    half = (hi - lo).max() / 2
    ax.set_xlim((lo + hi)[0] / 2 - half, (lo + hi)[0] / 2 + half)
    ax.set_ylim((lo + hi)[1] / 2 - half, (lo + hi)[1] / 2 + half)
    ax.set_aspect("equal")
    ax.grid(False)
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title("top surface from above: its triangles", fontsize=9)
    ax.tick_params(labelsize=8)
    ax.legend(handles=[matplotlib.lines.Line2D([], [], color="tab:red", lw=1.4, label="contact zone"),
                       matplotlib.lines.Line2D([], [], ls="", marker="o", mfc="0.6", mec="k", ms=4,
                                               label="sensors (on the base)")],
              loc="lower left", fontsize=8, framealpha=0.9)
    # The section: its window's width and height in the figure's right part, z stretched.
    exaggeration, zmax = 2, m["points"][:, 2].max()
    width = 4.25
    height = width * exaggeration * (zmax + 0.1) / (x1 - x0)
    bx = fig.add_axes([4.6 / 9, (0.5 + (3.5 - height) / 2) / 4.3, width / 9, height / 4.3])
    bx.add_collection(matplotlib.collections.LineCollection(segs[keep], colors="0.2", linewidths=0.35))
    bx.axhline(0, color="k", lw=1.2)
    mark_sensors(bx, sensors, on_line=True, ms=5)
    if contact is not None:
        bx.plot(contact[0], contact[1], color="tab:red", lw=2.5, solid_capstyle="butt", zorder=4, clip_on=False)
    bx.set_xlim(x0, x1)
    bx.set_ylim(0, zmax + 0.1)
    bx.set_aspect(exaggeration)
    bx.grid(False)
    bx.set_xlabel("x (mm); ▲ sensors", labelpad=6)
    bx.set_ylabel(f"z (mm), stretched {exaggeration}×", fontsize=9)
    bx.set_title("section y = 0: the cut tetrahedra; base z = 0", fontsize=9)
    bx.tick_params(labelsize=8)
    bx.tick_params(axis="x", pad=8)
    return fig


def contact_pressure_map(d):
    pr = read_contact_zone(d)
    direction = sliding_direction(d, pr)
    p, z = pr["points"], pr["zone"]
    tri = matplotlib.tri.Triangulation(p[:, 0], p[:, 1], pr["triangles"])
    margin = 0.4
    lo, hi = p[z, :2].min(axis=0) - margin, p[z, :2].max(axis=0) + margin
    side = 3.4  # inches, the map's height
    wmap = side * (hi[0] - lo[0]) / (hi[1] - lo[1])
    fig = plt.figure(figsize=(9, side + 0.95))
    ax = fig.add_axes([0.65 / 9, 0.55 / (side + 0.95), wmap / 9, side / (side + 0.95)])
    cax = fig.add_axes([(0.65 + wmap + 0.1) / 9, 0.55 / (side + 0.95), 0.15 / 9, side / (side + 0.95)])
    px0 = 0.65 + wmap + 0.1 + 0.15 + 0.95
    bx = fig.add_axes([px0 / 9, 0.55 / (side + 0.95), (9 - px0 - 0.15) / 9, side / (side + 0.95)])
    cmap = plt.get_cmap("viridis")
    im = ax.tripcolor(tri, pr["pressure_kPa"], shading="gouraud", cmap=cmap, vmin=0,
                      vmax=pr["pressure_kPa"].max(), rasterized=True)
    contact_outline(ax, pr, colors="w", linewidths=1.0)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.grid(False)
    ax.set_facecolor(cmap(0.0))  # outside the zone solved: no contact, p = 0
    if direction is not None:
        tail = np.array([lo[0] + 0.06 * (hi[0] - lo[0]), hi[1] - 0.07 * (hi[1] - lo[1])])
        ax.annotate("", xy=tail + 0.22 * (hi[0] - lo[0]) * direction, xytext=tail,
                    arrowprops=dict(arrowstyle="-|>", color="w", lw=1.6, mutation_scale=14))
        ax.text(tail[0], tail[1] - 0.04 * (hi[1] - lo[1]), "sliding direction", color="w", ha="left", va="top",
                fontsize=8)
    ax.plot([], [], color="w", lw=1.0, label="contact zone (active nodes)")
    ax.legend(loc="lower left", fontsize=8, facecolor=cmap(0.0), labelcolor="w", edgecolor="w")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title("p on the skin's top, from above", fontsize=9)
    ax.tick_params(labelsize=8)
    cax.grid(False)
    cb = fig.colorbar(im, cax=cax)
    cb.set_label("contact pressure p (kPa)", fontsize=9)
    cb.ax.tick_params(labelsize=8)
    line = np.abs(p[:, 1]) <= 1e-9 * np.ptp(p, axis=0).max()
    if line.any():
        o = np.argsort(p[line, 0], kind="stable")
        bx.plot(p[line, 0][o], pr["pressure_kPa"][line][o], "-", color="k", lw=1.2, marker=".", ms=3,
                label="p at the nodes on y = 0")
        zl = line & z
        if zl.any():
            bx.axvspan(p[zl, 0].min(), p[zl, 0].max(), color="tab:green", alpha=0.12, lw=0,
                       label="active nodes on y = 0")
        bx.legend(loc="upper left", fontsize=8)
    else:
        no_data(bx, "no node on y = 0")
    bx.set_xlim(lo[0], hi[0])
    bx.set_ylim(0, 1.3 * pr["pressure_kPa"].max())
    bx.set_xlabel("x (mm), along y = 0")
    bx.set_ylabel("p (kPa)")
    bx.set_title("p along y = 0", fontsize=9)
    bx.tick_params(labelsize=8)
    return fig


def skin_stress(d):
    path = os.path.join(d, "contact/fields.vtu")
    f = read_vtk(path, point_arrays=("stress_MPa",))
    if f["stress_MPa"].ndim != 2 or f["stress_MPa"].shape[1] != 9:
        raise InputError(f"{path}: array 'stress_MPa' has not 9 components")
    tets = tetrahedra(f, path)
    pr, sensors = read_contact_zone(d), read_sensor_positions(d)
    contact = contact_on_section(pr)
    direction = sliding_direction(d, pr)
    xz, tris, vals, _ = section_y(f["points"], tets, 1e3 * f["stress_MPa"][:, 8])  # σ_zz (row-major), kPa
    x0, x1 = section_window(f["points"], sensors, contact)
    keep = (xz[tris, 0].max(axis=1) >= x0) & (xz[tris, 0].min(axis=1) <= x1)
    v = vals[:, 0]
    top = np.abs(v[np.unique(tris[keep])]).max() or 1.0
    exaggeration, zmax = 2, f["points"][:, 2].max()
    fig, ax = section_axes(x0, x1, zmax + 0.45, exaggeration, 7.3, left=0.65, right=1.05, bottom=0.65, top=0.3)
    cmap = plt.get_cmap("RdBu_r")
    im = ax.tripcolor(matplotlib.tri.Triangulation(xz[:, 0], xz[:, 1], tris[keep]), v, shading="gouraud",
                      cmap=cmap, vmin=-top, vmax=top, rasterized=True)
    ax.set_facecolor("0.8")  # outside the skin
    ax.axhline(0, color="k", lw=1.2)
    mark_sensors(ax, sensors, on_line=True, ms=6)
    if contact is not None:
        ax.plot(contact[0], contact[1] + 0.05, color="k", lw=3, solid_capstyle="butt", zorder=4,
                label="contact on y = 0")
        if direction is not None and abs(direction[0]) > 1e-9:
            xm, zt, sgn = contact[0].mean(), contact[1].max() + 0.27, np.sign(direction[0])
            ax.annotate("", xy=(xm + 0.7 * sgn, zt), xytext=(xm - 0.7 * sgn, zt),
                        arrowprops=dict(arrowstyle="-|>", color="k", lw=1.4, mutation_scale=12))
            ax.text(xm + 0.9, zt, "sliding", ha="left", va="center", fontsize=8)
    ax.set_aspect(exaggeration)
    ax.grid(False)
    w, h = fig.get_size_inches()
    cax = fig.add_axes([(w - 0.95) / w, 0.65 / h, 0.15 / w, (h - 0.95) / h])
    cax.grid(False)
    cb = fig.colorbar(im, cax=cax)
    cb.set_label("σ_zz (kPa; < 0: compression)", fontsize=9)
    cb.ax.tick_params(labelsize=8)
    ax.set_xlabel("x (mm); ▲ sensors on the base", labelpad=4)
    ax.tick_params(axis="x", pad=9, labelsize=8)
    ax.tick_params(axis="y", labelsize=8)
    ax.set_ylabel(f"z (mm), stretched {exaggeration}×")
    ax.set_title("σ_zz on the section y = 0 through the skin (grey: outside it; black bar: the contact)",
                 fontsize=9)
    return fig


def budget_style(names):
    """(colour, marker) per hypothesis: a family (the name's first word: coulomb, shear, mixed, …) has one
    colour map, its members darker in file order."""
    maps = ("Blues", "Reds", "Greens", "Purples", "Oranges", "Greys")
    families = in_order(np.array([n.split("_")[0] for n in names]))
    members = {f: [n for n in names if n.split("_")[0] == f] for f in families}
    markers = "osD^v<>PX*h"
    style = {}
    for i, fam in enumerate(families):
        cmap = plt.get_cmap(maps[i % len(maps)])
        k = len(members[fam])
        for j, n in enumerate(members[fam]):
            style[n] = (cmap(0.9 - 0.5 * j / max(k - 1, 1)), markers[names.index(n) % len(markers)])
    return style


def budget_summary(d):
    t = read_csv(os.path.join(d, "crosscheck/hole_budget.csv"),
                 {"hypothesis": text, "case": one_of(*CASES), "sensor": sensor_number, "component": one_of("z", "x"),
                  "fe_peak_kPa": number, "model_peak_kPa": number, "ratio": number})
    names = in_order(t["hypothesis"])
    style = budget_style(names)
    f = read_csv(os.path.join(d, "crosscheck/hole_budget_facts.csv"),
                 {"hypothesis": text, "fact": one_of("F1", "F2", "F3", "F4", "F5"), "met": one_of("0", "1")})
    met = {n: " ".join(sorted(x for x, h, m in zip(f["fact"], f["hypothesis"], f["met"]) if h == n and m == "1"))
           for n in names}
    sensors = sorted(set(t["sensor"].tolist()))
    fig, axes = plt.subplots(1, 2, figsize=(9, 4.8), sharey=True)
    for ax, comp in zip(axes, ("z", "x")):
        ax.axhspan(0.5, 2, color="tab:green", alpha=0.12, lw=0, label="F2: the back sensors match (0.5–2×)")
        ax.axhspan(2, 4, color="tab:orange", alpha=0.15, lw=0, label="F3: the front sensors up to 4× (≥ 2×)")
        ax.axhline(1, color="k", lw=0.8, ls="--", label="FE = the paper's model")
        for n in names:
            m = (t["hypothesis"] == n) & (t["case"] == "sliding") & (t["component"] == comp) & (t["ratio"] > 0)
            if m.any():
                color, marker = style[n]
                ax.plot(*series(t, m, "sensor", "ratio"), marker=marker, color=color, lw=1.1, ms=4.5,
                        label=f"{n} (met: {met[n] or 'none'})")
        ax.set_yscale("log")
        plain_log_ticks(ax.yaxis)
        ax.yaxis.set_major_locator(matplotlib.ticker.FixedLocator([0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 4, 10, 20]))
        ax.set_xticks(sensors)
        ax.set_xticklabels([f"#{s}" for s in sensors])
        ax.set_xlabel("sensor")
        ax.set_title(f"ς_{comp}", fontsize=10)
        ax.tick_params(labelsize=8)
    axes[0].set_ylabel("max |ς| sliding: FE / paper's model")
    handles, labels = axes[0].get_legend_handles_labels()
    order = list(range(3, len(handles))) + [0, 1, 2]
    fig.legend([handles[i] for i in order], [labels[i] for i in order], loc="lower center", ncol=4, fontsize=8)
    fig.suptitle("Hole-signal budget: max |ς| of each hypothesis over the paper's model, per sensor (sliding)",
                 fontsize=10)
    inch_margins(fig, left=0.7, right=0.15, bottom=1.35, top=0.55, wspace=0.06, hspace=0.2)
    return fig


FIGURES = [
    ("fig1_calibration.png", ("green/green.csv", "kfit/kfit.json"), fig1_calibration),
    ("fig2_static_sliding.png", ("crosscheck/readings.csv",), fig2_static_sliding),
    ("fig3_varsigma_z.png", ("crosscheck/defect.csv", "crosscheck/readings.csv"), lambda d: fig_varsigma(d, "z")),
    ("fig4_varsigma_x.png", ("crosscheck/defect.csv", "crosscheck/readings.csv"), lambda d: fig_varsigma(d, "x")),
    ("pressure_profiles.png", ("crosscheck/pressure.csv",), pressure_profiles),
    ("green_vs_halfspace.png", ("green/green.csv", "kfit/kfit.json"), green_vs_halfspace),
    ("k_sweep.png", ("kfit/k_sweep.csv", "kfit/kfit.json"), k_sweep),
    ("pareto.png", ("study/chain_study.csv",), pareto),
    ("post_design.png", ("green/post_design.csv",), post_design),
    ("perception_scan.png", ("perception/row.csv", "perception/summary.json"), perception_scan),
    ("perception_superposition.png", ("perception/pairs.csv", "perception/summary.json"), perception_superposition),
    ("perception_detection.png", ("perception/detection.csv", "perception/detection_map.csv",
                                  "perception/summary.json"), perception_detection),
    ("perception_inversion.png", ("perception/row.csv", "perception/features.csv", "perception/summary.json"),
     perception_inversion),
    ("skin_mesh.png", ("mesh/boundary.vtu", "mesh/mesh.vtu", "contact/pressure.vtp", "contact/sensors.csv"), skin_mesh),
    ("contact_pressure_map.png", ("contact/pressure.vtp", "contact/summary.json"), contact_pressure_map),
    ("skin_stress.png", ("contact/fields.vtu", "contact/pressure.vtp", "contact/sensors.csv", "contact/summary.json"),
     skin_stress),
    ("budget_summary.png", ("crosscheck/hole_budget.csv", "crosscheck/hole_budget_facts.csv"), budget_summary),
]


def save(fig, path):
    tmp = os.path.join(os.path.dirname(path), "." + os.path.basename(path) + ".tmp")
    try:
        fig.savefig(tmp, dpi=120, format="png", metadata={"Software": None})
        os.replace(tmp, path)
    finally:
        plt.close(fig)
        if os.path.exists(tmp):
            os.remove(tmp)


def main(argv):
    usage = ("usage: /usr/bin/python3 scripts/figures.py DIR [--only NAMES | --except NAMES] [--wait-for-go]  "
             "(DIR: a `skinfem report` output folder; NAMES: comma-separated figure names, e.g. pareto.png)")
    wait = len(argv) in (3, 5) and argv[-1] == "--wait-for-go"
    if wait:
        argv = argv[:-1]
    selection = None
    if len(argv) == 4 and argv[2] in ("--only", "--except"):
        selection = (argv[2], set(argv[3].split(",")))
    if len(argv) not in (2, 4) or (len(argv) == 4 and not selection) or not os.path.isdir(argv[1]):
        print(usage, file=sys.stderr)
        return 2
    d = argv[1]
    if wait and sys.stdin.readline().strip() != "go":
        return 0  # the report stopped before these figures' inputs were written
    out = os.path.join(d, "figures")
    os.makedirs(out, exist_ok=True)
    written = skipped = 0
    global _FIGURES, _DIR
    try:
        _FIGURES, _DIR = FIGURES + budget_figures(d) + finite_figures(d), d
    except InputError as e:
        print(f"figures: error: {e}", file=sys.stderr)
        return 2
    if selection:
        known = {f[0] for f in FIGURES}
        unknown = sorted(n for n in selection[1]
                         if n not in known and not n.startswith("budget_") and n != "finite_path.png")
        if unknown:
            print(f"figures: error: {selection[0]} {','.join(unknown)}: not a figure (known: "
                  f"{', '.join(sorted(known))}, budget_<hypothesis>.png)", file=sys.stderr)
            return 2
        keep = selection[0] == "--only"
        _FIGURES = [f for f in _FIGURES if (f[0] in selection[1]) == keep]
    chosen = {f[0] for f in _FIGURES}
    for name in os.listdir(out):  # figures/ then holds exactly what this run drew, nothing from an earlier one
        if name.endswith(".png") and (selection is None or name in chosen):
            os.remove(os.path.join(out, name))
    budget = [f for f in _FIGURES if "crosscheck/hole_budget_signals.csv" in f[1]]  # not budget_summary.png
    signals = any("crosscheck/defect.csv" in f[1] for f in _FIGURES)
    try:
        if signals and os.path.isfile(os.path.join(d, "crosscheck/defect.csv")):
            defect_table(d)
        if budget and all(os.path.isfile(os.path.join(d, f)) for f in budget[0][1]):
            budget_tables(d)
    except InputError as e:
        print(f"figures: error: {e}", file=sys.stderr)
        return 2
    # Each figure is independent: drawn on the machine's cores in forked workers, reported in list order.
    workers = min(len(os.sched_getaffinity(0)), len(_FIGURES))
    if workers > 1:
        with multiprocessing.get_context("fork").Pool(workers) as pool:
            outcomes = pool.map(draw_figure, range(len(_FIGURES)), chunksize=1)
    else:
        outcomes = [draw_figure(i) for i in range(len(_FIGURES))]
    for (name, _, _), (status, detail) in zip(_FIGURES, outcomes):
        if status == "error":
            print(f"figures: error: {detail}", file=sys.stderr)
            return 2
        if status == "skipped":
            print(f"figures: skipped {name}: missing {detail}")
            skipped += 1
        else:
            print(f"figures: wrote figures/{name}")
            written += 1
    print(f"figures: {written} written, {skipped} skipped")
    return 0


_FIGURES, _DIR = [], ""


def draw_figure(i):
    """("wrote" | "skipped" | "error", detail) for figure i of _FIGURES."""
    name, inputs, draw = _FIGURES[i]
    missing = [f for f in inputs if not os.path.isfile(os.path.join(_DIR, f))]
    if missing:
        return "skipped", ", ".join(missing)
    try:
        save(draw(_DIR), os.path.join(_DIR, "figures", name))
    except InputError as e:
        return "error", str(e)
    except MissingModule as e:
        return "skipped", str(e)
    return "wrote", ""


if __name__ == "__main__":
    sys.exit(main(sys.argv))
