#!/usr/bin/env bash
# The end of the README's first command (scripts/setup.sh): fill the bundled
# sample DEM three ways and draw them. OUT_DIR (default out/) gets
# sample_filled.tif (the default fill), sample_rough.tif (-rs auto),
# sample_drainage.tif (-morph auto), sample_hillshade.png (the default fill's
# hillshade) and sample_modes.png (the voids and the three modes side by
# side), and nothing else: the single hillshades, with the .aux.xml files
# gdaldem writes beside them, are made in a temporary folder.
# Usage: sample.sh [OUT_DIR]; MCMD_BIN: the folder of mcmd_fillnodata
# (default build/bin).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out=${1:-$root/out}
tool=${MCMD_BIN:-$root/build/bin}/mcmd_fillnodata
sample="$root/testdata/sample_dem.tif"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
rm -f "$out"/sample_*.tif "$out"/sample_*.aux.xml "$out"/.hillshade_*  # and what earlier versions left
"$tool" "$sample" "$out/sample_filled.tif"
"$tool" -q -rs auto "$sample" "$out/sample_rough.tif"
"$tool" -q -morph auto "$sample" "$out/sample_drainage.tif"
shade() { gdaldem hillshade -q -z 2 -compute_edges "$1" "$tmp/$2.png" -of PNG; }
shade "$sample" voids
for mode in filled rough drainage; do shade "$out/sample_$mode.tif" "$mode"; done
cp "$tmp/filled.png" "$out/sample_hillshade.png"
/usr/bin/python3 "$root/scripts/sample_gallery.py" "$out/sample_modes.png" "$tmp/voids.png" "$tmp/filled.png" \
  "$tmp/rough.png" "$tmp/drainage.png"
