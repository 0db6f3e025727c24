#!/usr/bin/env bash
# The bad-input catalogue: each case goes through the skinfem command line and must give one line on stderr
# naming the field (and value) and what is allowed, exit code 2, no crash, no hang (each run is given 60 s),
# and nothing written to --out. Base scene: a 16 mm wide, 3 mm flat layer, one 0.5 mm punch, 1 N.
set -u
skinfem=$(realpath "$1")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0 passed=0
check() {  # name, expected substring (grep -E), command...
  local name=$1 expect=$2
  shift 2
  timeout 60 "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local code=$? bad=0
  if [ $code -ne 2 ]; then echo "FAIL $name: exit $code, expected 2"; bad=1; fi
  if ! grep -Eq -- "$expect" "$tmp/stderr"; then echo "FAIL $name: stderr lacks '$expect':"; cat "$tmp/stderr"; bad=1; fi
  if [ "$(grep -vc '^\[skinfem\]' "$tmp/stderr")" -ne 1 ]; then echo "FAIL $name: not one line"; cat "$tmp/stderr"; bad=1; fi
  if [ -e "$tmp/out" ]; then echo "FAIL $name: output written"; rm -rf "$tmp/out"; bad=1; fi
  if [ $bad -eq 0 ]; then passed=$((passed + 1)); else fail=$((fail + 1)); fi
}
cat >"$tmp/base.json" <<'JSON'
{"geometry": {"type": "flat", "h": 3.0, "half_width": 8.0},
 "material": {"E": 3.0, "nu": 0.5},
 "sensors": {"positions": [[0.0, 0.0]], "disc_diameter": 0.2},
 "mesh": {"h_min": 0.4, "growth": 1.5, "h_max": 3.0},
 "loads": {"punches": [{"center": [0.0, 0.0], "diameter": 0.5, "force": 1.0}]},
 "calibration": {"punch_diameter": 0.5, "spacing": 0.1}}
JSON
# variant NAME PYTHON: the base scene as d, changed by the Python statement, written to $tmp/NAME.json.
variant() {
  /usr/bin/python3 - "$tmp/base.json" "$tmp/$1.json" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
exec(sys.argv[3])
open(sys.argv[2], "w").write(json.dumps(d))
PY
}
bad() {  # NAME PYTHON EXPECT [subcommand]: a scene variant through `skinfem SUB scene --out`
  variant "$1" "$2"
  check "$1" "$3" "$skinfem" "${4:-solve}" "$tmp/$1.json" --out "$tmp/out"
}
punch='d["loads"]["punches"][0]'

# The file itself.
printf '{"geometry": ' >"$tmp/truncated.json"
check truncated_json 'truncated.json: .*(syntax|parse|unexpected|end of input)' "$skinfem" mesh "$tmp/truncated.json" --out "$tmp/out"
: >"$tmp/empty.json"
check empty_file 'empty.json' "$skinfem" mesh "$tmp/empty.json" --out "$tmp/out"
check missing_file 'no.json: cannot read scene file' "$skinfem" mesh "$tmp/no.json" --out "$tmp/out"
mkdir "$tmp/dir.json"
check directory 'dir.json: cannot read scene file: is a directory' "$skinfem" mesh "$tmp/dir.json" --out "$tmp/out"
echo '[1, 2]' >"$tmp/array.json"
check top_level_array '\(top level\) = .*must be an object' "$skinfem" mesh "$tmp/array.json" --out "$tmp/out"
sed 's/"nu": 0.5/"nu": NaN/' "$tmp/base.json" >"$tmp/nan.json"
check nan_literal 'nan.json: .*(syntax|parse|invalid)' "$skinfem" mesh "$tmp/nan.json" --out "$tmp/out"
sed 's/"nu": 0.5/"nu": 0.5, "nu": 0.4/' "$tmp/base.json" >"$tmp/dupkey.json"
check duplicate_key 'material.nu.*duplicate' "$skinfem" mesh "$tmp/dupkey.json" --out "$tmp/out"
# 600 KB of nesting: refused at a depth limit, not by running out of memory (issue 57).
/usr/bin/python3 -c 'import sys; n = 100000; sys.stdout.write("{\"geometry\": " + "[" * n + "]" * n + "}")' >"$tmp/deep.json"
check deep_nesting 'deep.json: geometry(\[0\])+: nested deeper than 32 levels' "$skinfem" mesh "$tmp/deep.json" --out "$tmp/out"

# Unknown keys at every level.
bad unknown_top 'd["colour"] = 1' 'colour: unknown key'
bad unknown_geometry 'd["geometry"]["radius"] = 1' 'geometry.radius: unknown key'
bad unknown_material 'd["material"]["colour"] = 1' 'material.colour: unknown key'
bad unknown_sensors 'd["sensors"]["pitch"] = 1' 'sensors.pitch: unknown key'
bad unknown_mesh 'd["mesh"]["order"] = 2' 'mesh.order: unknown key'
bad symmetry_word 'd["symmetry"] = "mirror"' 'symmetry = "mirror": must be "auto" or "none"'
bad unknown_punch "$punch[\"depth\"] = 1" 'loads.punches\[0\].depth: unknown key'
bad unknown_calibration 'd["calibration"]["k"] = 1.48' 'calibration.k: unknown key'
bad unknown_contact 'd["contact"] = {"indenter": {"type": "sphere", "R": 50, "center": [0, 0]}, "force": 0.1, "glue": 1}' 'contact.glue: unknown key'

