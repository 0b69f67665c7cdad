#!/bin/sh
# Build a zip for QGIS's Plugins > Manage and Install Plugins > Install from ZIP.
#
#   qgis/make_zip.sh [OUTPUT.zip] [--cli PATH]
#
# Default output: build/mcmd_provider.zip (at the repository root). The zip holds the
# top folder mcmd_provider/. With --cli, the mcmd_fillnodata executable is bundled as
# mcmd_provider/bin/mcmd_fillnodata (only useful on machines like the one it was built on).
set -eu

here=$(cd "$(dirname "$0")" && pwd)
out="$here/../build/mcmd_provider.zip"
cli=""
while [ $# -gt 0 ]; do
  case "$1" in
    --cli) cli="$2"; shift ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) out="$1" ;;
  esac
  shift
done

mkdir -p "$(dirname "$out")"
out=$(cd "$(dirname "$out")" && pwd)/$(basename "$out")
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT INT TERM
sh "$here/copy_plugin.sh" "$stage/mcmd_provider" "$cli"
rm -f "$out"
# Python's zipfile is everywhere QGIS is; the zip command is not.
(cd "$stage" && /usr/bin/env python3 - "$out" <<'PY'
import os, sys, zipfile
out = sys.argv[1]
with zipfile.ZipFile(out, 'w', zipfile.ZIP_DEFLATED) as z:
    for root, dirs, files in os.walk('mcmd_provider'):
        dirs.sort()
        z.write(root)
        for name in sorted(files):
            path = os.path.join(root, name)
            info = zipfile.ZipInfo.from_file(path)
            info.compress_type = zipfile.ZIP_DEFLATED
            with open(path, 'rb') as f:
                z.writestr(info, f.read())
PY
)
echo "$out"
