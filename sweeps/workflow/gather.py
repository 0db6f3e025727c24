"""A sweep's member runs and their gather, the jobs of the Snakefile beside this file, run in the sweep's
folder (where manifest.json is):
  gather.py member ID THREADS STATUS_PATH    one member
  gather.py gather                           the tables and plots

run_member: one member's skinfem run, its status (exit code, error line, time, and whether the next sweep
runs it again: killed by a signal or out of memory) in members/<id>/status.json.
gather: results.csv (one row per member: its id, the axes' values, its status, every number of its summary
file flattened as dotted keys), results.h5 (per member: its parameters as attributes, every numeric array of
its summary file and every column of its CSV outputs) and plots/<axis>.png (the headline numbers against each
axis, one line per value of the other axes, with error bars where the members carry them: error_of). A summary
number equal to an axis on every member is not repeated in results.csv.
"""
import csv
import datetime
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time

# Units of the scene keys an axis may vary (scene conventions: mm, N, MPa); a column is named with its unit.
LENGTH_KEYS = {"h", "R", "R_y", "diameter", "radius", "half_width", "h_min", "h_max", "sensor_h", "spacing",
               "height", "displacement", "zone_radius", "truncation_radius", "period", "edge_width",
               "disc_diameter", "punch_diameter", "width", "depth"}
UNITS = {"E": "MPa", "force": "N"}

# What the plots show: the keys of the summary file that the command table names (manifest "plotted",
# scene/commands.cpp); for commands whose results are per sensor (in results.h5), the cost. The table holds
# every number.
COST = ["dofs", "wall_total_s"]


def axis_column(axis):
    last = axis["pointer"].rsplit("/", 1)[-1]
    unit = "mm" if last in LENGTH_KEYS else UNITS.get(last, "")
    return axis["column"] + ("_" + unit if unit else "")


def write_json_atomic(path, value):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(value, f, indent=2)
        f.write("\n")
    os.replace(tmp, path)


def run_member(manifest, member_id, threads, status_path):
    member_dir = os.path.dirname(status_path)
    out = os.path.join(member_dir, "out")
    shutil.rmtree(out, ignore_errors=True)  # an interrupted run's files
    argv = [manifest["skinfem"], manifest["command"], "scenes/%s.json" % member_id, "--out", out]
    argv += manifest["options"]
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OPENBLAS_NUM_THREADS=str(threads))
    started = datetime.datetime.now(datetime.timezone.utc).isoformat()
    t0 = time.monotonic()
    log_path = os.path.join(member_dir, "log.txt")
    with open(log_path, "w") as log:
        rc = subprocess.call(argv, stdout=log, stderr=subprocess.STDOUT, env=env)
    wall = time.monotonic() - t0
    error = ""
    if rc < 0:
        # Completed, not failed, so that the gather still runs and shows it; "retry" runs it again on the
        # next sweep (a kill is no verdict on the member).
        error = "killed by signal %d (%s)" % (-rc, signal_name(-rc))
    elif rc != 0:
        with open(log_path) as log:
            lines = [l.strip() for l in log if l.startswith("skinfem:")]
        error = lines[-1] if lines else "exit code %d, no error line (see %s)" % (rc, log_path)
    write_json_atomic(status_path, {"id": member_id, "exit_code": rc, "error": error, "wall_s": wall,
                                    "started_utc": started, "argv": argv,
                                    "retry": rc < 0 or out_of_memory(error)})


def signal_name(number):
    try:
        return signal.Signals(number).name
    except ValueError:
        return "unknown"


# Out of memory is the machine's state (and the other jobs'), not the member's: MUMPS's INFOG(1) = -9 (its
# work array too small) or -13 (an allocation failed), a refusal of a factorization or mesh larger than the
# memory then available (fem/mumps_ldlt.cpp, pipeline/resources.cpp: "... GB available; coarsen ..."), or an
# allocation that failed elsewhere. Such a member runs again on the next sweep; --max-dofs refusals do not.
OUT_OF_MEMORY = re.compile(r"INFOG\(1\) = -(9|13)\b|GB available; coarsen |std::bad_alloc")


def out_of_memory(error):
    return bool(OUT_OF_MEMORY.search(error))


