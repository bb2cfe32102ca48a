# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""Volumes from numpy: viewed or copied once, LPS metadata and nibabel's affine, bad arguments named."""
import numpy as np
import pytest

import vesselreformation as vr


def test_c_contiguous_float32_is_viewed_and_its_address_reaches_the_engine():
    array = np.zeros((20, 30, 40), dtype=np.float32)
    volume = vr.Volume(array, spacing=(1.0, 1.0, 2.0))
    assert not volume.copied
    assert volume._buffer_address == array.ctypes.data
    assert np.shares_memory(volume.array, array)
    # A view: a change to the array is what the engine reads.
    array[3, 4, 5] = 7.0
    assert volume.array[3, 4, 5] == 7.0


def test_reform_reads_the_callers_float32_memory():
    volume, centerlines, _ = vr.phantom("thorax", spacing=4.0)
    mine = np.ascontiguousarray(volume.array).copy()
    viewed = vr.Volume(mine, spacing=volume.spacing, origin=volume.origin, direction=volume.direction)
    result = vr.reform(viewed, centerlines, size=(64, 128), iterations=5)
    assert result._engine_volume_address == mine.ctypes.data


@pytest.mark.parametrize("make", [
    lambda a: a[:, :, ::2],                 # strided: not contiguous
    lambda a: np.asfortranarray(a),         # Fortran order, as (k, j, i)
    lambda a: a.astype(np.int16),           # another dtype (CT's int16)
    lambda a: a.astype(np.float64),
], ids=["strided", "fortran-order", "int16", "float64"])
def test_other_arrays_are_copied_once_to_float32_c_order(make):
    base = np.arange(20 * 30 * 40, dtype=np.float32).reshape(20, 30, 40) % 1000
    array = make(base)
    volume = vr.Volume(array)
    assert volume.copied
    assert volume._buffer_address != array.ctypes.data
    assert volume.array.dtype == np.float32 and volume.array.flags["C_CONTIGUOUS"]
    assert not np.shares_memory(volume.array, array)
    # One copy: the engine's buffer is the copy the Volume shows, not a second one.
    assert volume._buffer_address == volume.array.ctypes.data
    np.testing.assert_array_equal(volume.array, array.astype(np.float32))


def test_affine_and_itk_metadata_describe_the_same_grid():
    # A volume with an oblique, flipped grid: ITK's LPS metadata, and the RAS affine nibabel would give it.
    angle = np.deg2rad(20.0)
    rotation = np.array([[np.cos(angle), -np.sin(angle), 0.0], [np.sin(angle), np.cos(angle), 0.0], [0, 0, 1.0]])
    direction = rotation @ np.diag([-1.0, 1.0, 1.0])
    spacing = np.array([0.7, 0.8, 2.5])
    origin = np.array([12.0, -30.0, 55.0])
    lps_to_ras = np.diag([-1.0, -1.0, 1.0])
    affine = np.eye(4)
    affine[:3, :3] = lps_to_ras @ direction @ np.diag(spacing)
    affine[:3, 3] = lps_to_ras @ origin

    array_kji = np.random.default_rng(1).random((6, 7, 8), dtype=np.float32)
    itk_style = vr.Volume(array_kji, spacing=spacing, origin=origin, direction=direction)
    nibabel_style = vr.Volume.from_affine(array_kji.T, affine)   # nibabel's (i, j, k) array
    np.testing.assert_allclose(nibabel_style.spacing, spacing, rtol=1e-12)
    np.testing.assert_allclose(nibabel_style.origin, origin, atol=1e-12)
    np.testing.assert_allclose(nibabel_style.direction, direction, atol=1e-12)
    np.testing.assert_allclose(itk_style.affine, affine, atol=1e-12)
    # nibabel's Fortran-ordered data is the engine's C order: viewed, not copied.
    assert not nibabel_style.copied
    assert nibabel_style._buffer_address == array_kji.ctypes.data


def test_bad_arrays_and_grids_raise_value_error_naming_the_argument():
    good = np.zeros((4, 5, 6), dtype=np.float32)
    with pytest.raises(ValueError, match=r"^array: a volume is a 3-D array .* ndim=2"):
        vr.Volume(np.zeros((4, 5), dtype=np.float32))
    with pytest.raises(ValueError, match=r"^array: dtype complex128"):
        vr.Volume(np.zeros((4, 5, 6), dtype=complex))
    with pytest.raises(ValueError, match=r"^array: axis 1 is empty"):
        vr.Volume(np.zeros((4, 0, 6), dtype=np.float32))
    with pytest.raises(ValueError, match=r"^spacing: .* is not finite"):
        vr.Volume(good, spacing=(1.0, float("nan"), 1.0))
    with pytest.raises(ValueError, match=r"^spacing: .* must be > 0"):
        vr.Volume(good, spacing=(1.0, 0.0, 1.0))
    with pytest.raises(ValueError, match=r"^spacing: expected 3 numbers"):
        vr.Volume(good, spacing=(1.0, 1.0))
    with pytest.raises(ValueError, match=r"^direction: columns 0 and 1 are not orthogonal"):
        vr.Volume(good, direction=[[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    with pytest.raises(ValueError, match=r"^affine: columns 0 and 2 are not orthogonal"):
        vr.Volume.from_affine(good, [[1, 0, 0.3, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    with pytest.raises(ValueError, match=r"^affine: the last row must be 0 0 0 1"):
        vr.Volume.from_affine(good, np.ones((4, 4)))
    nan = good.copy()
    nan[1, 2, 3] = np.nan
    with pytest.raises(ValueError, match=r"^array: voxel \(i, j, k\) = \(3, 2, 1\) is not finite"):
        vr.Volume(nan)


def test_read_volume_and_write_volume(aorta, output):
    volume = vr.read_volume(aorta / "aorta.mha")
    assert volume.shape == (34, 393, 157)
    np.testing.assert_allclose(volume.spacing, (0.878906, 0.878906, 1.50009), rtol=1e-5)
    np.testing.assert_allclose(np.diag(volume.direction), (-1.0, -1.0, 1.0))
    vr.write_volume(volume, output / "copy.nrrd")
    again = vr.read_volume(output / "copy.nrrd")
    np.testing.assert_array_equal(again.array, volume.array)
    with pytest.raises(OSError) as error:
        vr.read_volume(output / "missing.nrrd")
    assert "missing.nrrd" in str(error.value) and error.value.filename.endswith("missing.nrrd")
    (output / "broken.nrrd").write_bytes(b"NRRD0004\ntype: float\ndimension: 3\nsizes: 10 10 10\n"
                                         b"encoding: raw\n\n\x00\x01")
    with pytest.raises(OSError, match="broken.nrrd"):
        vr.read_volume(output / "broken.nrrd")
