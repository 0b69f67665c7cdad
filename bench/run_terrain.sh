#!/bin/sh
# One command for the terrain benchmark: writes bench/TERRAIN.md and
# bench/terrain/*.png. Extra arguments go to terrain_bench.py (--quick).
# Uses /usr/bin/python3 (numpy, GDAL bindings, PIL); run from anywhere.
set -e
here=$(cd "$(dirname "$0")" && pwd)
exec /usr/bin/python3 "$here/terrain_bench.py" "$@"
