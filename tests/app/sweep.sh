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
# SIGTERM to a sweep's process group; it must exit with 128 + SIGTERM. terminate PID LOG WHAT
terminate() {
  kill -TERM -- -"$1"
  local rc=0
  wait "$1" || rc=$?
  [ "$rc" -eq 143 ] || fail "$3 exited with $rc, want 143 (128 + SIGTERM): $(tail -3 "$2")"
}

# 1. Killed (SIGTERM to its process group, as a scheduler or a closed terminal does) after the first member.
setsid "$skinfem" sweep spec.json --out D --cores 2 >run1.log 2>&1 &
pid=$!
# Snakemake's "1 of 6 steps" line: the first member is done and registered (a status written but not yet
# registered is removed as incomplete by the shutdown).
for _ in $(seq 1 6000); do
  grep -q "^1 of 6 steps" D/snakemake.log 2>/dev/null && break
  kill -0 $pid 2>/dev/null || fail "the sweep ended before its first member finished: $(tail -3 run1.log)"
  sleep 0.05
done
# skinfem passes the signal to Snakemake and returns only after Snakemake has ended (its members stopped,
# their unfinished outputs removed): the statuses counted here are final, and the run resumes at once.
terminate $pid run1.log "the killed sweep"
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
ran=$(grep -c "^rule member:" D/snakemake.log)
[ "$ran" -eq $((4 - n_first)) ] || fail "the resume ran $ran members, want the $((4 - n_first)) missing"
for f in $first; do cmp -s "$f" "$f.before" || fail "$f was run again"; done
[ "$(statuses | wc -l)" -eq 4 ] || fail "after the resume: $(statuses | wc -l) statuses"

# 3. Nothing changed: nothing runs.
"$skinfem" sweep spec.json --out D --cores 2 >run3.log 2>&1 || fail "third run: $(tail -3 run3.log)"
[ "$(grep -c '^rule member:' D/snakemake.log)" -eq 0 ] || fail "the third sweep ran members again"
# What the terminal shows: the progress line and the gather's summary; Snakemake's own log is in its file.
grep -q "sweep: 4 of 4 members finished (0 failed)" run2.log || fail "no progress line: $(cat run2.log)"
grep -q "^gathered 4 members (4 ok, 0 failed)" run2.log || fail "no gather summary: $(cat run2.log)"
! grep -q "^rule member:" run2.log || fail "Snakemake's job log on the terminal: $(head -5 run2.log)"

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
    # kfit.json's nu and punch_diameter_mm repeat the axes: the axis columns stand for them.
    assert "nu" not in row and "punch_diameter_mm" not in row, [c for c in row if c in ("nu", "punch_diameter_mm")]
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
terminate $pid stuck.log "the stuck sweep"
grep -q "after Snakemake was killed (it had not ended 30 s after the signal)" stuck.log ||
  fail "the stuck sweep did not say it killed Snakemake: $(tail -1 stuck.log)"
[ ! -e K/.snakemake/locks ] || fail "the killed Snakemake's lock was left"
! pgrep -f "$tmp/stuck/bin/snakemake" >/dev/null || fail "the stuck Snakemake still runs"
# 6c. options.grid as `skinfem green --grid` checks it: a kernel grid past green's point limit is refused
# for the member, in one line, before anything is written.
cat >grid.json <<'JSON'
{"scene": "base.json", "command": "green", "options": {"grid": 0.01},
 "axes": [{"pointer": "/material/nu", "values": [0.45, 0.5]}]}
JSON
rc=0
"$skinfem" sweep grid.json --out G --dry-run >grid.log 2>&1 || rc=$?
[ "$rc" -eq 2 ] && [ "$(wc -l <grid.log)" -eq 1 ] && [ ! -e G ] &&
  grep -q "member 1 (/material/nu = 0.45): --grid = 0.01: the kernel grid .* allowed at most 1e6 points" grid.log ||
  fail "a kernel grid past green's limit: rc $rc, $(cat grid.log)"
