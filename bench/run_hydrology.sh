#!/bin/sh
# One command for the hydrology benchmark: writes bench/HYDROLOGY.md and
# bench/hydrology/*.png. Extra arguments go to hydrology.py, e.g.
#   bench/run_hydrology.sh --quick
#   bench/run_hydrology.sh --selfcheck
#   bench/run_hydrology.sh --mcmd /tmp/build/bin/mcmd_fillnodata --only zion
#   bench/run_hydrology.sh --extra "morph2=-morph auto -o X=1"
# Uses /usr/bin/python3 (numpy, numba, GDAL bindings); run from anywhere.
set -e
here=$(cd "$(dirname "$0")" && pwd)
exec /usr/bin/python3 "$here/hydrology.py" "$@"
