#!/usr/bin/env bash
# The installed package: `cmake --install` into a fresh prefix, a downstream CMake project built against it
# with find_package(skinfem), and its mesh of a scene against the installed command's (same nodes and
# elements); the installed command finds its figure script beside itself.
# With the Python module (PYTHON = ON): `import skinfem` from the prefix reproduces the installed command's
# kfit.json of the same scene.
# usage: install.sh BUILD_DIR SOURCE_DIR PYTHON
set -euo pipefail
build=$1 src=$2 python=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
for f in bin/skinfem share/skinfem/figures.py share/skinfem/workflow/Snakefile share/skinfem/workflow/gather.py lib/cmake/skinfem/skinfemConfig.cmake \
  include/skinfem/pipeline/skin_setup.hpp include/skinfem/scene/scene.hpp; do
  [ -e "$prefix/$f" ] || { echo "install.sh: $f not installed" >&2; exit 1; }
done
# Installed headers include each other by their prefixed path (<skinfem/folder/x.hpp>), each found in the
# prefix: a consumer's own scene/ or mesh/ can never stand in for ours.
while read -r inc; do
  [ -e "$prefix/include/$inc" ] || { echo "install.sh: an installed header includes \"$inc\", not in $prefix/include" >&2; exit 1; }
  case $inc in skinfem/*) ;; *) echo "install.sh: an installed header includes \"$inc\" without the skinfem/ prefix" >&2; exit 1 ;; esac
done < <(grep -rhoE '#include "[^"]+"' "$prefix/include/skinfem" | sed -E 's/#include "(.*)"/\1/' | sort -u)
cmake -S "$src/tests/install/downstream" -B "$work/downstream" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/downstream" >/dev/null
scene=$src/scenes/flat_layer.json
"$work/downstream/downstream" "$scene" 2>/dev/null >"$work/downstream.txt"
"$prefix/bin/skinfem" mesh "$scene" --out "$work/mesh" >/dev/null 2>&1
python3 - "$work/downstream.txt" "$work/mesh/summary.json" <<'PY'
import json, sys
got = dict(line.split() for line in open(sys.argv[1]))
ref = json.load(open(sys.argv[2]))
for key in ("nodes", "elements"):
    if int(got[key]) != ref[key]:
        sys.exit(f"install.sh: downstream {key} {got[key]} != installed skinfem mesh's {ref[key]}")
if int(got["free_dofs"]) <= 0:
    sys.exit("install.sh: downstream factored no DOFs")
print(f"downstream: {got['nodes']} nodes, {got['elements']} elements, {got['free_dofs']} free DOFs, as skinfem mesh")
PY
# The README's C++ example as printed (its CMakeLists.txt and main.cpp), built against the prefix and run from
# the source tree: it prints its progress through its sink, and the installed command's `report --fast` numbers.
readme=$work/readme
mkdir -p "$readme"
python3 - "$src/README.md" "$readme" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
for marker, name in (("cmake-example", "CMakeLists.txt"), ("cpp-example", "main.cpp")):
    blocks = re.findall(rf"<!-- {marker} -->\s*```\w+\n(.*?)```", text, re.S)
    if len(blocks) != 1:
        sys.exit(f"install.sh: README.md has {len(blocks)} <!-- {marker} --> blocks, not one")
    open(f"{sys.argv[2]}/{name}", "w").write(blocks[0])
PY
cmake -S "$readme" -B "$readme/b" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$readme/b" >/dev/null
(cd "$src" && "$readme/b/mine") >"$work/mine.txt" 2>"$work/mine.err"
grep -q '^\[mine\] ' "$work/mine.err" ||
  { echo "install.sh: the README's C++ example printed no progress line through its sink" >&2; exit 1; }
"$prefix/bin/skinfem" report "$src/scenes/hertz_layer.json" --fast --out "$work/report" >/dev/null 2>&1
python3 - "$work/mine.txt" "$work/report/report.json" <<'PY'
import json, re, sys
line = open(sys.argv[1]).read().strip()
m = re.fullmatch(r"(\S+): (\d+) DOFs, k_central ([0-9.]+), contact radius ([0-9.]+) mm", line)
if not m:
    sys.exit(f"install.sh: the README's C++ example printed '{line}'")
ref = json.load(open(sys.argv[2]))
want = (ref["scene"]["name"], str(ref["dofs"]), f"{ref['kfit']['k_central']:.4f}", f"{ref['contact']['contact_radius_mm']:.3f}")
if m.groups() != want:
    sys.exit(f"install.sh: the README's C++ example printed {m.groups()}, the installed command's report {want}")
print(f"README's C++ example: {line}, as skinfem report --fast")
PY
# The installed command runs the installed figure script, not the source tree's.
figures=$("$prefix/bin/skinfem" --version | sed -n 's/^figures: //p')
[ "$figures" = "$(realpath "$prefix/share/skinfem/figures.py")" ] ||
  { echo "install.sh: the installed skinfem runs '$figures', not its installed figures.py" >&2; exit 1; }
# ... and the installed sweep workflow.
"$prefix/bin/skinfem" sweep "$src/sweeps/k_vs_nu_and_punch.json" --out "$work/sweep" --dry-run >"$work/sweep.txt"
grep -q -- "--snakefile $(realpath "$prefix/share/skinfem/workflow/Snakefile") " "$work/sweep.txt" ||
  { echo "install.sh: the installed skinfem sweep runs another workflow: $(tail -1 "$work/sweep.txt")" >&2; exit 1; }
if [ "$python" = ON ]; then
  "$prefix/bin/skinfem" kfit "$scene" --out "$work/kfit" >/dev/null 2>&1
  PYTHONPATH=$prefix /usr/bin/python3 - "$scene" "$work/kfit/kfit.json" <<'PY'
import json, math, sys
import skinfem
fit = skinfem.kfit(skinfem.scene(sys.argv[1])).to_dict()
ref = json.load(open(sys.argv[2]))
for key in ("k_central", "k_lsq_line", "k_central_exact", "dofs", "path"):
    same = math.isclose(fit[key], ref[key], rel_tol=1e-12) if isinstance(ref[key], float) else fit[key] == ref[key]
    if not same:
        sys.exit(f"install.sh: installed module's {key} {fit[key]} != installed command's {ref[key]}")
print(f"installed module: k_central {fit['k_central']:.6f}, k_lsq_line {fit['k_lsq_line']:.6f}, as the command")
PY
fi
