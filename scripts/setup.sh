#!/usr/bin/env bash
# The README's first command: install, build, and fill the bundled sample DEM.
# Leaves out/sample_filled.tif and out/sample_hillshade.png to look at.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
bash "$root/scripts/install-python.sh"  # import mcmd from /usr/bin/python3
mkdir -p "$root/out"
rm -f "$root/out/sample_filled.tif"
"$root/build/bin/mcmd_fillnodata" "$root/testdata/sample_dem.tif" "$root/out/sample_filled.tif"
gdaldem hillshade -q -z 2 "$root/out/sample_filled.tif" "$root/out/sample_hillshade.png" -of PNG
echo "filled: out/sample_filled.tif   hillshade: out/sample_hillshade.png"
