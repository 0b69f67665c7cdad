#!/bin/sh
# Copy the plugin folder (without Python caches) to DEST, and the optional
# mcmd_fillnodata executable CLI into DEST/bin/. Shared by install.sh and make_zip.sh.
#
#   qgis/copy_plugin.sh DEST [CLI]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
dest="$1"
cli="${2:-}"
mkdir -p "$dest"
(cd "$here/mcmd_provider" && find . -name __pycache__ -prune -o -type f ! -name '*.pyc' -print) |
  while IFS= read -r f; do
    mkdir -p "$dest/$(dirname "$f")"
    cp "$here/mcmd_provider/$f" "$dest/$f"
  done
if [ -n "$cli" ]; then
  [ -x "$cli" ] || { echo "copy_plugin.sh: error: $cli is not an executable" >&2; exit 1; }
  mkdir -p "$dest/bin"
  cp "$cli" "$dest/bin/mcmd_fillnodata"
  chmod 755 "$dest/bin/mcmd_fillnodata"
  # mcmd:terrain runs mcmd_terrain, found beside mcmd_fillnodata.
  if [ -x "$(dirname "$cli")/mcmd_terrain" ]; then
    cp "$(dirname "$cli")/mcmd_terrain" "$dest/bin/mcmd_terrain"
    chmod 755 "$dest/bin/mcmd_terrain"
  fi
fi
