# Sourced by scripts/test.sh and scripts/fuzz.sh: the compiler cache for CMake, as the array
# `launcher` of configure arguments. Each CI run builds a fresh clone, and most of a change
# leaves most objects as they were: ccache, keyed on paths relative to the clone (base dir, no
# working directory in the hash), gives a new clone the objects of the last one, precompiled
# headers included (their defines and time macros are the build's own, hence the sloppiness).
# The cache is the user's (~/.cache/ccache); a build without it is the same, only slower.
# DYNPOS_CCACHE=0 turns it off.
if [ "${DYNPOS_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null; then
  export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
  export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
else
  launcher=(-UCMAKE_CXX_COMPILER_LAUNCHER)
fi
