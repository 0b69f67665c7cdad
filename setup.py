"""pip's build of the package mcmd: the extension mcmd._mcmd is built by this
repository's CMake project (target _mcmd, for the Python running pip) and
copied beside python/mcmd/*.py. Nothing is downloaded: CMake, a C++20
compiler, GDAL, numpy and pybind11 come from Debian (scripts/install-deps.sh).

MCMD_CMAKE_BUILD_DIR=DIR builds in DIR, a configured build tree used as it
is (its Python, type and options); default: build-pip/ beside this file,
configured for the Python running pip and kept between builds. MCMD_BUILD_JOBS
sets the parallel jobs (default: the CPU count).
"""
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


def version() -> str:
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        return re.search(r"project\(mcmd\s+VERSION\s+([0-9.]+)", f.read()).group(1)


def base_python() -> str:
    """The interpreter that the venv running pip was made from (the module
    links against its headers; a venv's python is a link to it)."""
    return os.path.realpath(getattr(sys, "_base_executable", sys.executable))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        given = os.environ.get("MCMD_CMAKE_BUILD_DIR")
        build = given or os.path.join(ROOT, "build-pip")
        jobs = os.environ.get("MCMD_BUILD_JOBS") or str(os.cpu_count() or 1)
        if not (given and os.path.exists(os.path.join(given, "CMakeCache.txt"))):
            subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                            f"-DMCMD_PYTHON={base_python()}"], check=True, stdout=subprocess.DEVNULL)
        subprocess.run(["cmake", "--build", build, "--target", "_mcmd", "-j", jobs], check=True)
        built = [f for f in os.listdir(os.path.join(build, "python", "mcmd")) if f.startswith("_mcmd.")]
        if not built:
            sys.exit(f"mcmd: CMake built no module in {build}/python/mcmd (see its 'Python package mcmd' line)")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(build, "python", "mcmd", built[0]), target)


setup(
    version=version(),
    packages=["mcmd", "mcmd.dask"],
    package_dir={"": "python"},
    package_data={"mcmd": ["*.pyi", "py.typed"], "mcmd.dask": ["*.pyi"]},
    ext_modules=[Extension("mcmd._mcmd", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
    options={"build": {"build_base": os.path.join("build-pip", "setuptools")},
             "egg_info": {"egg_base": "build-pip"}},
)
