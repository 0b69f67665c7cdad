#!/bin/sh
# One command for the delta surface fill benchmark: writes bench/FILL_FROM.md
# and bench/fill_from/*.png. Extra arguments go to fill_from.py, e.g.
#   bench/run_fill_from.sh --quick
# Uses /usr/bin/python3 (numpy + GDAL bindings); run from anywhere.
set -e
here=$(cd "$(dirname "$0")" && pwd)
exec /usr/bin/python3 "$here/fill_from.py" "$@"
