# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""The package outside the build tree: pip install from the built package folder into a virtual environment without
any registry, and cmake --install into a prefix's Python path."""
import os
import pathlib
import subprocess
import sys

# What the installed package must do, run by the installed interpreter in a folder of its own.
SMOKE = """
import os, sys, numpy as np, vesselreformation as vr
assert os.path.dirname(vr.__file__).startswith(sys.argv[1]), vr.__file__
volume, centerlines, angle = vr.phantom("thorax", spacing=4.0)
result = vr.reform(volume, centerlines, size=(32, 64), iterations=5)
assert result.cpr.shape == (64, 32) and np.isfinite(result.cpr).all()
print("installed package works:", vr.__file__)
"""


def clean_environment():
    environment = dict(os.environ)
    environment.pop("PYTHONPATH", None)
    return environment


def test_pip_install_into_a_virtual_environment_without_a_registry(output):
    package = pathlib.Path(os.environ["VR_PYTHON_PACKAGE_ROOT"])
    environment = output / "env"
    # Debian's numpy and setuptools come from the system's site packages: nothing is downloaded.
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(environment)], check=True)
    completed = subprocess.run(
        [str(environment / "bin" / "pip"), "install", "--no-index", "--no-build-isolation", "--no-cache-dir",
         str(package)], capture_output=True, text=True, env=clean_environment(), cwd=output)
    assert completed.returncode == 0, completed.stdout + completed.stderr
    site = subprocess.run([str(environment / "bin" / "python"), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                          capture_output=True, text=True, check=True).stdout.strip()
    completed = subprocess.run([str(environment / "bin" / "python"), "-c", SMOKE, site], capture_output=True,
                               text=True, env=clean_environment(), cwd=output)
    assert completed.returncode == 0, completed.stdout + completed.stderr


def test_cmake_install_puts_the_package_in_the_prefix_python_path(output):
    prefix = output / "prefix"
    completed = subprocess.run(["cmake", "--install", os.environ["VR_BUILD_DIR"], "--prefix", str(prefix)],
                               capture_output=True, text=True)
    assert completed.returncode == 0, completed.stdout + completed.stderr
    site = prefix / os.environ["VR_PYTHON_INSTALL_DIR"]
    assert (site / "vesselreformation" / "__init__.py").exists()
    environment = clean_environment()
    environment["PYTHONPATH"] = str(site)
    completed = subprocess.run([sys.executable, "-c", SMOKE, str(site)], capture_output=True, text=True,
                               env=environment, cwd=output)
    assert completed.returncode == 0, completed.stdout + completed.stderr