# 6d. One sweep per folder, none outliving skinfem (stand-in Snakemakes): a second sweep into a folder where
# one runs is refused in one line and writes nothing; a SIGKILLed skinfem's Snakemake gets SIGTERM and still
# holds the folder's lock (it inherited it); Snakemake's lock left by a killed run is removed before the next.
mkdir -p hold/bin L/.snakemake/locks
touch L/.snakemake/locks/0.input.lock
cat >hold/bin/snakemake <<'SH'
#!/bin/bash
while [ $# -gt 0 ]; do [ "$1" = --directory ] && dir=$2; shift; done
# The handler first: the test kills skinfem as soon as it sees $HOLD.locks.
trap 'if flock -n "$dir/.skinfem-sweep.lock" true; then echo free; else echo held; fi >"$HOLD.term.tmp"; mv "$HOLD.term.tmp" "$HOLD.term"; kill $child; exit 143' TERM
sleep 300 &
child=$!
if [ -e "$dir/.snakemake/locks" ]; then echo present; else echo absent; fi >"$HOLD.locks.tmp"
mv "$HOLD.locks.tmp" "$HOLD.locks"
wait
SH
chmod +x hold/bin/snakemake
HOLD="$tmp/hold" PATH="$tmp/hold/bin:$PATH" "$skinfem" sweep spec.json --out L --cores 1 >hold.log 2>&1 &
pid=$!
for _ in $(seq 1 600); do [ -e hold.locks ] && break; sleep 0.05; done
[ "$(cat hold.locks 2>/dev/null)" = absent ] || fail "Snakemake's stale lock was there when it started: $(cat hold.log)"
grep -q "removed L/.snakemake/locks, left by a Snakemake that did not end cleanly" hold.log ||
  fail "the stale lock's removal was not said: $(cat hold.log)"
cp L/manifest.json manifest.before
rc=0
"$skinfem" sweep zip.json --out L --dry-run >second.log 2>&1 || rc=$?
[ "$rc" -ne 0 ] && [ "$(wc -l <second.log)" -eq 1 ] &&
  grep -q "^skinfem: --out L: another skinfem sweep is running there" second.log ||
  fail "a second sweep into a running sweep's folder: rc $rc, $(cat second.log)"
cmp -s L/manifest.json manifest.before || fail "the second sweep rewrote the running sweep's manifest"
kill -KILL $pid
{ wait $pid; } 2>/dev/null || true
# Up to 30 s: under the sanitizers, with another test on the second core, the handler can take seconds.
for _ in $(seq 1 600); do [ -e hold.term ] && break; sleep 0.05; done
[ "$(cat hold.term 2>/dev/null)" = held ] ||
  fail "after skinfem's SIGKILL, Snakemake got no SIGTERM or did not hold the lock ($(cat hold.term 2>/dev/null))"
for _ in $(seq 1 100); do pgrep -f "$tmp/hold/bin/snakemake" >/dev/null || break; sleep 0.05; done
"$skinfem" sweep spec.json --out L --dry-run >third.log 2>&1 || fail "the folder stayed locked: $(cat third.log)"
# 6e. Members killed by a signal or out of memory (a stand-in skinfem in the manifest, on Debian's Snakemake):
# their rows say so, the gather runs, and the next sweep runs them again; a member refused for its input
# stays done.
cat >oom.json <<'JSON'
{"scene": "base.json", "command": "kfit", "options": {"path": "meridian"},
 "axes": [{"pointer": "/material/nu", "values": [0.4, 0.45, 0.48, 0.5]}]}
JSON
cat >standin.sh <<'SH'
#!/bin/bash
mkdir -p "$4"
if grep -q '"nu": 0.45' "$2"; then kill -KILL $$; fi
if grep -q '"nu": 0.48' "$2"; then echo "skinfem: MUMPS job 2 failed: INFOG(1) = -9, INFOG(2) = 4312"; exit 1; fi
if grep -q '"nu": 0.5' "$2"; then echo "skinfem: scene.json: material.nu = 0.5: refused"; exit 2; fi
echo '{"k_central": 1.5, "k_lsq_line": 1.4}' >"$4/kfit.json"
SH
chmod +x standin.sh
"$skinfem" sweep oom.json --out M --dry-run >oom1.log
snakefile=$(sed -n 's/.* --snakefile \([^ ]*\) .*/\1/p' oom1.log)
/usr/bin/python3 -c "
import json; m = json.load(open('M/manifest.json')); m['skinfem'] = '$tmp/standin.sh'
json.dump(m, open('M/manifest.json', 'w'))"
(cd M && snakemake --snakefile "$snakefile" --cores 2 --keep-going >../oom2.log 2>&1) ||
  fail "Snakemake failed on a killed member: $(tail -3 oom2.log)"
/usr/bin/python3 - <<'PY' || exit 1
import csv, json
rows = {r["material.nu"]: r for r in csv.DictReader(open("M/results.csv"))}
assert rows["0.45"]["exit_code"] == "-9" and rows["0.45"]["error"] == "killed by signal 9 (SIGKILL)", rows["0.45"]
assert rows["0.48"]["exit_code"] == "1" and "INFOG(1) = -9" in rows["0.48"]["error"], rows["0.48"]
assert rows["0.5"]["exit_code"] == "2" and rows["0.4"]["k_central"] == "1.5", rows
retry = {r["material.nu"]: json.load(open("M/members/%s/status.json" % r["id"]))["retry"] for r in rows.values()}
assert retry == {"0.4": False, "0.45": True, "0.48": True, "0.5": False}, retry
print("killed and out-of-memory members: in the table, marked to retry")
PY
mkdir -p list/bin
printf '#!/bin/bash\nls M/members/*/status.json >listed.txt\n' >list/bin/snakemake
chmod +x list/bin/snakemake
PATH="$tmp/list/bin:$PATH" "$skinfem" sweep oom.json --out M >oom3.log 2>&1 || fail "retry: $(tail -2 oom3.log)"
grep -q "4 members .*, 2 already done, 2 to retry;" oom3.log || fail "retry: $(head -1 oom3.log)"
[ "$(wc -l <listed.txt)" -eq 2 ] || fail "Snakemake started with $(wc -l <listed.txt) statuses, want the 2 not to retry"
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