# Types and ranges.
bad geometry_type 'd["geometry"]["type"] = "torus"' 'geometry.type = "torus": must be one of'
bad h_string 'd["geometry"]["h"] = "3"' 'geometry.h = "3": must be a length'
bad h_huge 'd["geometry"]["h"] = 1e308' 'geometry.h = 1e\+308: must be a length in \(0, 10000\] mm'
bad half_width_zero 'd["geometry"]["half_width"] = 0' 'geometry.half_width = 0: must be a length'
bad E_negative 'd["material"]["E"] = -3' 'material.E = -3: must be a Young.s modulus in \(0, 1e12\] MPa'
bad E_huge 'd["material"]["E"] = 1e200' 'material.E = 1e\+200: must be a Young.s modulus'
bad nu_high 'd["material"]["nu"] = 0.7' 'material.nu = 0.7: must be a number in \[0, 0.5\]'
bad nu_negative 'd["material"]["nu"] = -0.1' 'material.nu = -0.1: must be a number in \[0, 0.5\]'
bad model_unknown 'd["material"]["model"] = "mooney"' 'material.model = "mooney": must be one of "linear", "neo_hookean"'
bad model_neo_hookean_compressible 'd["material"].update(model="neo_hookean", nu=0.45)' 'material.nu = 0.45: must be 0.5 with "model": "neo_hookean"'
bad model_neo_hookean_punch_force 'd["material"]["model"] = "neo_hookean"' 'loads.punches\[0\].force: with material.model "neo_hookean" a punch is driven by its "displacement"'
bad model_neo_hookean_kfit 'd["material"]["model"] = "neo_hookean"' 'material.model = "neo_hookean": kfit takes "linear" only \(the finite-strain skin runs in solve, green, contact, defect and report\)' kfit
bad cap_h_ge_R 'd["geometry"] = {"type": "cap", "R": 3, "h": 3, "apex": [0, 0], "truncation_radius": 2}' 'geometry.h = 3: must be a number in \(0, R\)'
bad cap_truncation 'd["geometry"] = {"type": "cap", "R": 129.7, "h": 3.04, "apex": [0, 0], "truncation_radius": 40}' 'geometry.truncation_radius = 40: .*where the cap thins to zero'
bad no_sensors 'd["sensors"]["positions"] = []' 'sensors.positions = \[\]: must be a non-empty array'
bad sensor_off_layer 'd["sensors"]["positions"] = [[7.95, 0]]' 'sensors.positions\[0\] = .*must lie inside the flat layer'
bad sensor_duplicate 'd["sensors"]["positions"] = [[0, 0], [1, 0], [0, 0]]' 'sensors.positions\[2\] = .*same place as sensors.positions\[0\]'
bad disc_zero 'd["sensors"]["disc_diameter"] = 0' 'sensors.disc_diameter = 0: must be a length'
bad sensor_model 'd["sensors"]["model"] = "pillar"' 'sensors.model = "pillar": must be "disc" or "post"'
bad post_for_disc 'd["sensors"]["post"] = {"height": 0.4}' 'sensors.post = .*is only for "model": "post"'
bad post_disc_diameter 'd["sensors"]["model"] = "post"' 'sensors.disc_diameter = 0.2: is only for "model": "disc"'
bad post_diameter_zero 'd["sensors"] = {"positions": [[0.0, 0.0]], "model": "post", "post": {"diameter": 0}}' 'sensors.post.diameter = 0: must be a length'
bad post_height_negative 'd["sensors"] = {"positions": [[0.0, 0.0]], "model": "post", "post": {"height": -0.1}}' 'sensors.post.height = -0.1: must be a length'
bad post_too_tall 'd["sensors"] = {"positions": [[0.0, 0.0]], "model": "post", "post": {"height": 2.9}}' 'sensors.post.height = 2.9: must be below 0.9 x the skin.s thickness over the post at sensors.positions\[0\] \(2.7 mm\)'
bad post_springs 'd["sensors"] = {"positions": [[0.0, 0.0]], "model": "post", "post": {"support": "springs"}}' 'sensors.post.support = "springs": must be "rigid" or the membrane'"'"'s springs'
bad post_spring_negative 'd["sensors"] = {"positions": [[0.0, 0.0]], "model": "post", "post": {"support": {"k_normal": -1, "k_tangential": 100, "k_tilt": 1}}}' 'sensors.post.support.k_normal = -1: must be a stiffness in \[1e-06, 1e\+09\] N/mm'
bad post_spring_missing 'd["sensors"] = {"positions": [[0.0, 0.0]], "model": "post", "post": {"support": {"k_normal": 100, "k_tangential": 100}}}' 'sensors.post.support.k_tilt'
bad post_spring_punch_force 'd["sensors"] = {"positions": [[0.0, 0.0]], "model": "post", "post": {"support": {"k_normal": 8, "k_tangential": 3, "k_tilt": 0.05}}}' 'loads.punches\[0\].force = 1.0: cannot drive a punch with posts on membrane springs'
bad post_unknown_key 'd["sensors"] = {"positions": [[0.0, 0.0]], "model": "post", "post": {"width": 0.2}}' 'sensors.post.width'
bad posts_overlap 'd["sensors"] = {"positions": [[0.0, 0.0], [0.25, 0.0]], "model": "post"}' 'sensors.positions\[1\] = .*post closer than 1.5 post diameters \(0.3 mm\) to sensors.positions\[0\]'
bad post_off_layer 'd["sensors"] = {"positions": [[7.95, 0.0]], "model": "post"}' 'sensors.positions\[0\] = .*post \(diameter 0.2\) must lie inside the flat layer'
bad h_min_above_h_max 'd["mesh"]["h_min"] = 4' 'mesh.h_max = 3.0: must be a number >= mesh.h_min = 4'
bad sensor_h_above_h_min 'd["mesh"]["sensor_h"] = 0.5' 'mesh.sensor_h = 0.5: must be a number in \(0, mesh.h_min = 0.4\]'
bad growth_one 'd["mesh"]["growth"] = 1' 'mesh.growth = 1: must be a number > 1'
bad h_min_negative 'd["mesh"]["h_min"] = -0.4' 'mesh.h_min = -0.4: must be a length'
bad contact_force_subnormal 'd["contact"] = {"indenter": {"type": "sphere", "R": 50, "center": [0, 0]}, "force": 5e-324}' 'contact.force = 5e-324: must be a force in \[1e-09, 1e\+06\] N' mesh
bad punch_both "$punch[\"displacement\"] = 0.01" 'loads.punches\[0\] = .*exactly one of "force" \(N\) or "displacement"'
bad punch_neither "del $punch[\"force\"]" 'loads.punches\[0\] = .*exactly one of "force"'
bad punch_force_huge "$punch[\"force\"] = 1e200" 'loads.punches\[0\].force = 1e\+200: must be a force in \[1e-09, 1e\+06\] N'
bad punch_at_edge "$punch[\"center\"] = [7.5, 0]; $punch[\"diameter\"] = 1" 'loads.punches\[0\].center = \[7.5,0.0\]: the load disc .* must lie on the skin'
bad punch_tiny "$punch[\"diameter\"] = 1e-9" 'loads.punches\[0\].diameter = 1e-09: must be >= 1e-6 x the skin.s width'
bad punch_wider_than_layer "$punch[\"diameter\"] = 100" 'loads.punches\[0\].center = .*must lie on the skin'
bad punch_on_corner "$punch[\"center\"] = [8, 8]" 'loads.punches\[0\].center = \[8.0,8.0\]: the load disc'
bad punches_overlap 'd["loads"]["punches"].append({"center": [0.3, 0], "diameter": 0.5, "force": 1})' 'punches 1 and 2 overlap or touch'
bad punches_identical 'd["loads"]["punches"].append(dict(d["loads"]["punches"][0]))' 'punches 1 and 2 overlap or touch'
bad punch_too_deep "del $punch[\"force\"]; $punch[\"displacement\"] = 3.5" 'loads.punches\[0\].displacement = 3.5: must be < the skin.s thickness 3 mm'
bad patch_direction_zero 'd["loads"]["patches"] = [{"center": [2, 0], "diameter": 0.5, "direction": [0, 0, 0], "force": 1}]' 'loads.patches\[0\].direction = \[0,0,0\]: must be a non-zero vector'
bad spacing_tiny 'd["calibration"]["spacing"] = 1e-9' 'calibration.spacing = 1e-09: must be >= 2 x scan half-width' kfit
bad no_loads 'del d["loads"]' 'loads = \{\}: solve needs at least one punch or patch'
bad plane_on_flat 'd["contact"] = {"indenter": {"type": "plane"}, "force": 1}' 'contact.indenter.type = "plane": a plane on a flat layer' mesh
bad hole_off_skin 'd["contact"] = {"indenter": {"type": "sphere", "R": 50, "center": [0, 0]}, "force": 0.1, "holes": [{"center": [7.9, 0], "diameter": 0.5}]}' 'contact.holes.0. = .*hole 1 of 1.*off the skin' mesh
bad zone_at_side 'd["contact"] = {"indenter": {"type": "sphere", "R": 50, "center": [0, 0]}, "force": 1}; d["geometry"]["half_width"] = 5; d["loads"] = {}' 'contact.force = 1: .*would reach the truncated side' mesh

