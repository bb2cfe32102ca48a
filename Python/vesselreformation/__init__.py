# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""VesselReformation from Python: multipath curved planar reformation (mpCPR) of vessel trees with bilateral depth
filtering, and the reading of one vessel (straightened CPR, cross-sections, lumen, stenosis), on the same C++ engine
as the command-line modules.

    import vesselreformation as vr
    volume, centerlines, angle = vr.phantom("runoff")
    result = vr.reform(volume, centerlines, angle=angle, size=(256, 512))
    result.cpr                      # numpy float32 (row, column), the volume's intensities
    result.to_patient(128, 256)     # LPS mm of that pixel on the cut surface

Volumes are numpy arrays with their grid: Volume(array_kji, spacing=..., origin=..., direction=...) in LPS as ITK and
SimpleITK give them, or Volume.from_affine(array_ijk, affine) as nibabel gives them (RAS). A float32 C-contiguous
array is viewed, not copied; any other is copied once to float32. Centerlines are a list of branches (N x 3 points,
optional radii and names) or read from any file the modules read. Errors: ValueError for a bad argument (the message
names it), OSError for a file; Cancelled when a progress callback returned False. The engine runs without the GIL.
"""
import os as _os

from ._engine import (Cancelled, Centerlines, ReformResult, Segmentation, VesselPathResult, Volume,
                      extract_centerlines, phantom, read_centerlines, read_volume, reform, vessel_path,
                      write_volume)
from ._engine import _read_segmentation

__all__ = ["Cancelled", "Centerlines", "ReformResult", "Segmentation", "VesselPathResult", "Volume",
           "extract_centerlines", "phantom", "read_centerlines", "read_segmentation", "read_volume", "reform",
           "vessel_path", "write_volume"]

# Files a segmentation folder may hold (TotalSegmentator writes one .nii.gz per structure).
_SEGMENTATION_EXTENSIONS = (".nii.gz", ".nii", ".nrrd", ".nhdr", ".mha", ".mhd")


def read_segmentation(paths, labels=(), vessels=None):
    """Reads a vessel segmentation as the command-line modules do, and returns a Segmentation.

    paths    a file (label map, mask, VMTK level set, probability map), a list of files combined into one vessel
             mask (each file's vessel voxels on the first file's grid), or a folder of masks such as
             TotalSegmentator's output, of which `vessels` chooses the files (names without extension, e.g.
             ["aorta", "iliac_artery_left", "iliac_artery_right"]; None: every segmentation file in the folder).
    labels   the label values that are vessel in a label map (default: every non-zero voxel).

    Each file's voxels stay a named region, so extract_centerlines() names the branches after the files.
    Raises OSError naming a file that cannot be read, or a folder without the vessels asked for.
    """
    if isinstance(paths, (str, _os.PathLike)) and _os.path.isdir(paths):
        folder = _os.fspath(paths)
        names = sorted(name for name in _os.listdir(folder) if name.endswith(_SEGMENTATION_EXTENSIONS))
        if vessels is not None:
            stems = {_stem(name): name for name in names}
            missing = [vessel for vessel in vessels if vessel not in stems]
            if missing:
                raise OSError(f"segmentation folder {folder}: no file for {', '.join(missing)} "
                              f"(it holds {', '.join(sorted(stems)) or 'no segmentation file'})")
            names = [stems[vessel] for vessel in vessels]
        if not names:
            raise OSError(f"segmentation folder {folder}: no segmentation file "
                          f"({', '.join(_SEGMENTATION_EXTENSIONS)})")
        paths = [_os.path.join(folder, name) for name in names]
    elif vessels is not None:
        raise ValueError("vessels: chooses files of a segmentation folder; paths is not a folder")
    return _read_segmentation(paths, list(labels))


def _stem(name):
    for extension in _SEGMENTATION_EXTENSIONS:
        if name.endswith(extension):
            return name[: -len(extension)]
    return name
