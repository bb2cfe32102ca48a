# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""Centerlines from lists, files and segmentations: the same trees the modules read and extract."""
import numpy as np
import pytest

import vesselreformation as vr

from conftest import run_module


def test_read_centerlines_gives_vmtks_tree_in_lps(aorta):
    centerlines = vr.read_centerlines(aorta / "aorta-centerline.vtp")
    assert "RAS" in centerlines.source and centerlines.has_radii
    lps = np.concatenate([branch["points"] for branch in centerlines.branches()])
    ras = np.concatenate([branch["points"] for branch in centerlines.branches(space="RAS")])
    np.testing.assert_array_equal(ras, lps * [-1, -1, 1])
    # VMTK's points land on lumen voxels once in LPS (the data's README): sample the volume at them.
    volume = vr.read_volume(aorta / "aorta.mha")
    index = np.rint((lps - volume.origin) @ np.linalg.inv(volume.direction * volume.spacing).T).astype(int)
    values = volume.array[index[:, 2], index[:, 1], index[:, 0]]
    assert np.median(values) > 1500.0
    with pytest.raises(OSError, match="nothing.vtp"):
        vr.read_centerlines(aorta / "nothing.vtp")


def test_extract_centerlines_matches_the_module(aorta, modules, output):
    segmentation = vr.read_segmentation(aorta / "aorta-final-levelset.mha")
    extracted = vr.extract_centerlines(segmentation)
    run_module(modules, "ExtractCenterlines", aorta / "aorta-final-levelset.mha", output / "module.vtp")
    module = vr.read_centerlines(output / "module.vtp")
    assert len(extracted) == len(module) >= 2
    for mine, theirs in zip(extracted.branches(), module.branches()):
        np.testing.assert_allclose(mine["points"], theirs["points"], atol=1e-9)
        np.testing.assert_allclose(mine["radii"], theirs["radii"], atol=1e-9)


def test_segmentation_from_a_label_array_and_a_folder_of_masks(aorta, output):
    levelset = vr.read_volume(aorta / "aorta-final-levelset.mha")
    from_volume = vr.Segmentation.from_volume(levelset)
    from_file = vr.read_segmentation(aorta / "aorta-final-levelset.mha")
    np.testing.assert_array_equal(from_volume.mask, from_file.mask)
    # A TotalSegmentator-like folder: one mask per vessel, named after it; the branches take the names.
    mask = from_file.mask
    half = mask.shape[1] // 2
    upper, lower = mask.copy(), mask.copy()
    upper[:, half:, :] = 0
    lower[:, :half, :] = 0
    folder = output / "segmentations"
    folder.mkdir()
    for name, part in (("aorta", upper), ("iliac_arteries", lower), ("liver", np.zeros_like(mask))):
        vr.write_volume(vr.Volume(part, spacing=levelset.spacing, origin=levelset.origin,
                                  direction=levelset.direction), folder / f"{name}.nii.gz")
    chosen = vr.read_segmentation(folder, vessels=["aorta", "iliac_arteries"])
    assert chosen.region_names == ["aorta", "iliac arteries"]
    np.testing.assert_array_equal(chosen.mask, mask)
    names = {branch["name"] for branch in vr.extract_centerlines(chosen).branches()}
    assert names <= {"aorta", "iliac arteries"} and names
    with pytest.raises(OSError, match="no file for kidney"):
        vr.read_segmentation(folder, vessels=["aorta", "kidney"])


def test_bad_centerlines_raise_value_error(aorta):
    with pytest.raises(ValueError, match=r"^centerlines: the list is empty"):
        vr.Centerlines([])
    with pytest.raises(ValueError, match=r"^centerlines: branch 1: radii must give one radius"):
        vr.Centerlines([np.zeros((3, 3)), {"points": np.ones((4, 3)), "radii": [1.0, 2.0]}])
    with pytest.raises(ValueError, match=r"^centerlines: branch 0: point 1 is not finite"):
        vr.Centerlines([[[0, 0, 0], [0, np.nan, 1]]])
    with pytest.raises(ValueError, match=r"^space: give \"LPS\""):
        vr.Centerlines([np.zeros((3, 3))], space="auto")
    with pytest.raises(ValueError, match=r"^segmentation: give a Segmentation"):
        vr.extract_centerlines(np.zeros((3, 3, 3)))