# Resource guards: refused from the size estimate, before meshing (issue 11's probe scenes).
bad huge_mesh 'd["mesh"]["h_min"] = 0.001' 'the mesh would have at least .* tetrahedra .* GB available; coarsen mesh.h_min'
bad thin_layer_fine 'd["geometry"] = {"type": "flat", "h": 0.1, "half_width": 20}; d["mesh"]["h_min"] = 0.05; d["loads"]["punches"][0]["displacement"] = 0.01; del d["loads"]["punches"][0]["force"]' 'the mesh would have .* tetrahedra .* GB available'
variant max_dofs 'pass'
check max_dofs 'above max_dofs \(--max-dofs\) = 1e\+03; coarsen mesh.h_min' "$skinfem" solve "$tmp/max_dofs.json" --max-dofs 1000 --out "$tmp/out"

# Imported surfaces.
printf 'solid x\n garbage\nendsolid\n' >"$tmp/garbage.stl"
variant stl_garbage 'd["geometry"] = {"type": "surface", "path": "garbage.stl"}; d["loads"] = {}'
check stl_garbage 'garbage.stl' "$skinfem" mesh "$tmp/stl_garbage.json" --out "$tmp/out"
/usr/bin/python3 "$(dirname "$0")/box_stl.py" "$tmp/open.stl" --open
variant stl_open 'd["geometry"] = {"type": "surface", "path": "open.stl"}; d["loads"] = {}'
check stl_open 'open.stl: surface is not watertight' "$skinfem" mesh "$tmp/stl_open.json" --out "$tmp/out"
/usr/bin/python3 "$(dirname "$0")/box_stl.py" "$tmp/crossing.stl" --overlap
variant stl_self_intersecting 'd["geometry"] = {"type": "surface", "path": "crossing.stl"}; d["loads"] = {}'
check stl_self_intersecting 'crossing.stl: surface intersects itself near \(' "$skinfem" mesh "$tmp/stl_self_intersecting.json" --out "$tmp/out"
/usr/bin/python3 -c 'import random, sys; random.seed(1); open(sys.argv[1], "wb").write(bytes(random.randrange(256) for _ in range(300)))' "$tmp/binary.stl"
variant stl_binary_garbage 'd["geometry"] = {"type": "surface", "path": "binary.stl"}; d["loads"] = {}'
check stl_binary_garbage 'binary.stl: a binary STL declaring [0-9]+ faces, 84 \+ 50 × [0-9]+ = [0-9]+ bytes; the file has 300' "$skinfem" mesh "$tmp/stl_binary_garbage.json" --out "$tmp/out"
# Imported skins have no size estimate, but a floor: their volume at mesh.h_max (a box scaled 1e30, and a
# 480 × 480 × 90 mm one, were meshed until killed at 9.8 and 7.1 GB).
for scale in 1e30 30; do
  /usr/bin/python3 "$(dirname "$0")/box_stl.py" "$tmp/box_$scale.stl" --scale $scale
  variant stl_box_$scale "d[\"geometry\"] = {\"type\": \"surface\", \"path\": \"box_$scale.stl\"}; d[\"loads\"] = {}"
  check stl_box_$scale "box_$scale.stl: the surface encloses .* mm³, at least .* tetrahedra at mesh.h_max = 3 mm, above the" "$skinfem" mesh "$tmp/stl_box_$scale.json" --out "$tmp/out"
done
printf 'OFF\n2000000000 12 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$tmp/huge_header.off"
variant off_huge_header 'd["geometry"] = {"type": "surface", "path": "huge_header.off"}; d["loads"] = {}'
check off_huge_header 'huge_header.off: the OFF header declares 2000000000 vertices and 12 faces, more than its [0-9]+ bytes can hold' "$skinfem" mesh "$tmp/off_huge_header.json" --out "$tmp/out"
for bad_value in nan inf; do
  /usr/bin/python3 "$(dirname "$0")/box_stl.py" "$tmp/$bad_value.stl"
  sed -i "0,/vertex -8 /s//vertex $bad_value /" "$tmp/$bad_value.stl"
  variant stl_${bad_value}_vertex "d[\"geometry\"] = {\"type\": \"surface\", \"path\": \"$bad_value.stl\"}; d[\"loads\"] = {}"
  check stl_${bad_value}_vertex "$bad_value.stl: line [0-9]+ holds \"$bad_value\": every coordinate must be a finite number" "$skinfem" mesh "$tmp/stl_${bad_value}_vertex.json" --out "$tmp/out"
