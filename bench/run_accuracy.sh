#!/bin/sh
# One command for the accuracy benchmark: writes bench/ACCURACY.md
# and bench/accuracy/*.png. Extra arguments go to accuracy.py, e.g.
#   bench/run_accuracy.sh --quick
#   bench/run_accuracy.sh --mcmd /tmp/build/bin/mcmd_fillnodata --only zion
# Installs the peers (GRASS, SAGA: bench/install_peers.sh) when they are
# missing; without them their rows say "not run". Uses /usr/bin/python3
# (numpy, scipy + GDAL bindings); run from anywhere.
set -e
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v grass >/dev/null 2>&1 || ! command -v saga_cmd >/dev/null 2>&1 \
   || ! /usr/bin/python3 -c "import scipy" >/dev/null 2>&1; then
  "$here/install_peers.sh" || echo "run_accuracy: the peers could not be installed; their rows are not run" >&2
fi
exec /usr/bin/python3 "$here/accuracy.py" "$@"
