# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""vessel_path(): one vessel of the phantoms and of VMTK's aorta, its lumen table and summary, bad branches named."""
import numpy as np
import pytest

import vesselreformation as vr

COLUMNS = ["arc_length_mm", "ras_r_mm", "ras_a_mm", "ras_s_mm", "area_mm2", "equivalent_diameter_mm",
           "min_diameter_mm", "max_diameter_mm", "reference_diameter_mm", "diameter_mm", "inscribed_diameter_mm",
           "reference_area_mm2", "diameter_stenosis_percent", "source", "in_segmentation", "region_clipped", "branch_id"]


def test_the_longest_path_of_the_phantom_with_radii():
    volume, centerlines, _ = vr.phantom("runoff", spacing=3.0)
    result = vr.vessel_path(volume, centerlines, width=30.0)
    assert result.cpr.ndim == 2 and result.cpr.dtype == np.float32
    assert result.cross_sections.ndim == 3 and result.cross_sections.shape[0] == len(result.lumen["arc_length_mm"])
    assert list(result.lumen) == COLUMNS
    assert (result.lumen["source"] == "centerline radius").all()
    assert result.summary["lumenSource"] == "centerline radius"
    # The radius-based diameter is twice the phantom's radii: between its narrowest and widest artery.
    radii = np.concatenate([branch["radii"] for branch in centerlines.branches()])
    assert 2 * radii.min() - 1e-6 <= result.summary["minimalLumenDiameter"] <= 2 * radii.max() + 1e-6
    assert result.path_length == pytest.approx(result.summary["pathLength"])
    assert result.branch_chain[-1] in {branch["id"] for branch in centerlines.branches()}


def test_a_chosen_branch_and_the_points_image():
    volume, centerlines, _ = vr.phantom("thorax", spacing=3.0)
    last = centerlines.branches()[-1]["id"]
    result = vr.vessel_path(volume, centerlines, branch=last, points=True, cross_sections=False)
    assert result.branch_chain[-1] == last
    assert result.cross_sections is None
    assert result.points.shape == result.cpr.shape + (3,)


def test_vmtk_aorta_lumen_from_its_level_set(aorta):
    volume = vr.read_volume(aorta / "aorta.mha")
    segmentation = vr.read_segmentation(aorta / "aorta-final-levelset.mha")
    result = vr.vessel_path(volume, vr.read_centerlines(aorta / "aorta-centerline.vtp"), segmentation=segmentation)
    assert result.summary["lumenSource"] == "segmentation"
    # The distal aorta and an iliac: a lumen of some 5 to 20 mm.
    assert 3.0 < result.summary["minimalLumenDiameter"] < 20.0
    inside = result.lumen["in_segmentation"]
    assert set(np.unique(inside[~np.isnan(inside)])) <= {0.0, 1.0}
    # With the centerlines extracted from the same level set (centerlines=None).
    extracted = vr.vessel_path(volume, None, segmentation=segmentation)
    assert extracted.centerline_source.startswith("extracted from segmentation")


def test_bad_arguments_name_the_argument(aorta):
    volume, centerlines, _ = vr.phantom("thorax", spacing=4.0)
    with pytest.raises(ValueError, match=r"^branch: .*99"):
        vr.vessel_path(volume, centerlines, branch=99)
    with pytest.raises(ValueError, match=r"^width: "):
        vr.vessel_path(volume, centerlines, width=-1.0)
    with pytest.raises(ValueError, match=r"^reformation: \"curved\""):
        vr.vessel_path(volume, centerlines, reformation="curved")
    with pytest.raises(ValueError, match=r"^centerlines: give centerlines, or a segmentation"):
        vr.vessel_path(volume, None)
    with pytest.raises(ValueError, match=r"^centerlines: the list is empty"):
        vr.vessel_path(volume, [])
    with pytest.raises(ValueError, match=r"^segmentation: give a Segmentation"):
        vr.vessel_path(volume, centerlines, segmentation="aorta.nii.gz")


def test_cancel_writes_nothing(output):
    volume, centerlines, _ = vr.phantom("thorax", spacing=3.0)
    outputs = {"cpr": output / "cpr.nrrd", "lumen_table": output / "lumen.csv"}
    with pytest.raises(vr.Cancelled):
        vr.vessel_path(volume, centerlines, outputs=outputs, progress=lambda fraction, stage: False)
    assert list(output.iterdir()) == []
    result = vr.vessel_path(volume, centerlines, outputs=outputs)
    assert sorted(result.written) == sorted(str(path) for path in outputs.values())
    with pytest.raises(OSError, match=r"lumen\.xlsx"):
        vr.vessel_path(volume, centerlines, outputs={"lumen_table": output / "lumen.xlsx"})
