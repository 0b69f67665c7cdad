#!/bin/sh
# Install the mcmd_provider QGIS plugin into a QGIS user profile.
#
#   qgis/install.sh [--link] [--cli PATH] [--profile NAME]
#
#   --link          symlink the plugin folder instead of copying it (for development)
#   --cli PATH      also copy this mcmd_fillnodata executable into the plugin's bin/
#                   (it is then found without any setting; default: build/bin/mcmd_fillnodata
#                   when it exists and --link is not given)
#   --profile NAME  QGIS profile (default: default)
#
# QGIS_PLUGINS_DIR overrides the destination folder altogether.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
src="$here/mcmd_provider"
link=0
cli=""
profile=default
while [ $# -gt 0 ]; do
  case "$1" in
    --link) link=1 ;;
    --cli) cli="$2"; shift ;;
    --profile) profile="$2"; shift ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "install.sh: error: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done

case "$(uname -s)" in
  Darwin) base="$HOME/Library/Application Support/QGIS/QGIS3" ;;
  *) base="${XDG_DATA_HOME:-$HOME/.local/share}/QGIS/QGIS3" ;;
esac
dest_dir="${QGIS_PLUGINS_DIR:-$base/profiles/$profile/python/plugins}"
dest="$dest_dir/mcmd_provider"

if [ "$link" -eq 1 ] && [ -n "$cli" ]; then
  echo "install.sh: error: --link with --cli would copy the tool into the source tree;" \
       "set its path in Settings > Options > Processing > Providers > MCMD void fill instead" >&2
  exit 2
fi
if [ -z "$cli" ] && [ "$link" -eq 0 ] && [ -x "$here/../build/bin/mcmd_fillnodata" ]; then
  cli="$here/../build/bin/mcmd_fillnodata"
fi

mkdir -p "$dest_dir"
rm -rf "$dest"
if [ "$link" -eq 1 ]; then
  ln -s "$src" "$dest"
else
  sh "$here/copy_plugin.sh" "$dest" "$cli"
fi
echo "Installed the mcmd_provider plugin in $dest"
echo "Enable it in QGIS: Plugins > Manage and Install Plugins > Installed > MCMD void fill"
echo "(headless: qgis_process plugins enable mcmd_provider)"
