#!/usr/bin/env bash
# Make the Python package built in build/python/mcmd (or the folder given)
# importable by the system Python: a mcmd.pth file in the user's
# site-packages adds that folder to sys.path, so a rebuild
# (scripts/build.sh) updates the package without installing again. The
# user site folder is shared by every Python of that version (pyenv's
# 3.11 too), so the line only acts in Debian's Python (sys.base_prefix
# /usr, which has numpy and GDAL); others do not see the package.
# Run by scripts/setup.sh; under sudo, registers it for the user who ran sudo
# too. The last checkout set up wins. Undo: rm "$(/usr/bin/python3 -m site --user-site)/mcmd.pth"
# A venv or a wheel: pip (docs/python.md).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
python=/usr/bin/python3
package="$(cd "${1:-$root/build/python}" 2>/dev/null && pwd || echo "${1:-$root/build/python}")"
if ! ls "$package"/mcmd/_mcmd.*.so >/dev/null 2>&1; then
  echo "install-python: $package/mcmd was not built (see cmake's 'Python package mcmd' line); skipped"
  exit 0
fi
prefix="$("$python" -c 'import sys; print(sys.base_prefix)')"

# register [sudo -u USER]: writes that user's mcmd.pth and imports mcmd from /.
register() {
  local site
  if [ "$("$@" "$python" -c 'import site; print(site.ENABLE_USER_SITE)')" != "True" ]; then
    echo "install-python: $python has no user site-packages here; use PYTHONPATH=$package" >&2
    return 1
  fi
  site="$("$@" "$python" -m site --user-site)"
  "$@" mkdir -p "$site"
  echo "import sys; sys.base_prefix == '$prefix' and sys.path.append('$package')" | "$@" tee "$site/mcmd.pth" >/dev/null
  (cd / && "$@" "$python" -c 'import mcmd')
  echo "install-python: $python imports mcmd from $package ($site/mcmd.pth)"
}

register
if [ "$(id -u)" -eq 0 ] && [ -n "${SUDO_USER:-}" ] && [ "$SUDO_USER" != root ]; then
  register sudo -u "$SUDO_USER" -H
fi