done
/usr/bin/python3 "$(dirname "$0")/box_stl.py" "$tmp/box.stl"
variant stl_sensor_off 'd["geometry"] = {"type": "surface", "path": "box.stl"}; d["sensors"]["positions"] = [[7.95, 0]]; d["loads"] = {"patches": [{"center": [0, 0], "diameter": 0.5, "direction": [0, 0, -1], "force": 1}]}'
check stl_sensor_off 'sensor 1 at \(7.95.*not entirely on the skin' "$skinfem" solve "$tmp/stl_sensor_off.json" --out "$tmp/out"
/usr/bin/python3 "$(dirname "$0")/box_stl.py" "$tmp/edge.off" --edge
variant off_non_manifold 'd["geometry"] = {"type": "surface", "path": "edge.off"}; d["loads"] = {}'
check off_non_manifold 'edge.off: 4 faces share the edge at \(8, 8, 1.5\) mm' "$skinfem" mesh "$tmp/off_non_manifold.json" --out "$tmp/out"
# No size estimate exists for an imported surface: the built mesh is checked before anything is assembled.
variant stl_max_dofs 'd["geometry"] = {"type": "surface", "path": "box.stl"}; d["loads"] = {}'
check stl_max_dofs 'stl_max_dofs.json: the mesh has [0-9]+ tetrahedra and [0-9]+ DOFs, above max_dofs \(--max-dofs\) = 3e\+03' "$skinfem" green "$tmp/stl_max_dofs.json" --max-dofs 3000 --out "$tmp/out"
variant stl_missing 'd["geometry"] = {"type": "surface", "path": "none.stl"}'
check stl_missing 'geometry.path = "none.stl": must name an existing file' "$skinfem" mesh "$tmp/stl_missing.json" --out "$tmp/out"
variant stl_extension 'd["geometry"] = {"type": "surface", "path": "base.json"}'
check stl_extension 'geometry.path = "base.json": must be a .stl, .obj or .off file' "$skinfem" mesh "$tmp/stl_extension.json" --out "$tmp/out"

# The command line.
touch "$tmp/a_file"
check out_is_file '--out .*a_file: exists and is not a directory' "$skinfem" mesh "$tmp/base.json" --out "$tmp/a_file"
check out_under_file '--out .*a_file/sub: cannot create or write' "$skinfem" mesh "$tmp/base.json" --out "$tmp/a_file/sub"
check unknown_subcommand "unknown subcommand 'frobnicate'; one of: mesh" "$skinfem" frobnicate "$tmp/base.json" --out "$tmp/out"
check unknown_option '--frob' "$skinfem" mesh "$tmp/base.json" --frob --out "$tmp/out"
check bad_solver '--solver' "$skinfem" solve "$tmp/base.json" --solver lu --out "$tmp/out"
check bad_scales '--scales' "$skinfem" study "$tmp/base.json" --scales 1,-2 --out "$tmp/out"
bad ridges_edge_width 'd["geometry"]["ridges"] = {"period": 0.2, "height": 0.05, "center": [0, 0], "radius": 1, "profile": "rectangular", "edge_width": 0.15}' 'geometry.ridges.edge_width = 0.15: must be a number in \(0, period/2 = 0.1\]' mesh
check study_ridges_none 'geometry.ridges: --ridges needs a scene with ridges' "$skinfem" study "$tmp/base.json" --ridges 4,5,6 --out "$tmp/out"
variant ridged 'd["geometry"]["ridges"] = {"period": 0.2, "height": 0.05, "center": [0, 0], "radius": 1}'
check study_ridges_two '--ridges: a ridge study needs at least 3 levels' "$skinfem" study "$tmp/ridged.json" --ridges 4,5 --out "$tmp/out"
check study_scales_huge '\(--scales 1000.0\): loads.punches\[0\].center = .*must lie on the skin with mesh.h_min = 400' "$skinfem" study "$tmp/base.json" --scales 1000,500,200 --out "$tmp/out"
check error_scales_one '--error-scales: one coarser level' "$skinfem" report "$tmp/base.json" --error-scales 2 --out "$tmp/out"
check defect_error_scales_fine '--error-scales: 0.5: the error levels are coarser than the scene' "$skinfem" defect "$tmp/base.json" --error-scales 2,0.5 --out "$tmp/out"

# A scene file is untrusted input: its name becomes the report's folder (out/<name>) and once reached a shell.
# Run from an empty folder with the default --out; nothing may appear there or anywhere above it.
mkdir "$tmp/cwd"
named() {  # NAME JSON_STRING: report on the base scene with that "name", from $tmp/cwd
  variant "$1" "d['name'] = $2"
  check "$1" 'name = .*must be a file name of 1 to 100 characters' env -C "$tmp/cwd" "$skinfem" report "$tmp/$1.json" --no-error-bars
  if [ -n "$(ls -A "$tmp/cwd")" ] || [ -e "$tmp/SOMEFILE" ] || [ -e "$tmp/escaped" ] || [ -e "$(dirname "$tmp")/escaped" ]; then
    echo "FAIL $1: wrote $(ls -A "$tmp/cwd") $(ls -d "$tmp/SOMEFILE" "$tmp/escaped" "$(dirname "$tmp")/escaped" 2>/dev/null)"
    passed=$((passed - 1)) fail=$((fail + 1))
  fi
}
named name_shell_injection "\"x'; touch SOMEFILE; echo '\""
named name_shell_substitution '"$(touch SOMEFILE)"'
named name_climbs_out '"../../escaped"'
named name_dot_dot '".."'
named name_separator '"a/b"'
named name_nul '"a\u0000b"'
named name_option '"-rf"'

# Command-line levels and numbers that CLI11 lets through.
check grid_nan '--grid: nan: must be a finite number' "$skinfem" green "$tmp/base.json" --grid nan --out "$tmp/out"
check max_dofs_nan '--max-dofs: nan: must be a finite number' "$skinfem" mesh "$tmp/base.json" --max-dofs nan --out "$tmp/out"
check study_scales_fine_first '--scales: 1 then 1.41: levels must be distinct and decreasing' "$skinfem" study "$tmp/base.json" --scales 1,1.41,2 --out "$tmp/out"
check study_scales_equal '--scales: 1 then 1: levels must be distinct' "$skinfem" study "$tmp/base.json" --scales 1,1,1 --chain --out "$tmp/out"
check study_ridges_equal '--ridges: 2 then 2: levels must be distinct and increasing' "$skinfem" study "$tmp/ridged.json" --ridges 2,2,2 --out "$tmp/out"
check study_ridges_nan '--ridges: nan: must be a finite number' "$skinfem" study "$tmp/ridged.json" --ridges 4,nan,6 --out "$tmp/out"
check study_scales_nan '--scales: nan: must be a finite number' "$skinfem" study "$tmp/base.json" --scales 2,nan,1 --out "$tmp/out"
check study_chain_scales_nan '--scales: nan: must be a finite number' "$skinfem" study "$tmp/base.json" --chain --scales nan,nan,nan --out "$tmp/out"
check max_dofs_huge '--max-dofs: 1e400: must be a finite number' "$skinfem" mesh "$tmp/base.json" --max-dofs 1e400 --out "$tmp/out"
check max_dofs_negative '--max-dofs: -1: must be a number >= 0' "$skinfem" mesh "$tmp/base.json" --max-dofs -1 --out "$tmp/out"
check grid_subnormal '--grid = 4.94066e-324: the kernel grid .* would have inf points' "$skinfem" green "$tmp/base.json" --grid 5e-324 --out "$tmp/out"
check grid_text '--grid: abc: must be a number' "$skinfem" green "$tmp/base.json" --grid abc --out "$tmp/out"
check out_empty "--out '': must name a directory" "$skinfem" mesh "$tmp/base.json" --out ""
long_name=$(printf 'x%.0s' $(seq 1 300))
check out_name_too_long '--out .*: a name in the path has 300 characters; allowed at most 255 per name' \
  "$skinfem" mesh "$tmp/base.json" --out "$tmp/$long_name/out"
