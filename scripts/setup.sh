#!/usr/bin/env bash
# The README's first command: install, build, and fill the bundled sample DEM.
# Leaves out/sample_filled.tif, its hillshade out/sample_hillshade.png, and
# out/sample_modes.png: the voids and the three fill modes side by side.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
bash "$root/scripts/install-python.sh"  # import mcmd from /usr/bin/python3
bash "$root/scripts/sample.sh" "$root/out"
echo "filled: out/sample_filled.tif   hillshade: out/sample_hillshade.png"
echo "the modes side by side (voids, default, -rs auto, -morph auto): out/sample_modes.png"
