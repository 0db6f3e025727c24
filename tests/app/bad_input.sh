#!/usr/bin/env bash
# The skinfem command on bad input: one line naming the field, the value and what is allowed,
# exit code 2, and no output directory written.
set -u
skinfem=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
check() {  # name, expected substring, command...
  local name=$1 expect=$2
  shift 2
  "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local code=$?
  if [ $code -ne 2 ]; then echo "FAIL $name: exit $code, expected 2"; fail=1; fi
  if ! grep -q -- "$expect" "$tmp/stderr"; then echo "FAIL $name: stderr lacks '$expect':"; cat "$tmp/stderr"; fail=1; fi
  if [ "$(grep -vc '^\[skinfem\]' "$tmp/stderr")" -ne 1 ]; then echo "FAIL $name: not one line"; cat "$tmp/stderr"; fail=1; fi
  if [ -e "$tmp/out" ]; then echo "FAIL $name: output written"; fail=1; fi
}
echo '{"geometry": {"type": "flat", "h": 3, "half_width": 5}, "material": {"E": 3, "nu": 0.7},
       "sensors": {"positions": [[0, 0]], "disc_diameter": 0.2}, "mesh": {"h_min": 0.5, "growth": 1.5, "h_max": 2}}' >"$tmp/nu.json"
check bad_nu "material.nu = 0.7" "$skinfem" mesh "$tmp/nu.json" --out "$tmp/out"
sed 's/"E": 3/"E": 3, "colour": 1/; s/0.7/0.5/' "$tmp/nu.json" >"$tmp/key.json"
check unknown_key "material.colour" "$skinfem" mesh "$tmp/key.json" --out "$tmp/out"
sed 's/0.7/0.5/' "$tmp/nu.json" >"$tmp/noload.json"
check no_load "loads" "$skinfem" solve "$tmp/noload.json" --out "$tmp/out"
check missing_file "no.json" "$skinfem" mesh "$tmp/no.json" --out "$tmp/out"
check bad_solver "--solver" "$skinfem" solve "$tmp/noload.json" --solver lu --out "$tmp/out"
# The contact section is read with the scene, before any subcommand runs.
echo '{"geometry": {"type": "flat", "h": 3, "half_width": 5}, "material": {"E": 3, "nu": 0.5},
       "sensors": {"positions": [[0, 0]], "disc_diameter": 0.2}, "mesh": {"h_min": 0.5, "growth": 1.5, "h_max": 2},
       "contact": {"indenter": {"type": "plane"}, "force": 1}}' >"$tmp/plane.json"
check plane_on_flat 'contact.indenter.type = "plane": a plane on a flat layer' "$skinfem" mesh "$tmp/plane.json" --out "$tmp/out"
sed 's/{"type": "plane"}/{"type": "sphere", "R": 50, "center": [0, 0]}, "holes": [{"center": [4.9, 0], "diameter": 0.5}]/' \
  "$tmp/plane.json" >"$tmp/hole.json"
check hole_off_skin 'contact.holes.0. = .*hole 1 of 1.*off the skin' "$skinfem" mesh "$tmp/hole.json" --out "$tmp/out"
sed 's/{"type": "plane"}/{"type": "sphere", "R": 50, "center": [0, 0]}/' "$tmp/plane.json" >"$tmp/zone.json"
check zone_at_side 'contact.force = 1: .*would reach the truncated side' "$skinfem" mesh "$tmp/zone.json" --out "$tmp/out"
check unknown_subcommand "unknown subcommand 'frobnicate'; one of: mesh" "$skinfem" frobnicate "$tmp/nu.json" --out "$tmp/out"
if [ $fail -eq 0 ]; then echo "8 passed, 0 failed"; fi
exit $fail
