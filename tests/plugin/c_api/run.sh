#!/usr/bin/env bash
# Install the build into a fresh prefix, build EXAMPLE_DIR/PROGRAM.c against
# it twice (its CMakeLists.txt with find_package(mcmd), then pkg-config), run
# each build on a file and compare the two files. With SAMPLE, each fills a
# copy of it in place; without, each writes its file.
# Usage: run.sh BUILD_DIR WORK_DIR EXAMPLE_DIR PROGRAM SANITIZERS [SAMPLE.tif]
# (SANITIZERS may be empty; a sanitizer build's library needs its runtime in
# the program too).
set -euo pipefail
build=$1 work=$2 example=$3 program=$4 sample=${6:-}
flags=${5:+-fsanitize=$5}
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$example" -B "$work/cmake" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="$flags" > "$work/configure.log"
cmake --build "$work/cmake" > "$work/build.log"
pc_dir=$(dirname "$(find "$work/prefix" -name mcmd.pc | head -1)")
cc $flags "$example/$program.c" -o "$work/${program}_pc" $(PKG_CONFIG_PATH="$pc_dir" pkg-config --cflags --libs mcmd) -lm
if [ -n "$sample" ]; then cp "$sample" "$work/a.tif" && cp "$sample" "$work/b.tif"; fi
"$work/cmake/$program" "$work/a.tif"
# No LD_LIBRARY_PATH: mcmd.pc gives the program the library's folder as its run path.
env -u LD_LIBRARY_PATH "$work/${program}_pc" "$work/b.tif"
cmp "$work/a.tif" "$work/b.tif"
echo "c_api: the installed package builds $program with CMake and with pkg-config, and both agree"
