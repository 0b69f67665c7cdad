#!/bin/sh
# The accuracy benchmark's peers, from Debian: GRASS GIS (r.fillnulls,
# v.surf.rst, r.resamp.bspline) and SAGA GIS (saga_cmd grid_tools), plus
# scipy for bench/peers.py's hole labelling. Run by bench/run_accuracy.sh
# when one of them is missing; as root or with sudo.
set -e
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq grass-core saga python3-scipy >/dev/null
echo "install_peers: $(grass --version 2>&1 | head -1), $(saga_cmd --version 2>&1 | grep -i version | head -1)"
