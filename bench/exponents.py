#!/usr/bin/python3
"""Time per stage against DOFs from skinfem_bench's JSON (--benchmark_format=json): a table per stage and
scene (DOFs, milliseconds, the minimum over repetitions) and the fitted exponent e of time ∝ DOFs^e
(least squares in log-log over the levels). Usage: bench/exponents.py bench.json"""
import json
import math
import sys
from collections import defaultdict

runs = json.load(open(sys.argv[1]))["benchmarks"]
best = defaultdict(dict)  # (stage, scene) -> dofs -> ms
for r in runs:
    if r.get("run_type") != "iteration":
        continue
    stage = r["name"].split("/")[0].removeprefix("BM_")
    scene = r.get("label", "").split(" ")[0]
    n = int(r["dofs"])
    ms = r["real_time"]
    best[(stage, scene)][n] = min(ms, best[(stage, scene)].get(n, math.inf))
print("| stage | scene | DOFs: ms | time ∝ DOFs^e |")
print("|---|---|---|---:|")
for (stage, scene), pts in best.items():
    xs = sorted(pts)
    cells = ", ".join(f"{n:,}: {pts[n]:.4g}" for n in xs)
    if len(xs) >= 2:
        lx = [math.log(n) for n in xs]
        ly = [math.log(pts[n]) for n in xs]
        mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
        e = sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)
        exp = f"{e:.2f}"
    else:
        exp = "–"
    print(f"| {stage} | {scene} | {cells} | {exp} |")
