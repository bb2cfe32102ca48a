# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""reform(): the tree CPR on the phantoms, its view and to_patient, progress, cancel and Ctrl-C leaving nothing
half-written, the GIL released while the engine runs, bad arguments named."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import vesselreformation as vr


@pytest.fixture(scope="module")
def thorax():
    return vr.phantom("thorax", spacing=3.0)


@pytest.fixture(scope="module")
def runoff():
    return vr.phantom("runoff", spacing=3.0)


def test_reform_returns_every_image_on_the_view(thorax):
    volume, centerlines, angle = thorax
    result = vr.reform(volume, centerlines, angle=angle, size=(96, 160), iterations=50)
    for image, dtype in ((result.cpr, np.float32), (result.unfiltered_cpr, np.float32), (result.depth, np.float32),
                         (result.relaxed_depth, np.float32), (result.fixed_mask, np.uint8),
                         (result.owner_labels, np.uint32)):
        assert image.shape == (160, 96) and image.dtype == dtype
    # The aorta's lumen (contrast, ~ 300 HU and more) lies where the centerline pixels are held fixed.
    assert result.fixed_mask.any()
    assert np.median(result.cpr[result.fixed_mask == 1]) > 200.0
    # The owner labels are the ids of the tree as reformed (the phantom's trunk split where its children leave), and
    # each branch's name is kept through the split.
    ids = {branch["id"]: branch["name"] for branch in result.centerlines.branches()}
    assert set(np.unique(result.owner_labels)) - {0} <= set(ids)
    assert len(ids) >= len(centerlines)
    assert set(ids.values()) == {branch["name"] for branch in centerlines.branches()}
    assert result.view["size"] == (96, 160)
    assert result.backend in ("cpu", "opencl")


def test_to_patient_follows_the_view_geometry(thorax):
    volume, centerlines, _ = thorax
    result = vr.reform(volume, centerlines, angle=30.0, size=(64, 96), iterations=10)
    view = result.view
    u, v, up, center = (np.array(view[key]) for key in ("u", "v", "up", "center"))
    sx, sy = view["spacing"]
    j, i = np.nonzero(result.fixed_mask)
    j, i = j[:20], i[:20]
    # By hand (docs/design.md "View"): B(i, j) = C + (i - (W-1)/2) sx u - (j - (H-1)/2) sy up; X = B + d v.
    plane = center + np.outer(i - 31.5, u) * sx - np.outer(j - 47.5, up) * sy
    expected = plane + result.relaxed_depth[j, i][:, None] * v
    np.testing.assert_allclose(result.to_patient(i, j), expected, atol=1e-6)
    ras = result.to_patient(i, j, space="RAS")
    np.testing.assert_allclose(ras, expected * [-1, -1, 1], atol=1e-6)
    # A fixed (centerline) pixel maps onto the centerline it shows: within a voxel of some centerline point.
    points = np.concatenate([branch["points"] for branch in centerlines.branches()])
    nearest = np.min(np.linalg.norm(points[None, :, :] - expected[:, None, :], axis=2), axis=1)
    assert np.max(nearest) < 3.0
    with pytest.raises(ValueError, match="outside the 64 x 96 view"):
        result.to_patient(64, 0)


def test_centerlines_as_a_list_in_ras_give_the_same_cpr(thorax):
    volume, centerlines, _ = thorax
    reference = vr.reform(volume, centerlines, size=(48, 80), iterations=5)
    branches = [{"points": branch["points"], "radii": branch["radii"], "id": branch["id"]}
                for branch in centerlines.branches(space="RAS")]
    again = vr.reform(volume, branches, space="RAS", size=(48, 80), iterations=5)
    np.testing.assert_array_equal(again.cpr, reference.cpr)


def test_outputs_are_written_whole_like_the_modules(thorax, output):
    volume, centerlines, _ = thorax
    outputs = {"cpr": output / "cpr.nrrd", "cpr_png": output / "cpr.png", "depth": output / "depth.nrrd",
               "surface": output / "surface.vtp"}
    result = vr.reform(volume, centerlines, size=(48, 80), iterations=5, outputs=outputs)
    assert sorted(result.written) == sorted(str(path) for path in outputs.values())
    for path in outputs.values():
        assert path.stat().st_size > 0
    assert not [name for name in os.listdir(output) if name not in {p.name for p in outputs.values()}]


def test_progress_reaches_the_callback_on_this_thread(runoff):
    volume, centerlines, angle = runoff
    calls = []
    main = threading.get_ident()
    vr.reform(volume, centerlines, angle=angle, size=(256, 512), iterations=400,
              progress=lambda fraction, stage: calls.append((fraction, stage, threading.get_ident())))
    assert calls, "no progress reported"
    assert all(thread == main for _, _, thread in calls)
    fractions = [fraction for fraction, _, _ in calls]
    assert fractions == sorted(fractions) and 0.0 <= fractions[0] and fractions[-1] <= 1.0
    assert any("relax" in stage.lower() for _, stage, _ in calls)


def _previous_outputs(folder):
    """Files a run must leave as they were when it stops, and the outputs it would write."""
    (folder / "cpr.nrrd").write_bytes(b"an earlier CPR")
    return {"cpr": folder / "cpr.nrrd", "cpr_png": folder / "cpr.png", "depth": folder / "depth.nrrd"}


