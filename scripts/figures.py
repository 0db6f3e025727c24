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
# Needs only the standard library, numpy and matplotlib (Debian's /usr/bin/python3; Agg backend). No
# randomness and no version string in the PNGs (savefig metadata Software=None): same inputs, same bytes.
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
# Each PNG is written to a hidden temporary name in DIR/figures and renamed into place. A figure whose inputs
# are missing prints `figures: skipped <name>.png: missing <file>`. The PNGs this run selects (all, without
# --only or --except) are deleted first, so DIR/figures never keeps one from an earlier run that this run
# skipped or did not reach.
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
import matplotlib.lines  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import matplotlib.transforms  # noqa: E402
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
    budget = [f for f in _FIGURES if f[0].startswith("budget_")]
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
    return "wrote", ""


if __name__ == "__main__":
    sys.exit(main(sys.argv))
