# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""Same engine, same bits: on VMTK's aorta, reform() and vessel_path() give arrays bit-identical to the modules' NRRD
outputs with the same parameters, and the lumen table equals the module's CSV (read here with a plain NRRD reader
and Python's csv, not through the engine)."""
import csv

import numpy as np

import vesselreformation as vr

from conftest import read_nrrd, read_returns, run_module


def test_reform_is_bit_identical_to_the_module(aorta, modules, output):
    run_module(modules, "VesselReformation", aorta / "aorta.mha", aorta / "aorta-centerline.vtp", output / "cpr.nrrd",
               "--up", "auto", "--angle", "30", "--size", "160,320", "--iterations", "200",
               "--outputUnfilteredCPR", output / "unfiltered.nrrd", "--outputDepth", output / "depth.nrrd",
               "--outputRelaxedDepth", output / "relaxed.nrrd", "--outputMask", output / "mask.nrrd",
               "--outputLabels", output / "labels.nrrd", "--returnparameterfile", output / "returns.txt")
    result = vr.reform(vr.read_volume(aorta / "aorta.mha"), vr.read_centerlines(aorta / "aorta-centerline.vtp"),
                       up="auto", angle=30, size=(160, 320), iterations=200)
    for mine, file in ((result.cpr, "cpr.nrrd"), (result.unfiltered_cpr, "unfiltered.nrrd"),
                       (result.depth, "depth.nrrd"), (result.relaxed_depth, "relaxed.nrrd"),
                       (result.fixed_mask, "mask.nrrd"), (result.owner_labels, "labels.nrrd")):
        theirs, _ = read_nrrd(output / file)
        assert mine.shape == theirs.shape, file
        assert mine.dtype == theirs.dtype, file
        assert mine.tobytes() == theirs.tobytes(), f"{file}: {np.count_nonzero(mine != theirs)} pixels differ"
    returns = read_returns(output / "returns.txt")
    assert returns["imageSize"] == "160,320"
    assert returns["backendUsed"] == result.backend


def test_vessel_path_is_bit_identical_and_its_lumen_table_equals_the_csv(aorta, modules, output):
    run_module(modules, "VesselPathReformation", aorta / "aorta.mha", aorta / "aorta-centerline.vtp",
               output / "straightened.nrrd", "--segmentation", aorta / "aorta-final-levelset.mha", "--width", "20",
               "--outputCrossSections", output / "sections.nrrd", "--outputLumenTable", output / "lumen.csv",
               "--returnparameterfile", output / "returns.txt")
    result = vr.vessel_path(vr.read_volume(aorta / "aorta.mha"), vr.read_centerlines(aorta / "aorta-centerline.vtp"),
                            segmentation=vr.read_segmentation(aorta / "aorta-final-levelset.mha"), width=20)
    cpr, _ = read_nrrd(output / "straightened.nrrd")
    assert result.cpr.shape == cpr.shape and result.cpr.tobytes() == cpr.tobytes()
    sections, _ = read_nrrd(output / "sections.nrrd")
    assert result.cross_sections.shape == sections.shape
    assert result.cross_sections.tobytes() == sections.tobytes()

    with open(output / "lumen.csv", newline="") as file:
        rows = list(csv.reader(line for line in file if not line.startswith("#")))  # the grading's summary lines
    header, rows = rows[0], rows[1:]
    # The profile's columns; the CSV adds the grading's marks per row after them.
    assert list(result.lumen) == header[:len(result.lumen)]
    assert header[len(result.lumen):] == ["segment", "mld_candidate", "excluded_because"]
    assert all(len(column) == len(rows) for column in result.lumen.values())
    for c, name in enumerate(header[:len(result.lumen)]):
        for r, row in enumerate(rows):
            value = result.lumen[name][r]
            if name == "source":
                written = value
            elif isinstance(value, (float, np.floating)) and np.isnan(value):
                written = ""
            else:
                written = "%.10g" % value   # the CSV's precision (10 significant digits)
            assert written == row[c], f"row {r}, {name}: {written!r} != {row[c]!r}"

    returns = read_returns(output / "returns.txt")
    for name in ("minimalLumenDiameter", "minimalLumenArea", "diameterStenosis", "referenceDiameter"):
        assert float(returns[name]) == result.summary[name], name
    # CAD-RADS only for a coronary artery: the aorta's path (aorta and peripheral scales) leaves it empty, None here.
    assert returns["cadRads"] == "" and result.summary["cadRads"] is None
    assert returns["gradingScale"] == result.summary["gradingScale"] == "peripheral"
