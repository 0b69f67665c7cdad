#!/usr/bin/env bash
# The README's first command: install, build, and fill the bundled sample DEM.
# Leaves out/sample_filled.tif, its hillshade out/sample_hillshade.png, and
# out/sample_modes.png: the voids and the three fill modes side by side.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
bash "$root/scripts/install-python.sh"  # import mcmd from /usr/bin/python3
out="$root/out"
mkdir -p "$out"
rm -f "$out"/sample_*.tif
tool="$root/build/bin/mcmd_fillnodata"
"$tool" "$root/testdata/sample_dem.tif" "$out/sample_filled.tif"
"$tool" -q -rs auto "$root/testdata/sample_dem.tif" "$out/sample_rough.tif"
"$tool" -q -morph auto "$root/testdata/sample_dem.tif" "$out/sample_drainage.tif"
gdaldem hillshade -q -z 2 -compute_edges "$out/sample_filled.tif" "$out/sample_hillshade.png" -of PNG
# The modes side by side: the voids, the smooth default, -rs auto, -morph auto.
for mode in voids rough drainage; do
  src="$out/sample_$mode.tif"
  [ "$mode" = voids ] && src="$root/testdata/sample_dem.tif"
  gdaldem hillshade -q -z 2 -compute_edges "$src" "$out/.hillshade_$mode.png" -of PNG
done
/usr/bin/python3 "$root/scripts/sample_gallery.py" "$out/sample_modes.png" "$out/.hillshade_voids.png" \
  "$out/sample_hillshade.png" "$out/.hillshade_rough.png" "$out/.hillshade_drainage.png"
rm -f "$out"/.hillshade_*.png "$out"/*.aux.xml
echo "filled: out/sample_filled.tif   hillshade: out/sample_hillshade.png"
echo "the modes side by side (voids, default, -rs auto, -morph auto): out/sample_modes.png"
