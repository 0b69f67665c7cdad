#!/usr/bin/env bash
# Install the build into a fresh prefix, build make_terrain.c against it
# twice (CMake package, pkg-config) and compare what the two make.
# Usage: run.sh BUILD_DIR WORK_DIR [SANITIZERS]
# (a sanitizer build's library needs its runtime in the program too).
set -euo pipefail
build=$1 work=$2
flags=${3:+-fsanitize=$3}
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$here" -B "$work/cmake" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="$flags" > "$work/configure.log"
cmake --build "$work/cmake" > "$work/build.log"
"$work/cmake/make_terrain" "$work/a.tif"
pc_dir=$(dirname "$(find "$work/prefix" -name mcmd.pc | head -1)")
lib_dir=$(dirname "$(find "$work/prefix" -name 'libmcmd_gdal.so' | head -1)")
cc $flags "$here/make_terrain.c" -o "$work/make_terrain_pc" $(PKG_CONFIG_PATH="$pc_dir" pkg-config --cflags --libs mcmd) -lm
LD_LIBRARY_PATH="$lib_dir" "$work/make_terrain_pc" "$work/b.tif"
cmp "$work/a.tif" "$work/b.tif"
echo "terrain c_api: the installed package makes terrains with CMake and with pkg-config"
