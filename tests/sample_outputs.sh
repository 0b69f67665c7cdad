#!/usr/bin/env bash
# scripts/sample.sh (the end of the README's first command) leaves its five
# files and nothing else, also where an earlier version left hidden ones.
# Usage: sample_outputs.sh REPO BIN_DIR WORK_DIR
set -euo pipefail
root=$1 bin=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
touch "$out/.hillshade_voids.png" "$out/.hillshade_voids.png.aux.xml"
MCMD_BIN=$bin bash "$root/scripts/sample.sh" "$out" > /dev/null
listing=$(cd "$out" && LC_ALL=C ls -A | tr '\n' ' ')
expected="sample_drainage.tif sample_filled.tif sample_hillshade.png sample_modes.png sample_rough.tif "
[ "$listing" = "$expected" ] || { echo "sample.sh left: $listing(expected: $expected)"; exit 1; }
gdalinfo "$out/sample_modes.png" | grep -q "Size is 1046, 257" || { echo "sample_modes.png is not 4 hillshades"; exit 1; }
echo "sample_outputs: $listing"