"$skinfem" mesh "$tmp/base.json" --out "$tmp/owned" >/dev/null 2>&1 || echo "FAIL: mesh into $tmp/owned"
check out_owned_by_another '--out .*owned: holds the results of `skinfem mesh` \(run.json\); `skinfem solve` would mix' "$skinfem" solve "$tmp/base.json" --out "$tmp/owned"
check study_ridges_coarse '--ridges: 2.000000: a level must give at least 3 mesh elements per ridge period' "$skinfem" study "$tmp/ridged.json" --ridges 2,3,4 --out "$tmp/out"
check error_scales_equal '--error-scales: 2 then 2: levels must be distinct and decreasing' "$skinfem" report "$tmp/base.json" --error-scales 2,2 --out "$tmp/out"
check error_scales_huge '--error-scales: 1e\+06: a level at more than 4 times every mesh size' "$skinfem" report "$tmp/base.json" --error-scales 1e6,2 --out "$tmp/out"

# Physics the scene cannot mean.
sphere='d["contact"] = {"indenter": {"type": "sphere", "R": 50, "center": [0, 0]}, "force": 0.1'
bad static_above_coulomb "$sphere, \"friction\": {\"mode\": \"static\", \"mu\": 1, \"static_ratio\": 5}}" 'contact.friction.static_ratio = 5: must be a number in \[0, mu = 1\]' contact
# The finite-strain contact's scope (pipeline/finite_contact.hpp): each refusal names its field.
neo='d["material"]["model"] = "neo_hookean"; '"$sphere"
bad neo_contact_depth "$neo"'}; del d["contact"]["force"]; d["contact"]["depth"] = 0.01' 'contact.depth: with material.model "neo_hookean" the contact is force controlled' contact
bad neo_contact_holes "$neo"', "holes": [{"center": [0.5, 0], "diameter": 0.5}]}' 'contact.holes: with material.model "neo_hookean" the plate has no holes \(1 given\)' contact
bad neo_contact_interface "$neo"', "interface": {"law": "linear", "K": 5}}' 'contact.interface.law = "linear": with material.model "neo_hookean" the interface is hard' contact
bad neo_defect_sphere "$neo"', "sweep": {"from": [-1, 0], "to": [1, 0]}}' 'contact.indenter = "sphere": with material.model "neo_hookean" the hole sweep runs under a plate' defect
bad neo_contact_uncoupled "$neo"', "friction": {"mode": "uncoupled", "mu": 1, "static_ratio": 0.1}}' "friction mode 'uncoupled' \(--friction or contact.friction.mode\): with material.model \"neo_hookean\" the contact is frictionless \('none'\), at rest" contact
bad neo_defect_resolved "$neo"'}; d["contact"]["indenter"] = {"type": "plane"}; d["geometry"] = {"type": "cap", "R": 20.0, "h": 3.0, "apex": [0.0, 0.0], "truncation_radius": 8.0}; d["contact"]["sweep"] = {"from": [-1, 0], "to": [1, 0], "hole_model": "resolved"}' 'contact.sweep.hole_model = "resolved": with material.model "neo_hookean" the hole is the bulge' defect
bad neo_report_interface "$neo"'}; d["contact"]["indenter"] = {"type": "plane"}; d["geometry"] = {"type": "cap", "R": 20.0, "h": 3.0, "apex": [0.0, 0.0], "truncation_radius": 8.0}; d["contact"]["sweep"] = {"from": [-1, 0], "to": [1, 0]}; d["contact"]["interface"] = {"law": "linear", "K": 5}' 'contact.interface.law = "linear": with material.model "neo_hookean" the interface is hard' report
variant neo_meridian "$neo"'}'
# The Green tensor about a preload: patches alone, in 3D.
bad neo_green_punch 'd["material"]["model"] = "neo_hookean"; d["loads"]["punches"][0]["displacement"] = 0.01; del d["loads"]["punches"][0]["force"]' 'loads.punches: with material.model "neo_hookean" the Green tensor.s preload is loads.patches alone \(1 punches given\)' green
variant neo_green 'd["material"]["model"] = "neo_hookean"; d["loads"] = {}'
check neo_green_meridian '--path meridian: with material.model "neo_hookean" the Green tensor is the 3D tangent.s' "$skinfem" green "$tmp/neo_green.json" --path meridian --out "$tmp/out"
check neo_contact_meridian '--path meridian: with material.model "neo_hookean" the contact is solved in 3D' "$skinfem" contact "$tmp/neo_meridian.json" --path meridian --out "$tmp/out"
bad friction_law_unknown "$sphere, \"friction\": {\"law\": \"tresca\"}}" 'contact.friction.law = "tresca": must be one of "coulomb", "shear_strength", "mixed"' contact
bad tau0_negative "$sphere, \"friction\": {\"law\": \"shear_strength\", \"tau0\": -0.1}}" 'contact.friction.tau0 = -0.1: must be a shear strength in \[0, 1e6\] MPa' defect
bad tau0_with_coulomb "$sphere, \"friction\": {\"mu\": 1, \"tau0\": 0.1}}" 'contact.friction.tau0 = 0.1: is the shear strength of "law": "shear_strength" or "mixed"' report
bad interface_K_zero "$sphere, \"interface\": {\"law\": \"linear\", \"K\": 0}}" 'contact.interface.K = 0: must be an interface stiffness in \(0, 1e12\] MPa/mm' contact
bad interface_law_unknown "$sphere, \"interface\": {\"law\": \"soft\"}}" 'contact.interface.law = "soft": must be one of "hard", "linear", "exponential"' defect
bad interface_K_when_hard "$sphere, \"interface\": {\"law\": \"hard\", \"K\": 5}}" 'contact.interface.K = 5: is the stiffness of "law": "linear"' contact
bad interface_u0_zero "$sphere, \"interface\": {\"law\": \"exponential\", \"u0\": 0, \"p_ref\": 0.01}}" 'contact.interface.u0 = 0: must be a decay length in \(0, 1\] mm' contact
bad interface_p_ref_negative "$sphere, \"interface\": {\"law\": \"exponential\", \"u0\": 0.001, \"p_ref\": -1}}" 'contact.interface.p_ref = -1: must be a pressure in \(0, 1e6\] MPa' report
bad interface_exponential_shear "$sphere, \"friction\": {\"law\": \"shear_strength\", \"mu\": 1}, \"interface\": {\"law\": \"exponential\", \"u0\": 0.001, \"p_ref\": 0.01}}" 'contact.interface.law = "exponential": touches everywhere, and a shear strength acts where the skin touches' defect
bad hole_below_mesh "$sphere, \"h\": 0.8, \"holes\": [{\"center\": [0.5, 0], \"diameter\": 0.5}]}" 'contact.holes\[0\].diameter = 0.5: must be >= the mesh size over the hole \(contact.h = 0.8 mm\)' contact
bad sweep_hole_below_mesh "$sphere, \"h\": 0.8, \"sweep\": {\"from\": [-1, 0], \"to\": [1, 0], \"hole_model\": \"resolved\"}}" 'contact.sweep.hole_diameter = 0.5: must be >= the mesh size over the hole' defect
bad sweep_bulge_soft_interface "$sphere, \"interface\": {\"law\": \"linear\", \"K\": 5}, \"sweep\": {\"from\": [-1, 0], \"to\": [1, 0], \"hole_model\": \"bulge\"}}" 'contact.sweep.hole_model = "bulge": is the hole.s solution under a hard interface; with "interface": \{"law": "linear"\} use "resolved"' defect
bad sweep_hole_model_unknown "$sphere, \"sweep\": {\"from\": [-1, 0], \"to\": [1, 0], \"hole_model\": \"crack\"}}" 'contact.sweep.hole_model = "crack": must be one of "bulge", "resolved"' defect
# Textured plates and their scan (skinfem scan).
tex='"scan": {"from": -2, "to": 2, "step": 0.05}, "texture": {"h": 0.4, '
bad texture_overlap "$sphere, $tex\"holes\": [{\"center\": [0, 0], \"diameter\": 0.5}, {\"center\": [0.3, 0], \"diameter\": 0.5}]}}" 'contact.texture.holes\[1\] = \[0.3,0(.0)?\]: overlaps contact.texture.holes\[0\]' scan
bad texture_outside "$sphere, $tex\"holes\": [{\"center\": [0, 5], \"diameter\": 0.5}]}}" 'contact.texture.holes\[0\] = \[0(.0)?,5(.0)?\]: never reaches the candidate contact zone' scan
bad texture_lattice_overlap "$sphere, $tex\"lattice\": {\"origin\": [-1, 0], \"period\": [0.4, 1], \"count\": [5, 1], \"diameter\": 0.5}}}" 'contact.texture.lattice.period = \[0.4,1(.0)?\]: each period .* must be >= its diameter' scan
bad texture_random_dense "$sphere, $tex\"random\": {\"from\": [-1, -0.5], \"to\": [1, 0.5], \"density\": 20, \"diameter\": [0.5, 0.5]}}}" 'contact.texture.random.density = 20: placed [0-9]+ of its 40 holes without overlapping another' scan
bad texture_mirror_lopsided "$sphere, $tex\"random\": {\"from\": [-1, -0.5], \"to\": [1, 0.8], \"density\": 2, \"diameter\": [0.2, 0.2], \"mirror\": True}}}" 'contact.texture.random.from = \[-1,-0.5\]: with "mirror": true the rectangle must be symmetric about y = 0' scan
bad texture_groove_overlap "$sphere, $tex\"holes\": [{\"center\": [0, 0], \"diameter\": 0.5}], \"grooves\": {\"origin\": [0.3, 0], \"width\": 0.5, \"length\": 2, \"count\": 1}}}" 'contact.texture.grooves \(groove 1 of 1\) = \[0.3,0(.0)?\]: overlaps contact.texture.holes\[0\]' scan
bad texture_grooves_period "$sphere, $tex\"grooves\": {\"origin\": [-1, 0], \"width\": 0.5, \"length\": 2, \"count\": 3, \"period\": 0.4}}}" 'contact.texture.grooves.period = 0.4: must be > the grooves. width 0.5 mm' scan
bad texture_groove_below_mesh "$sphere, $tex\"grooves\": {\"origin\": [-1, 0], \"width\": 0.2, \"length\": 2, \"count\": 1}}}" 'contact.texture.grooves.width = 0.2: must be >= the mesh size over the hole \(mesh.h_min = 0.4 mm\)' scan
bad texture_empty "$sphere, $tex\"h\": 0.4}}" 'contact.texture = .*must have at least one of "holes", "lattice", "grooves", "random"' scan
bad scan_step_coarse "$sphere, \"scan\": {\"from\": -2, \"to\": 2, \"step\": 0.5}, \"texture\": {\"h\": 0.4, \"holes\": [{\"center\": [0, 0], \"diameter\": 0.5}]}}" 'contact.scan.step = 0.5: must be <= the mesh size along the holes. tracks' scan
bad scan_backwards "$sphere, \"scan\": {\"from\": 2, \"to\": -2, \"step\": 0.05}, \"texture\": {\"holes\": [{\"center\": [0, 0], \"diameter\": 0.5}]}}" 'contact.scan.to = -2: must be > from = 2' scan
bad scan_without_texture "$sphere, \"scan\": {\"from\": -2, \"to\": 2, \"step\": 0.05}}" 'contact.scan = .*a textured plate is scanned: give both "texture" and "scan"' scan
bad perceive_resolved "$sphere, \"sweep\": {\"from\": [-1, 0], \"to\": [1, 0], \"hole_model\": \"resolved\"}}" 'contact.sweep.hole_model = "resolved": skinfem perceive sweeps holes down to an eighth' perceive
bad scan_sweep_across "$sphere, \"sweep\": {\"from\": [0, -1], \"to\": [0, 1]}}" 'contact.sweep: skinfem scan moves the plate along the sliding direction' scan
# skinfem invert's signals file (checked before any solve).
variant invert_scene "$sphere, \"sweep\": {\"from\": [-1, 0], \"to\": [1, 0]}}"
printf 'u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n0,1,0.1,0.2\n0.1,2,0.1,0.2\n' >"$tmp/signals_sensor.csv"
check invert_wrong_sensor 'signals_sensor.csv: row 3: sensor = 2: the scene has sensors 1 to 1' "$skinfem" invert "$tmp/signals_sensor.csv" "$tmp/invert_scene.json" --out "$tmp/out"
printf 'u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n0,1,nan,0.2\n0.1,1,0.1,0.2\n' >"$tmp/signals_nan.csv"
check invert_nan 'signals_nan.csv: row 2: varsigma_z_kPa = nan: must be a finite number' "$skinfem" invert "$tmp/signals_nan.csv" "$tmp/invert_scene.json" --out "$tmp/out"
printf 'u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n0,1,0.1,0.2\n0.1,1,0.1,0.2\n0.3,1,0.1,0.2\n' >"$tmp/signals_uneven.csv"
check invert_uneven 'signals_uneven.csv: u_mm is not evenly spaced' "$skinfem" invert "$tmp/signals_uneven.csv" "$tmp/invert_scene.json" --out "$tmp/out"
printf 'u,sensor,sz,sx\n0,1,0.1,0.2\n' >"$tmp/signals_header.csv"
check invert_header 'signals_header.csv: header has no column u_mm' "$skinfem" invert "$tmp/signals_header.csv" "$tmp/invert_scene.json" --out "$tmp/out"
printf 'u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n0,1,0.1,0.2\n0,1,0.1,0.2\n' >"$tmp/signals_twice.csv"
check invert_twice 'signals_twice.csv: row 3: sensor 1 at u = 0 mm is given twice' "$skinfem" invert "$tmp/signals_twice.csv" "$tmp/invert_scene.json" --out "$tmp/out"
check invert_missing 'no_signals.csv: cannot read the signals file' "$skinfem" invert "$tmp/no_signals.csv" "$tmp/invert_scene.json" --out "$tmp/out"
awk 'BEGIN { print "u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa"; for (i = 0; i < 5000; ++i) printf "%.3f,1,0,0\n", 0.001 * i }' >"$tmp/signals_long.csv"
check invert_too_large 'signals_long.csv: 5000 positions every 0.001000 mm make a fit of .* hole positions by 10000 samples; at most 2.5e7' "$skinfem" invert "$tmp/signals_long.csv" "$tmp/invert_scene.json" --out "$tmp/out"
variant invert_posts 'd["sensors"]["model"] = "post"; d["sensors"].pop("disc_diameter", None); d["sensors"]["post"] = {"diameter": 0.2, "height": 0.4}; '"$sphere"', "sweep": {"from": [-1, 0], "to": [1, 0]}}'
printf 'u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n0,1,0.1,0.2\n0.1,1,0.1,0.2\n' >"$tmp/signals_posts.csv"
check invert_posts_offset 'invert_posts.json: sensors.model = "post": a post reads the skin only where it is meshed.*give --offset-range 0' "$skinfem" invert "$tmp/signals_posts.csv" "$tmp/invert_posts.json" --out "$tmp/out"
bad scan_no_texture "$sphere}" 'contact.texture: missing; skinfem scan needs' scan
bad depth_through_skin 'd["contact"] = {"indenter": {"type": "sphere", "R": 50, "center": [0, 0]}, "depth": 5, "zone_radius": 3}' 'contact.depth = 5: must be below the skin.s thickness \(3 mm\)' contact
bad depth_beyond_sphere 'd["contact"] = {"indenter": {"type": "sphere", "R": 1, "center": [0, 0]}, "depth": 2}' 'contact.depth = 2: must be below the sphere.s radius R = 1 mm' contact
bad sphere_R_subnormal 'd["contact"] = {"indenter": {"type": "sphere", "R": 5e-324, "center": [0, 0]}, "force": 0.1}' 'contact.indenter.R = 5e-324: must be a radius in \[0.001, 10000\] mm' contact
bad force_below_mesh "$sphere}; d['contact']['force'] = 1e-9" 'contact.force = 1e-09: the automatic candidate contact zone \(radius .* mm\) must be at least one contact element across' contact
bad zone_below_mesh "$sphere, \"zone_radius\": 5e-324}" 'contact.zone_radius = 5e-324: the candidate contact zone \(radius .* mm\) must be at least one contact element across' contact
bad hole_covers_zone "$sphere, \"zone_radius\": 3, \"holes\": [{\"center\": [0, 0], \"diameter\": 7}]}" 'contact.holes\[0\].diameter = 7(.0)?: the hole covers the whole candidate contact zone' contact
# Coulomb ratios beyond where the contact stays unique: the bound is computed on the condensed skin (the
# coarse cap of app/report.sh: about 6), so these fail after condensing, still with the field and the bound.
/usr/bin/python3 - "$(dirname "$0")/data/coarse_cap.json" "$tmp" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
del d["contact"]["sweep"]
d["contact"]["friction"] = {"mode": "coupled", "mu": 30, "static_ratio": 0.1}
json.dump(d, open(sys.argv[2] + "/mu30.json", "w"))
d["contact"]["friction"] = {"mode": "static", "mu": 30, "static_ratio": 30}
json.dump(d, open(sys.argv[2] + "/static30.json", "w"))
d["contact"]["friction"] = {"mode": "none"}
d["contact"]["holes"] = [{"center": [0.5, 0.0], "diameter": 0.8, "depth": 1e-5}]
json.dump(d, open(sys.argv[2] + "/shallow_hole.json", "w"))
del d["contact"]["holes"]
d["contact"]["sweep"] = {"from": [-2.0, 0.0], "to": [3.0, 0.0], "positions": 11, "hole_diameter": 0.8, "hole_depth": 1e-5}
json.dump(d, open(sys.argv[2] + "/shallow_sweep.json", "w"))
PY
check mu_beyond_uniqueness 'contact.friction.mu = 30: the coupled contact did not solve .*guaranteed one solution only for mu below [0-9.]+ on this skin' "$skinfem" contact "$tmp/mu30.json" --out "$tmp/out"
# The meridian contact path where it is not exact or not symmetric: coupled friction, a hole in the indenter.
check meridian_coupled 'contact.friction.mu = 30\): its normal displacement varies as cos θ, so the contact zone is not a disc; use --path 3d' "$skinfem" contact "$tmp/mu30.json" --path meridian --out "$tmp/out"
variant meridian_holes "$sphere, \"zone_radius\": 3, \"holes\": [{\"center\": [0.5, 0], \"diameter\": 0.5}]}"
check meridian_holes "meridian \(axisymmetric\) contact path does not apply: a hole off the contact's axis breaks its symmetry" "$skinfem" contact "$tmp/meridian_holes.json" --path meridian --out "$tmp/out"
variant meridian_axis_hole "$sphere, \"zone_radius\": 3, \"holes\": [{\"center\": [0, 0], \"diameter\": 0.5}]}"
check meridian_axis_hole "contact path does not apply: holes are on the 3D path only \(a hole on the axis keeps the symmetry" "$skinfem" contact "$tmp/meridian_axis_hole.json" --path meridian --out "$tmp/out"
# A hole shallower than the skin's rise into it: the solve assumes its bottom untouched.
check hole_too_shallow 'contact.holes\[0\].depth = 1e-05: the skin rises [0-9.]+ um into the hole, past its bottom' "$skinfem" contact "$tmp/shallow_hole.json" --out "$tmp/out"
check sweep_hole_too_shallow 'contact.sweep.hole_depth = 1e-05: the skin rises [0-9.]+ um into the hole, past its bottom' "$skinfem" defect "$tmp/shallow_sweep.json" --out "$tmp/out"
check static_ratio_beyond_uniqueness 'contact.friction.static_ratio = 30: .*only for static_ratio below [0-9.]+' "$skinfem" contact "$tmp/static30.json" --out "$tmp/out"
# An indenter beside an imported skin: refused when the surface is read, before meshing.
/usr/bin/python3 - "$(dirname "$0")/../../scenes" "$tmp" <<'PY'
import json, os, sys
d = json.load(open(os.path.join(sys.argv[1], "dome_stl.json")))
d["geometry"]["path"] = os.path.realpath(os.path.join(sys.argv[1], d["geometry"]["path"]))
d["contact"]["indenter"]["center"] = [40.0, 0.0]
json.dump(d, open(sys.argv[2] + "/dome_off.json", "w"))
PY
check sphere_off_imported_skin 'contact.indenter.center = \(40, 0\): not above the imported skin.s top \(.*dome.stl spans x' "$skinfem" contact "$tmp/dome_off.json" --out "$tmp/out"
bad ridges_mesh_coarse 'd["geometry"]["ridges"] = {"period": 0.5, "height": 0.05, "center": [0, 0], "radius": 1, "h": 5}' 'geometry.ridges.h = 5: must be a number in \(0, period/3 = 0.166667 mm\]' mesh
bad ridges_period_tiny 'd["geometry"]["ridges"] = {"period": 1e-6, "height": 0.05, "center": [0, 0], "radius": 1, "h": 0.2}' 'geometry.ridges.h = 0.2: must be a number in \(0, period/3' mesh