def _nothing_half_written(folder):
    assert (folder / "cpr.nrrd").read_bytes() == b"an earlier CPR"
    assert sorted(os.listdir(folder)) == ["cpr.nrrd"], os.listdir(folder)


def test_cancel_through_the_callback_writes_nothing(runoff, output):
    volume, centerlines, angle = runoff
    outputs = _previous_outputs(output)
    seen = []

    def progress(fraction, stage):
        seen.append(fraction)
        return fraction < 0.3   # False: cancel

    with pytest.raises(vr.Cancelled, match="nothing was written"):
        vr.reform(volume, centerlines, angle=angle, size=(512, 1024), iterations=3000, outputs=outputs,
                  progress=progress)
    assert seen and seen[-1] < 0.9
    _nothing_half_written(output)


def test_keyboard_interrupt_in_the_callback_stops_the_engine_and_writes_nothing(runoff, output):
    volume, centerlines, angle = runoff
    outputs = _previous_outputs(output)

    def progress(fraction, stage):
        if fraction > 0.2:
            raise KeyboardInterrupt

    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        vr.reform(volume, centerlines, angle=angle, size=(512, 1024), iterations=20000, outputs=outputs,
                  progress=progress)
    _nothing_half_written(output)
    # The relaxation was stopped, not run to its end (20000 passes at 512 x 1024 take far longer).
    uninterrupted = time.monotonic() - start
    assert uninterrupted < 30.0


def test_ctrl_c_without_a_callback_stops_the_engine_and_writes_nothing(runoff, output):
    volume, centerlines, angle = runoff
    outputs = _previous_outputs(output)
    # SIGINT from another thread while reform() runs: Python's handler flags it, reform() notices within 0.1 s.
    timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            vr.reform(volume, centerlines, angle=angle, size=(512, 1024), iterations=20000, outputs=outputs)
    finally:
        timer.cancel()
    _nothing_half_written(output)


def test_the_gil_is_released_while_the_engine_runs(runoff):
    volume, centerlines, angle = runoff
    ticks = []
    running = threading.Event()
    stop = threading.Event()

    def count():
        running.set()
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.005)

    thread = threading.Thread(target=count)
    thread.start()
    running.wait()
    try:
        start = time.monotonic()
        vr.reform(volume, centerlines, angle=angle, size=(512, 1024), iterations=1500)
        end = time.monotonic()
    finally:
        stop.set()
        thread.join()
    during = [tick for tick in ticks if start < tick < end]
    # The other thread ran all along: at least one tick every 0.1 s of the run.
    assert end - start > 0.2
    assert len(during) >= (end - start) / 0.1


def test_bad_arguments_raise_value_error_naming_them(thorax, output):
    volume, centerlines, _ = thorax
    with pytest.raises(ValueError, match=r"^centerlines: the list is empty"):
        vr.reform(volume, [])
    with pytest.raises(ValueError, match=r"^centerlines: branch 0: points must be an N x 3 array"):
        vr.reform(volume, [np.zeros((5, 2))])
    with pytest.raises(ValueError, match=r"^iterations: .*-3"):
        vr.reform(volume, centerlines, iterations=-3)
    with pytest.raises(ValueError, match=r"^iterations: expected a whole number"):
        vr.reform(volume, centerlines, iterations=2.5)
    with pytest.raises(ValueError, match=r"^relaxation: .*must be"):
        vr.reform(volume, centerlines, relaxation=1.5)
    with pytest.raises(ValueError, match=r"^jump_threshold: "):
        vr.reform(volume, centerlines, jump_threshold=float("nan"))
    with pytest.raises(ValueError, match=r"^mode \"curved\": use scanline, nearest or visibility"):
        vr.reform(volume, centerlines, mode="curved")
    with pytest.raises(ValueError, match=r"^size: expected 2 whole numbers"):
        vr.reform(volume, centerlines, size=(0, 10))
    with pytest.raises(ValueError, match=r"^volume: give a Volume"):
        vr.reform(np.zeros((3, 3, 3)), centerlines)
    with pytest.raises(ValueError, match=r"^outputs: unknown kind \"cpr_tiff\""):
        vr.reform(volume, centerlines, outputs={"cpr_tiff": output / "x.tif"})
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'iteration'"):
        vr.reform(volume, centerlines, iteration=10)
    far = [np.array([[1e5, 0, 0], [1e5, 0, 50.0]])]
    with pytest.raises(ValueError, match=r"^space: .*none of the 2 points lies inside the volume"):
        vr.reform(volume, far)
    with pytest.raises(OSError, match="no-such-folder"):
        vr.reform(volume, centerlines, outputs={"cpr": output / "no-such-folder" / "cpr.nrrd"})


def test_help_shows_the_docstrings():
    assert "jump_threshold" in vr.reform.__doc__ and "GIL" in vr.reform.__doc__
    assert "nibabel" in vr.Volume.__doc__
    assert "lumen table" in vr.vessel_path.__doc__ or "lumen_table" in vr.vessel_path.__doc__
    assert "reform" in vr.__doc__
