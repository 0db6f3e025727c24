#!/usr/bin/env bash
# skinfem sweep on Snakemake (issue 31): a 2 x 2 kfit sweep is killed after its first member and resumed with
# 2 cores; only the missing members run again, a third sweep runs none, and the gathered table equals every
# member's own kfit.json. A member that fails at run time does not stop the others and its error is in the
# table. The same sweep through a Snakemake profile (a stand-in cluster) gives the same table. Bad specs are in
# tests/app/bad_input.sh.
#   tests/app/sweep.sh SKINFEM [--profile]
set -euo pipefail
skinfem=$(realpath "$1")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cat >base.json <<'JSON'
{"geometry": {"type": "flat", "h": 3.0, "half_width": 20.0},
 "material": {"E": 3.0, "nu": 0.5},
 "sensors": {"positions": [[0.0, 0.0]], "disc_diameter": 0.2},
 "mesh": {"h_min": 0.4, "growth": 1.5, "h_max": 3.0},
 "calibration": {"punch_diameter": 0.5, "spacing": 0.1}}
JSON
cat >spec.json <<'JSON'
{"scene": "base.json", "command": "kfit", "options": {"path": "meridian"},
 "axes": [{"pointer": "/material/nu", "values": [0.45, 0.5]},
          {"pointer": "/calibration/punch_diameter", "range": {"from": 0.4, "to": 0.5, "count": 2}}]}
JSON
fail() { echo "FAIL: $*"; exit 1; }
statuses() { find D/members -name status.json 2>/dev/null | sort; }

# 1. Killed (SIGTERM to its process group, as a scheduler or a closed terminal does) after the first member.
setsid "$skinfem" sweep spec.json --out D --cores 2 >run1.log 2>&1 &
pid=$!
# Snakemake's "1 of 6 steps" line: the first member is done and registered (a status written but not yet
# registered is removed as incomplete by the shutdown).
for _ in $(seq 1 6000); do
  grep -q "^1 of 6 steps" run1.log && break
  kill -0 $pid 2>/dev/null || fail "the sweep ended before its first member finished: $(tail -3 run1.log)"
  sleep 0.05
done
kill -TERM -- -$pid
rc=0
wait $pid || rc=$?
# skinfem passes the signal to Snakemake and returns only after Snakemake has ended (its members stopped,
# their unfinished outputs removed): the statuses counted here are final, and the run resumes at once.
[ "$rc" -eq 143 ] || fail "the killed sweep exited with $rc, want 143 (128 + SIGTERM): $(tail -3 run1.log)"
grep -q "stopped by signal 15 .* members done, results not gathered; the same command resumes" run1.log ||
  fail "the killed sweep did not say what it left: $(tail -2 run1.log)"
# Snakemake and its jobs run in D (--directory): none may be left.
for p in /proc/[0-9]*; do
  [ "$(readlink "$p/cwd" 2>/dev/null)" != "$tmp/D" ] || fail "process ${p#/proc/} of the killed sweep still runs"
done
first=$(statuses)
n_first=$(echo "$first" | wc -l)
[ -n "$first" ] && [ "$n_first" -lt 4 ] || fail "after the kill $n_first of 4 members have a status (want 1 to 3)"
[ ! -e D/results.csv ] || fail "results.csv written by a killed sweep"
for f in $first; do cp "$f" "$f.before"; done

# 2. Resumed with 2 cores: the missing members run, the finished ones do not.
"$skinfem" sweep spec.json --out D --cores 2 >run2.log 2>&1 || fail "resume: $(tail -3 run2.log)"
grep -q "4 members .*, $n_first already done" run2.log || fail "resume: $(head -1 run2.log)"
ran=$(grep -c "^rule member:" run2.log)
[ "$ran" -eq $((4 - n_first)) ] || fail "the resume ran $ran members, want the $((4 - n_first)) missing"
for f in $first; do cmp -s "$f" "$f.before" || fail "$f was run again"; done
[ "$(statuses | wc -l)" -eq 4 ] || fail "after the resume: $(statuses | wc -l) statuses"

# 3. Nothing changed: nothing runs.
"$skinfem" sweep spec.json --out D --cores 2 >run3.log 2>&1 || fail "third run: $(tail -3 run3.log)"
[ "$(grep -c '^rule member:' run3.log)" -eq 0 ] || fail "the third sweep ran members again"

# 4. The gathered table against the members' own files.
/usr/bin/python3 - <<'PY' || exit 1
import csv, json
rows = list(csv.DictReader(open("D/results.csv")))
manifest = json.load(open("D/manifest.json"))
assert len(rows) == 4, len(rows)
seen = set()
for row, m in zip(rows, manifest["members"]):
    assert row["id"] == m["id"] and row["exit_code"] == "0", row
    scene = json.load(open("D/scenes/%s.json" % m["id"]))
    nu, d = scene["material"]["nu"], scene["calibration"]["punch_diameter"]
    assert float(row["material.nu"]) == nu and float(row["calibration.punch_diameter_mm"]) == d, row
    seen.add((nu, d))
    k = json.load(open("D/members/%s/out/kfit.json" % m["id"]))
    assert k["nu"] == nu and k["punch_diameter_mm"] == d, (k["nu"], k["punch_diameter_mm"])
    for key in ("k_central", "k_lsq_line", "k_central_exact", "k_lsq_line_exact", "dofs", "h_mm"):
        assert float(row[key]) == k[key], (key, row[key], k[key])
    for c in ("zz", "zx", "xz", "xx"):
        assert float(row["components.%s.k" % c]) == k["components"][c]["k"], c