# Sweep specs (skinfem sweep): refused before anything is written or run.
bad_spec() {  # NAME SPEC_JSON EXPECT: a spec over the base scene through `skinfem sweep`
  printf '%s' "$2" >"$tmp/$1.json"
  check "$1" "$3" "$skinfem" sweep "$tmp/$1.json" --out "$tmp/out"
}
bad_spec sweep_unknown_pointer '{"scene": "base.json", "command": "kfit", "axes": [{"pointer": "/materail/nu", "values": [0.4]}]}' \
  'axes\[0\].pointer = "/materail/nu": names nothing in the base scene: /materail is not an object there'
bad_spec sweep_empty_axis '{"scene": "base.json", "command": "kfit", "axes": [{"pointer": "/material/nu", "values": []}]}' \
  'axes\[0\].values = \[\]: must be a non-empty array'
bad_spec sweep_zip_lengths '{"scene": "base.json", "command": "kfit", "combine": "zip", "axes": [{"pointer": "/material/nu", "values": [0.4, 0.5]}, {"pointer": "/geometry/h", "values": [2, 3, 4]}]}' \
  'axes\[1\] = .*has 3 values, axes\[0\] has 2: zipped axes need equal lengths'
bad_spec sweep_member_refused '{"scene": "base.json", "command": "kfit", "axes": [{"pointer": "/material/nu", "values": [0.4, 0.7]}]}' \
  'sweep_member_refused.json: member 2 \(/material/nu = 0.7\): .*material.nu = 0.7: must be a number in \[0, 0.5\]'
