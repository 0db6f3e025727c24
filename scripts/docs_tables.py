#!/usr/bin/python3
"""The docs' numbers tables, generated from the run they quote, so that they cannot go stale.

    scripts/docs_tables.py RUN_DIR            rewrite every generated table from RUN_DIR's outputs
    scripts/docs_tables.py RUN_DIR --check    exit 1, naming the table, where a doc differs from RUN_DIR

RUN_DIR is the output folder of `skinfem report scenes/candelier2011.json` (`scripts/run` writes it to
out/candelier2011): its report.json and crosscheck/readings.csv. A generated table sits between two marker
lines in a Markdown file under docs/:

    <!-- generated: NAME (scripts/docs_tables.py from skinfem report scenes/candelier2011.json) -->
    | ... the table ... |
    <!-- end generated: NAME -->

NAME is one of TABLES below. --check compares numbers, not times: the cost table's seconds and megabytes
belong to the machine that ran and are left out of the comparison (COMPARED).
The test `docs.tables` (label study) runs the report and checks.
"""
import csv
import json
import math
import os
import re
import sys

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The stages in the order the report runs them (report_run), for a table whose rows do not move between runs.
STAGE_ORDER = ["mesh", "assemble", "factor", "green_adjoints", "green_profiles", "condense", "contact",
               "defect", "kfit_wait", "crosscheck", "hole_budget", "perception_scans", "perception_inversion",
               "k_sweep_wait", "error_levels",
               "post_design_wait", "figures"]


def cell(text):
    """Text for a Markdown table cell: a literal | would end the cell."""
    return text.replace("|", "\\|")


ERROR_DIGITS = 2  # significant digits of an error bar; its value is given to the same decimal place


def headline(run):
    """report.json error_bars: each headline number with its error bar and how it was obtained."""
    rows = ["| quantity | value | error | how |", "|---|---:|---:|---|"]
    for e in run["report"]["error_bars"]:
        unit = {"um": "µm"}.get(e["unit"], e["unit"])
        decimals = max(0, ERROR_DIGITS - 1 - math.floor(math.log10(e["error"])))
        value = "%.*f" % (decimals, e["value"]) + (" " + unit if unit else "")
        rows.append("| %s | %s | ± %.*g | %s |"
                    % (cell(e["what"]), value, ERROR_DIGITS, e["error"], cell(e["method"])))
    return rows


def budget(run):
    """report.json hole_budget: each hypothesis's sliding amplitude ratio FE/model on the back and front
    sensors (ς_z, ς_x) and the paper's five facts it meets; skipped hypotheses with their reason."""
    report = run["report"]
    front = {int(s) for s in re.findall(r"#(\d+)", report["front_sensors"]["front_sensors"])}
    rows = ["| hypothesis | back sensors FE/model ς_z, ς_x | front sensors ς_z, ς_x | F1 | F2 | F3 | F4 | F5 |",
            "|---|---|---|---|---|---|---|---|"]

    def span(values, sensors):
        picked = [v for i, v in enumerate(values, start=1) if i in sensors]
        return "%.2f–%.2f" % (min(picked), max(picked))

    for h in report["hole_budget"]["hypotheses"]:
        ratio = h["amplitude_ratio"]["sliding"]
        every = set(range(1, len(ratio["z"]) + 1))
        back = every - front
        cells = ["`%s`: %s" % (h["name"], cell(h["what"])),
                 "%s, %s" % (span(ratio["z"], back), span(ratio["x"], back)),
                 "%s, %s" % (span(ratio["z"], front), span(ratio["x"], front))]
        cells += ["yes" if h["facts"][f]["met"] else "no" for f in ("F1", "F2", "F3", "F4", "F5")]
        rows.append("| " + " | ".join(cells) + " |")
    for s in report["hole_budget"]["skipped"]:
        rows.append("| `%s`: skipped: %s | – | – | – | – | – | – | – |" % (s["name"], cell(s["why"])))
    return rows


