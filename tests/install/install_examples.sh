#!/usr/bin/env bash
# The installed package end to end: installs the build into a temporary prefix, checks what is
# there, builds examples/ against it with find_package(dynpos CONFIG) and runs every example,
# checking its exit code and a key line of its output.
#   install_examples.sh BUILD_DIR SOURCE_DIR WORK_DIR CXX CXX_FLAGS GENERATOR [LAUNCHER]
set -euo pipefail
build="$1"; source="$2"; work="$3"; cxx="$4"; flags="$5"; generator="$6"; launcher="${7:-}"
prefix="$work/prefix"
rm -rf "$work"; mkdir -p "$work"

step() {  # step NAME COMMAND...: runs it quietly, shows its output if it fails
  local name="$1"; shift
  if ! "$@" > "$work/$name.log" 2>&1; then
    cat "$work/$name.log"; echo "$name failed: $*"; exit 1
  fi
}
step install cmake --install "$build" --prefix "$prefix"

# Only the CLI, the public headers, the libraries with their CMake package and the data.
libdir="$(cd "$prefix" && ls -d lib*)"
for f in bin/dynpos include/dynpos/core/log.hpp include/dynpos/analysis/data_dir.hpp \
         "$libdir/libdynpos_core.a" "$libdir/libdynpos_analysis.a" \
         "$libdir/cmake/dynpos/dynposConfig.cmake" "$libdir/cmake/dynpos/dynposConfigVersion.cmake" \
         share/dynpos/scenarios/turning-circle.toml share/dynpos/vessels/gunnerus.toml; do
  [[ -e "$prefix/$f" ]] || { echo "not installed: $f"; exit 1; }
done
stray="$(cd "$prefix" && find . -type f | grep -Ev "^\./(bin/dynpos|include/dynpos/.*\.hpp|$libdir/(libdynpos_[a-z]+\.a|cmake/dynpos/[A-Za-z-]+\.cmake)|share/dynpos/.*)$" || true)"
[[ -z "$stray" ]] || { echo "unexpected files installed:"; echo "$stray"; exit 1; }

step configure cmake -S "$source/examples" -B "$work/build" -G "$generator" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="$flags" ${launcher:+-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher"}
grep -q "^dynpos_DIR:PATH=$prefix/" "$work/build/CMakeCache.txt" ||
  { grep "^dynpos_DIR" "$work/build/CMakeCache.txt"; echo "dynpos not found in $prefix"; exit 1; }
step build cmake --build "$work/build" -j 2

# The examples read the installed data, not the source tree's.
export DYNPOS_DATA_DIR="$prefix/share/dynpos"
run() {  # run EXAMPLE PATTERN: exit code 0 and a line matching PATTERN (extended regex)
  local example="$1" pattern="$2"
  if ! "$work/build/$example" > "$work/$example.out" 2>&1; then
    cat "$work/$example.out"; echo "$example failed"; exit 1
  fi
  grep -Eq "$pattern" "$work/$example.out" ||
    { cat "$work/$example.out"; echo "$example: no line matches '$pattern'"; exit 1; }
}
# The first step of the shipped log: T = 1.6 s, delay 1.0 s.
run identify_steps "^step at +10\.0 s.*T = 1\.[5-7][0-9] s, delay = (0\.9|1\.0)"
run gnss_lever_arms "^gnss1 .* [0-9.]+ mm "
run scenario_truth "^propeller port step at 20\.0 s.*shaft speed T = [0-9.]+ s"
run hybrid_case "^ideal +[1-9][0-9]* "
echo "ok"
