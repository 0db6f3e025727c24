#!/bin/bash
# The docs' numbers tables come from the run they quote: runs the main job on the default scene and checks
# every generated table under docs/ against its report.json (scripts/docs_tables.py; the cost table's
# seconds and megabytes are the machine's and left out).
#   tests/docs/tables.sh SKINFEM SOURCE_DIR
set -euo pipefail
skinfem=$1 source_dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$skinfem" report "$source_dir/scenes/candelier2011.json" --out "$tmp/out" >"$tmp/log" 2>&1 ||
  { tail -5 "$tmp/log"; echo "FAIL: skinfem report on the default scene"; exit 1; }
/usr/bin/python3 "$source_dir/scripts/docs_tables.py" "$tmp/out" --check