assert seen == {(0.45, 0.4), (0.45, 0.5), (0.5, 0.4), (0.5, 0.5)}, seen
import h5py
with h5py.File("D/results.h5") as h5:
    for m in manifest["members"]:
        k = json.load(open("D/members/%s/out/kfit.json" % m["id"]))
        got = h5["members/%s/sensors.k_central" % m["id"]][()]
        assert list(got) == [s["k_central"] for s in k["sensors"]], (list(got), k["sensors"])
print("gathered table: 4 members equal their kfit.json")
PY
for axis in material.nu calibration.punch_diameter_mm; do
  [ -s "D/plots/$axis.png" ] || fail "no plot for $axis"
done

# 5. A member that fails at run time (the meridian path refuses a layer whose side is within 2.5 h of the
# scan) is a row with its exit code and error; the other member and the gather go on.
cat >failing.json <<'JSON'
{"scene": "base.json", "command": "kfit", "options": {"path": "meridian"},
 "axes": [{"pointer": "/geometry/half_width", "values": [8.0, 20.0]}]}
JSON
"$skinfem" sweep failing.json --out F --cores 2 >failing.log 2>&1 || fail "a failed member stopped the sweep: $(tail -3 failing.log)"
/usr/bin/python3 - <<'PY' || exit 1
import csv
rows = {float(r["geometry.half_width_mm"]): r for r in csv.DictReader(open("F/results.csv"))}
assert rows[8.0]["exit_code"] == "2" and "meridian (axisymmetric) path does not apply" in rows[8.0]["error"], rows[8.0]
assert rows[20.0]["exit_code"] == "0" and rows[20.0]["error"] == "" and float(rows[20.0]["k_central"]) > 1, rows[20.0]
print("failed member: in the table with its error; the other ran")
PY

# 6. Zipped axes and ranges by step, written only (--dry-run).
cat >zip.json <<'JSON'
{"scene": "base.json", "command": "green", "combine": "zip",
 "axes": [{"pointer": "/material/nu", "range": {"from": 0.4, "to": 0.5, "step": 0.05}},
          {"pointer": "/geometry/h", "values": [2.5, 3.0, 3.5]}]}
JSON
"$skinfem" sweep zip.json --out Z --dry-run >zip.log
grep -q "3 members of \`skinfem green\` (zip 3 x 3), 0 already done" zip.log || fail "zip: $(cat zip.log)"
[ "$(ls Z/scenes | wc -l)" -eq 3 ] && [ ! -e Z/members ] || fail "zip: the dry run ran something"
# 6b. A Snakemake that does not end after the signal (it can deadlock in its own handler) is killed 30 s
# later with its group, and its lock removed so that the same command resumes: a stand-in that ignores
# SIGTERM, on PATH before Debian's, with a lock left in place.
mkdir -p stuck/bin K/.snakemake/locks
printf '#!/bin/bash\ntrap "" TERM INT HUP\nsleep 300\n' >stuck/bin/snakemake
chmod +x stuck/bin/snakemake
touch K/.snakemake/locks/0.input.lock
PATH="$tmp/stuck/bin:$PATH" setsid "$skinfem" sweep spec.json --out K --cores 2 >stuck.log 2>&1 &
pid=$!
for _ in $(seq 1 200); do grep -q "running: snakemake" stuck.log && break; sleep 0.05; done
sleep 0.5
kill -TERM -- -$pid
rc=0
wait $pid || rc=$?
[ "$rc" -eq 143 ] || fail "the stuck sweep exited with $rc, want 143: $(tail -2 stuck.log)"
grep -q "after Snakemake was killed (it had not ended 30 s after the signal)" stuck.log ||
  fail "the stuck sweep did not say it killed Snakemake: $(tail -1 stuck.log)"
[ ! -e K/.snakemake/locks ] || fail "the killed Snakemake's lock was left"
! pgrep -f "$tmp/stuck/bin/snakemake" >/dev/null || fail "the stuck Snakemake still runs"
# 7. The cluster route without a cluster (with --profile; Release only: it is Snakemake's route, not our C++,
# and its polling makes it 30 s): the same sweep through a Snakemake profile whose submit command is bash
# (each job script runs where it is submitted) gives the same table as the local run.
if [ "${2:-}" = --profile ]; then
mkdir profile
printf 'cluster: "bash"\njobs: 2\nlatency-wait: 5\nkeep-going: true\nrerun-incomplete: true\n' >profile/config.yaml
"$skinfem" sweep spec.json --out P --profile profile >profile.log 2>&1 || fail "profile: $(tail -3 profile.log)"
/usr/bin/python3 - <<'PY' || exit 1
import csv
local = {r["id"]: r for r in csv.DictReader(open("D/results.csv"))}
cluster = {r["id"]: r for r in csv.DictReader(open("P/results.csv"))}
assert local.keys() == cluster.keys(), (local.keys(), cluster.keys())
for i, row in cluster.items():
    for key in ("k_central", "k_lsq_line", "k_central_exact", "dofs"):
        assert row[key] == local[i][key], (i, key, row[key], local[i][key])
print("profile: the same 4 members and k as the local run")
PY
fi
echo "sweep: kill after $n_first member(s), resume ran $ran, third run none; all checks passed"
