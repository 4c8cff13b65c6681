#!/usr/bin/env bash
# Installs the Python package dynpos of a build (scripts/install-python.sh BUILD_DIR, as root)
# into the system Python's local site-packages, so that `python3 -c "import dynpos"` works in
# any directory. When the python3 first on PATH is another interpreter of the same version (a
# pyenv one, say), a .pth file in its site-packages points it there too, and to Debian's
# packages for numpy.
set -euo pipefail
build="${1:-build/release}"
[ -f "$build/python/dynpos/__init__.py" ] || { echo "no Python package in $build"; exit 0; }
cmake --install "$build" --component python >/dev/null
site=$(/usr/bin/python3 -c "import sysconfig; print(sysconfig.get_path('platlib', 'posix_local'))")
py=$(command -v python3)
if [ "$(readlink -f "$py")" != "$(readlink -f /usr/bin/python3)" ] &&
   ! "$py" -c "import dynpos" 2>/dev/null; then
  version='import sys; print(sys.version_info[:2])'
  if [ "$("$py" -c "$version")" = "$(/usr/bin/python3 -c "$version")" ]; then
    own=$("$py" -c "import sysconfig; print(sysconfig.get_path('purelib'))")
    printf '%s\n%s\n' "$site" /usr/lib/python3/dist-packages > "$own/dynpos-system.pth"
  fi
fi
echo "dynpos Python package in $site"