bad_spec sweep_unknown_key '{"scene": "base.json", "command": "kfit", "axes": [{"pointer": "/material/colour", "values": [1]}]}' \
  'member 1 \(/material/colour = 1\): .*material.colour: unknown key'
bad_spec sweep_option '{"scene": "base.json", "command": "kfit", "options": {"friction": "none"}, "axes": [{"pointer": "/material/nu", "values": [0.4]}]}' \
  'options.friction = "none": not an option of kfit; allowed: load, max_dofs, path'
bad_spec sweep_command '{"scene": "base.json", "command": "mesh", "axes": [{"pointer": "/material/nu", "values": [0.4]}]}' \
  'command = "mesh": must be one of contact, defect, green, kfit, perceive, report, scan'
bad_spec sweep_name_climbs '{"name": "..", "scene": "base.json", "command": "kfit", "axes": [{"pointer": "/material/nu", "values": [0.4]}]}' \
  'name = "..": must be a file name of 1 to 100 characters'
bad_spec sweep_range '{"scene": "base.json", "command": "kfit", "axes": [{"pointer": "/material/nu", "range": {"from": 0.3, "to": 0.5, "count": 1}}]}' \
  'axes\[0\].range.count = 1: must be an integer in \[2, 10000\]'
bad_spec sweep_nested_axes '{"scene": "base.json", "command": "kfit", "axes": [{"pointer": "/sensors/positions", "values": [[[0, 0]]]}, {"pointer": "/sensors/positions/0/0", "values": [0.5]}]}' \
  'axes\[1\].pointer = "/sensors/positions/0/0": lies inside axes\[0\].pointer /sensors/positions'
bad_spec sweep_error_scales '{"scene": "base.json", "command": "report", "options": {"error_scales": [1.41, 2]}, "axes": [{"pointer": "/material/nu", "values": [0.4]}]}' \
  'options.error_scales = \[1.41,2\]: must be an array of at least two mesh scales in \(1, 4\], strictly decreasing'

echo "$passed passed, $fail failed"
[ $fail -eq 0 ]
