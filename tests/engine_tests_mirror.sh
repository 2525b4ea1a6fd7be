#!/usr/bin/env bash
# The engine tests mirror the engine: every engine/<room>/<name>.cpp has its test file
# tests/engine/<room>/test_<name>.cpp (engine/<name>.cpp: tests/engine/test_<name>.cpp),
# and every test file there belongs to an engine file (<name>.cpp or <name>.hpp).
# Usage: engine_tests_mirror.sh SOURCE_DIR. Exit 0 when mirrored, 1 naming what is missing.
set -u
root=${1:?usage: engine_tests_mirror.sh SOURCE_DIR}
cd "$root" || exit 2
[ -d engine ] && [ -d tests/engine ] || { echo "no engine/ or tests/engine/ under $root" >&2; exit 2; }

status=0
checked=0
while IFS= read -r source; do
  rel=${source#engine/}
  dir=$(dirname "$rel")
  name=$(basename "$rel" .cpp)
  if [ "$dir" = "." ]; then test_file="tests/engine/test_$name.cpp"; else test_file="tests/engine/$dir/test_$name.cpp"; fi
  checked=$((checked + 1))
  if [ ! -f "$test_file" ]; then
    echo "engine_tests_mirror: $source has no test file $test_file" >&2
    status=1
  fi
done < <(find engine -name '*.cpp' | sort)

while IFS= read -r test_file; do
  rel=${test_file#tests/engine/}
  dir=$(dirname "$rel")
  name=$(basename "$rel" .cpp)
  name=${name#test_}
  if [ "$dir" = "." ]; then base="engine/$name"; else base="engine/$dir/$name"; fi
  if [ ! -f "$base.cpp" ] && [ ! -f "$base.hpp" ]; then
    echo "engine_tests_mirror: $test_file tests no engine file ($base.cpp or $base.hpp)" >&2
    status=1
  fi
done < <(find tests/engine -name 'test_*.cpp' | sort)

[ "$status" -eq 0 ] && echo "engine_tests_mirror: all $checked engine .cpp files have their test file"
exit "$status"
