#!/bin/sh
# One command for the realism benchmark: writes bench/REALISM.md and
# bench/realism/*.png (synthetic terrains against real mountains, erosion
# times). Extra arguments go to realism.py (--quick). Uses /usr/bin/python3
# (numpy, numba, GDAL bindings) and build/bin/mcmd_terrain; run from anywhere.
set -e
here=$(cd "$(dirname "$0")" && pwd)
exec /usr/bin/python3 "$here/realism.py" "$@"
