#!/bin/sh
# One command for the speed/memory benchmark: writes bench/RESULTS.md
# and bench/speed/*.png. Extra arguments go to speed.py, e.g.
#   bench/run_speed.sh --quick
#   bench/run_speed.sh --mcmd /tmp/build/bin/mcmd_fillnodata --only sierra
# Uses /usr/bin/python3 (numpy + GDAL bindings); run from anywhere.
set -e
here=$(cd "$(dirname "$0")" && pwd)
exec /usr/bin/python3 "$here/speed.py" "$@"
