#!/usr/bin/env bash
# meshio.sh IO_TOOL: runs meshio_check.py with the first Python that can import meshio
# ($LH_PYTHON, python3, /usr/bin/python3: a pyenv python3 may not see Debian's
# python3-meshio). Exit status 77 (skipped) when none can.
set -u
here="$(cd "$(dirname "$0")" && pwd)"
for py in ${LH_PYTHON:-} python3 /usr/bin/python3; do
  if command -v "$py" > /dev/null && "$py" -c "import meshio" 2> /dev/null; then
    work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
    "$py" "$here/meshio_check.py" "$1" "$work"
    exit $?
  fi
done
echo "SKIP: no Python with meshio (Debian: apt-get install python3-meshio; scripts/deps.sh test)"
exit 77
