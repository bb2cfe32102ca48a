# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""What the Python tests share: where the data, the modules and the outputs are (CTest passes them in the
environment, Testing/Python/CMakeLists.txt), a fresh folder per test, and a plain NRRD reader independent of the
package (the modules' outputs are read with it, so that a comparison does not read both sides through the engine)."""
import gzip
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest


def _environment(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"{name} is not set: run the Python tests through CTest (Testing/Python/CMakeLists.txt)")
    return pathlib.Path(value)


@pytest.fixture(scope="session")
def aorta():
    """VMTK's aorta MRA folder (Testing/Data/vmtk-aorta-mra)."""
    folder = _environment("VR_TEST_DATA_DIR")
    assert (folder / "aorta.mha").exists(), f"VMTK's aorta is missing from {folder}"
    return folder


@pytest.fixture(scope="session")
def modules():
    """The command-line modules' folder (build/cli-modules)."""
    return _environment("VR_CLI_MODULES_DIR")


@pytest.fixture
def output(request):
    """An empty folder for this test under VR_TEST_OUTPUT_DIR."""
    folder = _environment("VR_TEST_OUTPUT_DIR") / request.node.name
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    return folder


def run_module(modules, name, *arguments):
    """Runs a command-line module; fails the test with its output when it fails."""
    completed = subprocess.run([str(modules / name), *map(str, arguments)], capture_output=True, text=True)
    assert completed.returncode == 0, f"{name} failed ({completed.returncode}):\n{completed.stdout}\n{completed.stderr}"
    return completed


def read_returns(path):
    """A module's --returnparameterfile: {name: text}."""
    values = {}
    for line in pathlib.Path(path).read_text().splitlines():
        if "=" in line:
            name, value = (part.strip() for part in line.split("=", 1))
            values[name] = value
    return values


_NRRD_TYPES = {"float": "f4", "double": "f8", "uchar": "u1", "unsigned char": "u1", "uint8": "u1",
               "short": "i2", "int16": "i2", "ushort": "u2", "unsigned short": "u2", "int": "i4", "int32": "i4",
               "uint": "u4", "unsigned int": "u4", "uint32": "u4"}


def read_nrrd(path):
    """A plain NRRD reader (attached header, raw or gzip encoding): the voxels as an array indexed like numpy
    (slowest axis first) and the header fields."""
    data = pathlib.Path(path).read_bytes()
    end = data.index(b"\n\n")
    fields = {}
    for line in data[:end].decode("latin-1").splitlines()[1:]:
        if line.startswith("#") or ":" not in line:
            continue
        key, value = line.split(":", 1)
        fields[key.strip()] = value.lstrip("=").strip()
    payload = data[end + 2:]
    if fields.get("encoding") in ("gzip", "gz"):
        payload = gzip.decompress(payload)
    else:
        assert fields.get("encoding") == "raw", f"{path}: encoding {fields.get('encoding')} is not read here"
    dtype = np.dtype(_NRRD_TYPES[fields["type"]]).newbyteorder("<" if fields.get("endian", "little") == "little"
                                                                 else ">")
    sizes = [int(size) for size in fields["sizes"].split()]
    array = np.frombuffer(payload, dtype=dtype, count=int(np.prod(sizes)))
    return array.reshape(sizes[::-1]), fields
