#!/usr/bin/env bash
# Every tracked C++ source is formatted as the repo's .clang-format says; lists the files that are not.
set -u
clang_format=$1
files=$(git ls-files '*.cpp' '*.hpp' 2>/dev/null || find . -path ./build\* -prune -o \( -name '*.cpp' -o -name '*.hpp' \) -print)
[ -n "$files" ] || { echo "no C++ sources found from $(pwd)"; exit 1; }
bad=0
for f in $files; do
  "$clang_format" --dry-run -Werror "$f" >/dev/null 2>&1 || { echo "not formatted: $f"; bad=1; }
done
exit $bad
