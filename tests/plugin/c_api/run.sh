#!/usr/bin/env bash
# Install the build into a fresh prefix, then build fill_voids.c against it
# twice (CMake package, pkg-config) and fill a copy of a sample with each.
# Usage: run.sh BUILD_DIR WORK_DIR SAMPLE.tif [SANITIZERS]
# (a sanitizer build's library needs its runtime in the program too).
set -euo pipefail
build=$1 work=$2 sample=$3
flags=${4:+-fsanitize=$4}
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$here" -B "$work/cmake" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="$flags" > "$work/configure.log"
cmake --build "$work/cmake" > "$work/build.log"
cp "$sample" "$work/a.tif"
"$work/cmake/fill_voids" "$work/a.tif"
pc_dir=$(dirname "$(find "$work/prefix" -name mcmd.pc | head -1)")
lib_dir=$(dirname "$(find "$work/prefix" -name 'libmcmd_gdal.so' | head -1)")
cc $flags "$here/fill_voids.c" -o "$work/fill_voids_pc" $(PKG_CONFIG_PATH="$pc_dir" pkg-config --cflags --libs mcmd)
cp "$sample" "$work/b.tif"
LD_LIBRARY_PATH="$lib_dir" "$work/fill_voids_pc" "$work/b.tif"
cmp "$work/a.tif" "$work/b.tif"
echo "c_api: the installed package builds and fills with CMake and with pkg-config"