def flatten(value, prefix=""):
    """Every number (and boolean) of a JSON object, keyed by its dotted path; lists are left to the HDF5."""
    out = {}
    if isinstance(value, dict):
        for k, v in value.items():
            out.update(flatten(v, prefix + k + "."))
    elif isinstance(value, bool):
        out[prefix[:-1]] = int(value)
    elif isinstance(value, (int, float)):
        out[prefix[:-1]] = value
    return out


def arrays(value, prefix=""):
    """Every list of numbers (or of equal-length lists of numbers) of a JSON object, by its dotted path; a
    list of objects (one per sensor) gives one array per number they hold, over the list."""
    out = {}
    if isinstance(value, dict):
        for k, v in value.items():
            out.update(arrays(v, prefix + k + "."))
    elif isinstance(value, list) and value:
        if all(isinstance(x, dict) for x in value):
            flats = [flatten(x) for x in value]
            for key in flats[0]:
                if all(key in f for f in flats):
                    out[prefix + key] = [f[key] for f in flats]
            return out
        flat = value if not isinstance(value[0], list) else [x for row in value for x in row]
        if all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in flat):
            if not isinstance(value[0], list) or len({len(r) for r in value}) == 1:
                out[prefix[:-1]] = value
    return out


def gather(manifest, directory):
    import h5py
    import numpy as np

    axes = manifest["axes"]
    rows, numbers, columns = [], [], []
    for m in manifest["members"]:
        with open(os.path.join(directory, "members", m["id"], "status.json")) as f:
            status = json.load(f)
        summary = {}
        if status["exit_code"] == 0:
            with open(os.path.join(directory, "members", m["id"], "out", manifest["summary_file"])) as f:
                summary = json.load(f)
        flat = flatten(summary)
        for k in flat:
            if k not in columns:
                columns.append(k)
        rows.append((m, status, summary))
        numbers.append(flat)

    # A summary number that repeats an axis on every member (kfit.json's "nu" on a /material/nu axis) is left
    # out: the axis column says it.
    columns = [k for k in columns if not any(repeats_axis(k, i, rows, numbers) for i in range(len(axes)))]
    header = ["id"] + [axis_column(a) for a in axes] + ["exit_code", "error", "member_wall_s"] + columns
    tmp = os.path.join(directory, "results.csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        for (m, status, _), flat in zip(rows, numbers):
            w.writerow([m["id"]] + [json.dumps(v) if not isinstance(v, (int, float)) else repr(v)
                                    for v in m["values"]]
                       + [status["exit_code"], status["error"], repr(status["wall_s"])]
                       + [repr(flat[k]) if k in flat else "" for k in columns])
    os.replace(tmp, os.path.join(directory, "results.csv"))

    tmp = os.path.join(directory, "results.h5.tmp")
    with h5py.File(tmp, "w") as h5:
        h5.attrs["sweep"] = manifest["name"]
        h5.attrs["command"] = " ".join(["skinfem", manifest["command"]] + manifest["options"])
        for m, status, summary in rows:
            g = h5.create_group("members/" + m["id"])
            for a, v in zip(axes, m["values"]):
                g.attrs[axis_column(a)] = v if isinstance(v, (int, float)) else json.dumps(v)
            g.attrs["exit_code"] = status["exit_code"]
            g.attrs["error"] = status["error"]
            for key, value in arrays(summary).items():
                g.create_dataset(key, data=np.asarray(value, dtype=float))
            out = os.path.join(directory, "members", m["id"], "out")
            for name in sorted(os.listdir(out)) if os.path.isdir(out) else []:
                if name.endswith(".csv"):
                    store_csv(g, name[:-4], os.path.join(out, name))
    os.replace(tmp, os.path.join(directory, "results.h5"))

    plotted = [k for k in manifest.get("plotted") or COST if k in columns]
    written = plot(manifest, rows, numbers, plotted, os.path.join(directory, "plots")) if plotted else []
    failed = sum(1 for _, s, _ in rows if s["exit_code"] != 0)
    plural = lambda n: "" if n == 1 else "s"
    print("gathered %d member%s (%d ok, %d failed) into %s: results.csv (%d columns), results.h5, %d plot%s"
          % (len(rows), plural(len(rows)), len(rows) - failed, failed, os.path.abspath(directory),
             len(header), len(written), plural(len(written))))


def repeats_axis(key, i, rows, numbers):
    """Whether the summary number `key` equals axis i's value on every member that has it (and one does)."""
    pairs = [(m["values"][i], flat[key]) for (m, _, _), flat in zip(rows, numbers) if key in flat]
    return bool(pairs) and all(isinstance(v, (int, float)) and not isinstance(v, bool)
                               and math.isclose(v, x, rel_tol=1e-12, abs_tol=1e-15) for v, x in pairs)


def error_of(flat, key):
    """A plotted number's error bar where the member carries one: `<key>_error` (absolute) or
    `<key>_change_from_half_resolution` (relative: the meridian path's k against half its resolution)."""
    if key + "_error" in flat:
        return abs(flat[key + "_error"])
    if key + "_change_from_half_resolution" in flat:
        return abs(flat[key + "_change_from_half_resolution"] * flat[key])
    return None


def store_csv(group, name, path):
    """A CSV output's columns as datasets name/<column>: numbers as float arrays, text (green's component
    names) as strings."""
    import h5py
    import numpy as np

    with open(path, newline="") as f:
        table = list(csv.reader(f))
    if len(table) < 2:
        return
    for j, column in enumerate(table[0]):
        cells = [row[j] for row in table[1:] if j < len(row)]
        try:
            group.create_dataset(name + "/" + column, data=np.array([float(c) for c in cells]))
        except ValueError:
            group.create_dataset(name + "/" + column, data=np.array(cells, dtype=object),
                                 dtype=h5py.string_dtype())


def plot(manifest, rows, numbers, plotted, plots_dir):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(plots_dir, exist_ok=True)
    axes = manifest["axes"]
    written = []
    for i, axis in enumerate(axes):
        if not all(isinstance(m["values"][i], (int, float)) for m, _, _ in rows):
            continue  # a categorical axis: the table says it
        fig, panels = plt.subplots(1, len(plotted), figsize=(4.2 * len(plotted), 3.4), squeeze=False)
        groups = {}
        for (m, _, _), flat in zip(rows, numbers):
            others = tuple((axis_column(a), json.dumps(m["values"][j])) for j, a in enumerate(axes) if j != i)
            groups.setdefault(others, []).append((m["values"][i], flat))
        for panel, key in zip(panels[0], plotted):
            bars = None  # the largest error bar drawn
            for others, points in groups.items():
                points = sorted((x, f[key], error_of(f, key)) for x, f in points
                                if key in f and math.isfinite(f[key]))
                if points:
                    label = ", ".join("%s %s" % (o[0].rsplit(".", 1)[-1], o[1]) for o in others) or None
                    errors = [p[2] for p in points]
                    panel.errorbar([p[0] for p in points], [p[1] for p in points], fmt="o-", ms=3, capsize=2,
                                   yerr=errors if all(e is not None for e in errors) else None, label=label)
                    if all(e is not None for e in errors):
                        bars = max(bars or 0.0, max(errors))
            if manifest["command"] == "kfit" and "paper_k" in numbers[0]:
                panel.axhline(numbers[0]["paper_k"], color="k", ls="--", lw=0.8, label="the paper's k")
            panel.set_xlabel(axis_column(axis))
            lo, hi = panel.get_ylim()
            note = "" if bars is None else ("\nerror bars smaller than the markers" if bars < 0.01 * (hi - lo)
                                            else "\nwith the members' error bars")
            panel.set_title(key + note, fontsize=8.5)
            panel.grid(alpha=0.3)
        if len(groups) <= 10 and panels[0][-1].get_legend_handles_labels()[1]:
            panels[0][-1].legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1))
        fig.suptitle("%s: skinfem %s" % (manifest["name"], manifest["command"]), fontsize=9)
        fig.tight_layout()
        path = os.path.join(plots_dir, axis_column(axis) + ".png")
        fig.savefig(path + ".tmp.png", dpi=110)
        plt.close(fig)
        os.replace(path + ".tmp.png", path)
        written.append(path)
    return written


if __name__ == "__main__":
    with open("manifest.json") as f:
        manifest = json.load(f)
    if sys.argv[1:2] == ["member"] and len(sys.argv) == 5:
        run_member(manifest, sys.argv[2], int(sys.argv[3]), sys.argv[4])
    elif sys.argv[1:] == ["gather"]:
        gather(manifest, ".")
    else:
        sys.exit("usage: gather.py member ID THREADS STATUS_PATH | gather.py gather")
