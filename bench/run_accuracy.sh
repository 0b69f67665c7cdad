#!/bin/sh
# One command for the accuracy benchmark: writes bench/ACCURACY.md
# and bench/accuracy/*.png. Extra arguments go to accuracy.py, e.g.
#   bench/run_accuracy.sh --quick
#   bench/run_accuracy.sh --mcmd /tmp/build/bin/mcmd_fillnodata --only zion
# Uses /usr/bin/python3 (numpy + GDAL bindings); run from anywhere.
set -e
here=$(cd "$(dirname "$0")" && pwd)
exec /usr/bin/python3 "$here/accuracy.py" "$@"
