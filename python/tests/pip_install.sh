#!/usr/bin/env bash
# `pip install --no-build-isolation .` into a new virtual environment, without a package index, reusing
# the build folder BUILD (so that only the module is linked again), then `import polydecomp` from
# outside the checkout: the installed copy, not the build tree's. Usage: pip_install.sh SOURCE BUILD
set -euo pipefail
source_dir="$1" build="$2"
venv="$build/python-venv"
rm -rf "$venv"
/usr/bin/python3 -m venv --system-site-packages "$venv"
POLYDECOMP_BUILD_DIR="$build" "$venv/bin/pip" install --quiet --no-build-isolation --no-index "$source_dir"
cd "$venv"
"$venv/bin/python" - "$venv" <<'PY'
import sys
import polydecomp
assert polydecomp.__file__.startswith(sys.argv[1]), polydecomp.__file__
result = polydecomp.decompose(polydecomp.generate("comb", 30), "hertel-mehlhorn")
assert result.valid and len(polydecomp.algorithms()) > 20
print("installed", polydecomp.__file__, result)
PY
