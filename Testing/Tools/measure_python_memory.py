#!/usr/bin/env python3
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""Peak resident memory of reform() from Python against the VesselReformation module on the same volume (issue 41:
"no copy of the volume"). A synthetic CT of 512 x 512 x 600 int16 voxels (two contrast-filled tubes in soft tissue)
and its centerlines are written once; then each run is a fresh process whose peak RSS (getrusage's ru_maxrss, or
/usr/bin/time's for the module) is reported:
  module        VesselReformation on the int16 NRRD (it reads the volume as float32)
  python-int16  the int16 array in Python, Volume() copies it once to float32, reform()
  python-float  a float32 array in Python, viewed, reform()
  python-bare   Python with numpy and the package imported, nothing else (the interpreter's own share)

Usage: PYTHONPATH=build/python python3 measure_python_memory.py --modules build/cli-modules --work /tmp/x
"""
import argparse
import json
import os
import resource
import subprocess
import sys

import numpy as np

SHAPE = (600, 512, 512)            # (k, j, i)
SPACING = (0.7, 0.7, 0.8)          # (i, j, k) mm
REFORM = dict(size=(512, 1024), iterations=200, up="S", angle=30.0)


def centerline_branches():
    """Two vessels (LPS mm): one along the volume's axis, one leaving it at an angle."""
    k = np.linspace(20, SHAPE[0] - 20, 200)
    trunk = np.stack([np.full_like(k, 256 * SPACING[0]), np.full_like(k, 256 * SPACING[1]), k * SPACING[2]], axis=1)
    t = np.linspace(0, 1, 120)
    side = np.stack([(256 + 150 * t) * SPACING[0], (256 + 40 * t) * SPACING[1], (300 + 200 * t) * SPACING[2]], axis=1)
    return [{"points": trunk, "radii": np.full(len(trunk), 6.0)}, {"points": side, "radii": np.full(len(side), 4.0)}]


def make_volume():
    """The int16 CT, slice by slice (the tubes' lumen 350 HU in tissue of 40 HU)."""
    volume = np.full(SHAPE, 40, dtype=np.int16)
    j, i = np.mgrid[0:SHAPE[1], 0:SHAPE[2]]
    for branch in centerline_branches():
        points = branch["points"] / SPACING
        for k in range(SHAPE[0]):
            near = points[np.abs(points[:, 2] - k) < 1.0]
            for point in near:
                inside = (i - point[0]) ** 2 + (j - point[1]) ** 2 < (branch["radii"][0] / SPACING[0]) ** 2
                volume[k][inside] = 350
    return volume


def write_nrrd(array, path):
    with open(path, "wb") as file:
        file.write(("NRRD0004\ntype: short\ndimension: 3\nspace: left-posterior-superior\n"
                    f"sizes: {SHAPE[2]} {SHAPE[1]} {SHAPE[0]}\n"
                    f"space directions: ({SPACING[0]},0,0) (0,{SPACING[1]},0) (0,0,{SPACING[2]})\n"
                    "space origin: (0,0,0)\nendian: little\nencoding: raw\n\n").encode())
        file.write(array.astype("<i2").tobytes())


def child(kind, work):
    import vesselreformation as vr
    if kind == "python-bare":
        pass
    else:
        if kind == "python-int16":
            array = np.fromfile(os.path.join(work, "ct.raw"), dtype="<i2").reshape(SHAPE)
        else:
            # Filled slice by slice: no int16 copy of the whole volume beside it.
            array = np.empty(SHAPE, dtype=np.float32)
            with open(os.path.join(work, "ct.raw"), "rb") as file:
                for k in range(SHAPE[0]):
                    array[k] = np.fromfile(file, dtype="<i2", count=SHAPE[1] * SHAPE[2]).reshape(SHAPE[1:])
        volume = vr.Volume(array, spacing=SPACING)
        result = vr.reform(volume, vr.read_centerlines(os.path.join(work, "centerlines.vtp")), **REFORM)
        assert result.cpr.shape == (1024, 512)
    print(json.dumps({"kind": kind, "own_peak_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0}))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--modules", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--child", help=argparse.SUPPRESS)
    parser.add_argument("--repeat", type=int, default=2)
    options = parser.parse_args()
    if options.child:
        child(options.child, options.work)
        return
    os.makedirs(options.work, exist_ok=True)
    import vesselreformation as vr
    if not os.path.exists(os.path.join(options.work, "ct.nrrd")):
        volume = make_volume()
        volume.tofile(os.path.join(options.work, "ct.raw"))
        write_nrrd(volume, os.path.join(options.work, "ct.nrrd"))
        vr.Centerlines(centerline_branches()).write(os.path.join(options.work, "centerlines.vtp"))
        del volume
    results = {}
    time_log = os.path.join(options.work, "time.txt")
    for _ in range(options.repeat):
        for kind in ("module", "python-int16", "python-float", "python-bare"):
            # Every run under /usr/bin/time, a small process: Linux keeps a process's peak RSS across exec, so a
            # child started from this (large) process directly would report this one's peak.
            if kind == "module":
                command = [os.path.join(options.modules, "VesselReformation"), os.path.join(options.work, "ct.nrrd"),
                           os.path.join(options.work, "centerlines.vtp"), os.path.join(options.work, "cpr.nrrd"),
                           "--size", "512,1024", "--iterations", "200", "--up", "S", "--angle", "30"]
            else:
                command = [sys.executable, __file__, "--modules", options.modules, "--work", options.work, "--child",
                           kind]
            subprocess.run(["/usr/bin/time", "-v", "-o", time_log] + command, check=True, capture_output=True)
            peak = [int(line.split(":")[1]) for line in open(time_log) if "Maximum resident" in line][0] / 1024.0
            results.setdefault(kind, []).append(peak)
    volume_mib = np.prod(SHAPE) * 2 / 2**20
    print(f"volume {SHAPE[2]} x {SHAPE[1]} x {SHAPE[0]} int16: {volume_mib:.0f} MiB (float32: {2 * volume_mib:.0f} MiB)")
    module = min(results["module"])
    for kind, peaks in results.items():
        print(f"{kind:13s} peak RSS {min(peaks):7.0f} MiB (runs: {', '.join(f'{p:.0f}' for p in peaks)})"
              f"  {min(peaks) / module:5.2f} x the module's")


if __name__ == "__main__":
    main()
