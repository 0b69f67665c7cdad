"""The package as a user installs it: pip into a fresh venv and a wheel, and
the .pth route of scripts/install-python.sh, which must not reach other
Pythons (pyenv's shares the user site folder and has no numpy)."""
import glob
import os
import subprocess
import sys

import numpy as np
import pytest

import mcmd
from conftest import REPO

PACKAGE = os.path.dirname(os.path.dirname(mcmd.__file__))  # the build's python/ folder
BUILD = os.path.dirname(PACKAGE)                            # its CMake build tree
CHECK = ("import os, sys, numpy as np, mcmd; a = np.array([[5, 6, 7], [8, -1, 9]], np.int16); "
         "print(os.path.dirname(mcmd.__file__)); print(mcmd.fill(a, nodata=-1).tobytes().hex())")


def run(cmd, **kw):
    p = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, timeout=600, **kw)
    assert p.returncode == 0, p.stdout + p.stderr
    return p.stdout


def check(python, inside, env=None):
    """Imports mcmd from `inside` (from /, not the checkout) and fills as the build does."""
    folder, filled = run([python, "-c", CHECK], cwd="/", env=env).split()
    want = mcmd.fill(np.array([[5, 6, 7], [8, -1, 9]], np.int16), nodata=-1).tobytes().hex()
    assert folder.startswith(str(inside)) and filled == want


def test_pip_install_into_a_venv_and_a_wheel(tmp_path):
    # The build tree of this test run is reused (MCMD_CMAKE_BUILD_DIR): pip
    # builds only what is missing of the target _mcmd.
    env = dict(os.environ, MCMD_CMAKE_BUILD_DIR=BUILD, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    env.pop("PYTHONPATH")
    venv = tmp_path / "venv"
    run([sys.executable, "-m", "venv", "--system-site-packages", venv], env=env)
    run([venv / "bin" / "pip", "install", "-q", "--no-build-isolation", REPO], env=env)
    check(venv / "bin" / "python", venv, env)
    run([venv / "bin" / "pip", "wheel", "-q", "--no-build-isolation", "--no-deps", "-w", tmp_path / "dist", REPO],
        env=env)
    wheel, = glob.glob(str(tmp_path / "dist" / "mcmd-*.whl"))
    other = tmp_path / "other"
    run([sys.executable, "-m", "venv", "--system-site-packages", other], env=env)
    run([other / "bin" / "pip", "install", "-q", wheel], env=env)
    check(other / "bin" / "python", other, env)


def test_pth_route_leaves_other_pythons_alone(tmp_path):
    env = dict(os.environ, PYTHONUSERBASE=str(tmp_path / "user"))
    env.pop("PYTHONPATH")
    run(["bash", os.path.join(REPO, "scripts", "install-python.sh"), PACKAGE], env=env)
    check("/usr/bin/python3", PACKAGE, env)  # through the .pth file alone
    others = sorted(glob.glob(os.path.expanduser("~/.pyenv/versions/3.11*/bin/python3")))
    if not others:
        pytest.skip("no other Python 3.11 here (pyenv's) to share the user site folder")
    p = subprocess.run([others[-1], "-c", "import mcmd"], capture_output=True, text=True, env=env, cwd="/")
    assert "No module named 'mcmd'" in p.stderr, p.stderr  # not found, rather than found and broken
