#!/usr/bin/env bash
# Install every Debian 12 package mcmd needs to build, test and benchmark.
set -euo pipefail
packages=(
  build-essential cmake git pkg-config            # C++20 toolchain (GCC 12), CMake >= 3.25
  libgdal-dev gdal-bin python3-gdal python3-numpy  # GDAL 3.6 + PROJ 9, CLI tools, Python bindings
  python3-numba                                    # JIT flow routing of bench/hydrology.py
  libgtest-dev googletest                          # GoogleTest for ctest
  qgis python3-qgis qgis-providers python3-pytest  # the QGIS Processing provider and its tests
  pybind11-dev python3-dev                         # the Python package mcmd (python/)
  python3-venv python3-pip python3-setuptools python3-wheel  # its pip build (pyproject.toml)
  python3-dask python3-distributed python3-xarray  # mcmd.dask: region-scale fills on Dask
  python3-rioxarray python3-rasterio python3-zarr  #   its reader/writer (GeoTIFF, Zarr)
  time zip                                         # /usr/bin/time -v for benchmarks, plugin zip
)
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq "${packages[@]}" >/dev/null
echo "install-deps: ${#packages[@]} packages present"
