#!/usr/bin/env bash
# The README's C example as a reader follows it: its ```c block saved as
# fill.c, then the ```sh block after it run as written (install into
# $HOME/mcmd, pkg-config, cc, ./fill) in a folder holding `build` (the build
# tree) and dem.tif, with no LD_LIBRARY_PATH: the program must find the
# library by itself. Its in-place fill must equal mcmd_fillnodata -rs auto.
# Usage: readme_example.sh README BUILD_DIR WORK_DIR SAMPLE.tif SANITIZERS
set -euo pipefail
readme=$1 build=$2 work=$3 sample=$4 flags=${5:+-fsanitize=$5}
rm -rf "$work" && mkdir -p "$work/home"
ln -s "$(cd "$build" && pwd)" "$work/build"
# The first ```c block, and the first ```sh block after it.
awk '/^```c$/ {on = 1; next} on && /^```$/ {exit} on' "$readme" > "$work/fill.c"
awk '/^```c$/ {seen = 1} seen && /^```sh$/ {on = 1; next} on && /^```$/ {exit} on' "$readme" > "$work/commands.sh"
grep -q 'MCMDFillNodata' "$work/fill.c" && grep -q 'pkg-config' "$work/commands.sh" ||
  { echo "readme_example: the README's C example or its build commands are missing"; exit 1; }
# A sanitizer build's library needs the sanitizer runtime in the program too.
[ -z "$flags" ] || sed -i "s/^cc /cc $flags /" "$work/commands.sh"
cp "$sample" "$work/dem.tif"
(cd "$work" && env -u LD_LIBRARY_PATH -u PKG_CONFIG_PATH HOME="$work/home" bash -e commands.sh) > "$work/run.log" 2>&1 ||
  { cat "$work/run.log"; exit 1; }
"$build/bin/mcmd_fillnodata" -q -rs auto "$sample" "$work/ref.tif"
for f in dem ref; do gdal_translate -q -of ENVI "$work/$f.tif" "$work/$f.raw"; done
gdal_translate -q -of ENVI "$sample" "$work/sample.raw"
! cmp -s "$work/sample.raw" "$work/ref.raw" || { echo "readme_example: the sample has no void"; exit 1; }
cmp "$work/dem.raw" "$work/ref.raw"
echo "readme_example: the README's C program, built as the README says, fills dem.tif as mcmd_fillnodata -rs auto"
