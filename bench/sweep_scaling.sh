#!/usr/bin/env bash
# The sweep engine's cost: a 16-member kfit sweep (sweeps/k_vs_nu_and_punch.json's first four Poisson's ratios
# and punch diameters, meridian path) run from scratch with 1 core and with 2, each RUNS times (default 2).
# Prints per run the wall time, the members' own time (their status.json wall_s summed) and the engine's
# overhead per member, (wall × cores − members' time) / members (Snakemake's start, scheduling, the
# gather); then the speed-up of 2 cores over 1 from the medians.
#   bench/sweep_scaling.sh build/app/skinfem [RUNS]
set -euo pipefail
skinfem=$(realpath "$1")
runs=${2:-2}
src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/k16.json" <<JSON
{"name": "k16", "scene": "$src/scenes/flat_layer.json", "command": "kfit", "options": {"path": "meridian"},
 "axes": [{"pointer": "/material/nu", "values": [0.3, 0.35, 0.4, 0.45]},
          {"pointer": "/calibration/punch_diameter", "values": [0.1, 0.25, 0.5, 0.75]}]}
JSON
for cores in 1 2; do
  for run in $(seq 1 "$runs"); do
    rm -rf "$tmp/out"
    start=$(date +%s.%N)
    "$skinfem" sweep "$tmp/k16.json" --out "$tmp/out" --cores "$cores" >"$tmp/log" 2>&1
    end=$(date +%s.%N)
    /usr/bin/python3 - "$tmp/out" "$cores" "$start" "$end" <<'PY' | tee -a "$tmp/table"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/results.csv")))
cores, wall = int(sys.argv[2]), float(sys.argv[4]) - float(sys.argv[3])
members = sum(float(r["member_wall_s"]) for r in rows)
assert all(r["exit_code"] == "0" for r in rows)
print("cores %d: %d members, wall %.2f s, members %.2f s, overhead %.3f s per member"
      % (cores, len(rows), wall, members, (wall * cores - members) / len(rows)))
PY
  done
done
/usr/bin/python3 - "$tmp/table" <<'PY'
import re, statistics, sys
wall = {1: [], 2: []}
for line in open(sys.argv[1]):
    m = re.match(r"cores (\d): .* wall ([0-9.]+) s", line)
    wall[int(m.group(1))].append(float(m.group(2)))
print("speed-up with 2 cores: %.2f (median walls %.2f s and %.2f s)"
      % (statistics.median(wall[1]) / statistics.median(wall[2]), statistics.median(wall[1]), statistics.median(wall[2])))
PY