def levels(run):
    """report.json chain_study: the headline quantities on each mesh level of the error bars (coarse to
    fine)."""
    rows = ["| scale | DOFs | k_central | k_lsq_line | contact radius | p0 | δ | peak hole signal |",
            "|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for i, level in enumerate(run["report"]["chain_study"]["levels"]):
        v = level["values"]
        unit = (lambda u: " " + u) if i == 0 else (lambda u: "")
        rows.append("| {:g} | {:,} | {:.4f} | {:.4f} | {:.4f}{} | {:.2f}{} | {:.3f}{} | {:.4f}{} |".format(
            level["scale"], level["dofs"], v["k_central"], v["k_lsq_line"], v["contact_radius"], unit("mm"),
            1e3 * v["contact_p0"], unit("kPa"), 1e3 * v["indentation"], unit("µm"), 1e3 * v["hole_signal"],
            unit("kPa")))
    return rows


def readings(run):
    """crosscheck/readings.csv: σ_z of sensors #6 and #10, at rest and sliding, under every variant of the
    paper's model (kPa)."""
    with open(os.path.join(run["dir"], "crosscheck", "readings.csv"), newline="") as f:
        table = list(csv.DictReader(f))
    value = {(r["case"], r["variant"], r["sensor"]): float(r["sigma_z_kPa"]) for r in table}
    rows = ["| variant | static #6 | static #10 | sliding #6 | sliding #10 |", "|---|---:|---:|---:|---:|"]
    for variant in dict.fromkeys(r["variant"] for r in table):
        rows.append("| %s | %s |" % (variant, " | ".join(
            "%.2f" % value[(case, variant, sensor)] for case in ("static", "sliding") for sensor in ("6", "10"))))
    return rows


def cost(run):
    """report.json: each stage's seconds in the order they run, the DOFs and the peak memory. The seconds
    and megabytes are the machine's (--check leaves them out)."""
    report = run["report"]
    wall = report["wall_s"]
    stages = [s for s in STAGE_ORDER if s in wall] + sorted(s for s in wall if s not in STAGE_ORDER)
    rows = ["| stage | seconds (the machine's) |", "|---|---:|"]
    rows += ["| %s | %.1f |" % (stage, wall[stage]) for stage in stages]
    rows += ["| %s, beside the stages (a thread or process) | %.1f |" % (stage, seconds)
             for stage, seconds in sorted(report["wall_beside_s"].items())]
    rows.append("| total: {:,} DOFs, peak {:,.0f} MB | {:.1f} |".format(report["dofs"], report["peak_rss_mb"],
                                                                   report["wall_total_s"]))
    return rows


# Per table, what --check compares of a line: the cost table's seconds and megabytes are the machine's.
def _untimed(line):
    line = re.sub(r"\| [0-9.]+ \|$", "| s |", line)
    return re.sub(r"peak [0-9,]+ MB", "peak M MB", line)


COMPARED = {"report-cost": _untimed}
TABLES = {"report-headline": headline, "report-budget": budget, "report-cost": cost, "report-levels": levels,
          "crosscheck-readings": readings}
MARK = re.compile(r"^<!-- generated: ([a-z0-9-]+) .*-->$")


def load_run(run_dir):
    path = os.path.join(run_dir, "report.json")
    try:
        with open(path) as f:
            return {"report": json.load(f), "dir": run_dir}
    except (OSError, ValueError) as e:
        sys.exit("docs_tables.py: %s: %s (give the output folder of skinfem report)" % (path, e))


def process(doc, run, check):
    with open(doc) as f:
        lines = f.read().split("\n")
    out, differs, i = [], [], 0
    while i < len(lines):
        out.append(lines[i])
        m = MARK.match(lines[i])
        i += 1
        if not m:
            continue
        name = m.group(1)
        if name not in TABLES:
            sys.exit("docs_tables.py: %s: unknown generated table '%s'; known: %s"
                     % (doc, name, ", ".join(TABLES)))
        end = "<!-- end generated: %s -->" % name
        try:
            stop = lines.index(end, i)
        except ValueError:
            sys.exit("docs_tables.py: %s: table '%s' has no line '%s'" % (doc, name, end))
        new = TABLES[name](run)
        # Checked, the machine's seconds aside; rewritten, as the run has them.
        comparable = COMPARED.get(name, lambda line: line) if check else (lambda line: line)
        if [comparable(l) for l in lines[i:stop]] != [comparable(l) for l in new]:
            differs.append(name)
        out += new
        i = stop
    if not check and differs:
        with open(doc + ".tmp", "w") as f:
            f.write("\n".join(out))
        os.replace(doc + ".tmp", doc)
    return differs


def main(argv):
    if len(argv) not in (2, 3) or (len(argv) == 3 and argv[2] != "--check"):
        sys.exit(__doc__)
    run = load_run(argv[1])
    check = len(argv) == 3
    docs = os.path.join(SOURCE, "docs")
    found, stale = 0, []
    for name in sorted(os.listdir(docs)):
        if name.endswith(".md"):
            path = os.path.join(docs, name)
            with open(path) as f:
                found += sum(1 for l in f if MARK.match(l.rstrip("\n")))
            stale += ["docs/%s: %s" % (name, t) for t in process(path, run, check)]
    if found == 0:
        sys.exit("docs_tables.py: no generated table under docs/")
    if check and stale:
        print("docs_tables.py: these tables differ from %s (regenerate: scripts/docs_tables.py %s):\n  %s"
              % (argv[1], argv[1], "\n  ".join(stale)))
        return 1
    verb = "checked" if check else "regenerated %d of" % len(stale)
    print("docs_tables.py: %s %d generated tables against %s" % (verb, found, argv[1]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
