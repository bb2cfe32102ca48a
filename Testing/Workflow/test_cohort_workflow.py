# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""The cohort workflow under Snakemake (workflows/cohort): three cases (two phantoms written by the demo, with their
centerlines; VMTK's aorta given its level set only) and a corrupt fourth, run with --cores 2 and killed after the
first case is published, then resumed: nothing finished is redone, the corrupt case is reported with the module's
message while the others finish, the cohort table's MLD equals the module's own, and `snakemake -n` on the finished
run plans nothing."""
import csv
import os
import pathlib
import re
import shutil
import signal
import subprocess
import time

import pytest

SNAKEMAKE = os.environ.get("VR_SNAKEMAKE", "snakemake")


def folder(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"{name} is not set: run this test through CTest (Testing/Workflow/CMakeLists.txt)")
    return pathlib.Path(value)


@pytest.fixture(scope="module")
def cohort():
    """The cohort's inputs, manifest and configuration in a fresh folder."""
    root = folder("VR_TEST_OUTPUT_DIR")
    shutil.rmtree(root, ignore_errors=True)
    inputs = root / "inputs"
    inputs.mkdir(parents=True)
    for phantom in ("runoff", "thorax"):
        subprocess.run([os.environ["VR_DEMO"], "--phantom", phantom, "--phantomSpacing", "3",
                        "--writePhantom", str(inputs)], check=True, capture_output=True)
    aorta = folder("VR_TEST_DATA_DIR")
    # A corrupt case: VMTK's volume cut off halfway through its voxels.
    data = (aorta / "aorta.mha").read_bytes()
    (inputs / "corrupt.mha").write_bytes(data[: len(data) // 2])
    rows = [("runoff", "inputs/runoff.nrrd", "inputs/runoff-centerlines.vtp", "", ""),
            ("thorax", "inputs/thorax.nrrd", "inputs/thorax-centerlines.vtp", "", ""),
            ("aorta", str(aorta / "aorta.mha"), "", str(aorta / "aorta-final-levelset.mha"), ""),
            ("corrupt", "inputs/corrupt.mha", str(aorta / "aorta-centerline.vtp"), "", "")]
    with open(root / "manifest.csv", "w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["case", "volume", "centerlines", "segmentation", "branch"])
        writer.writerows(rows)
    (root / "cohort.yaml").write_text(
        f"manifest: manifest.csv\noutput: results\nmodules: {os.environ['VR_CLI_MODULES_DIR']}\n"
        "angles: [0, 90]\ntree: {size: \"128,256\", iterations: 50}\nvessel: {width: 30}\nthreads: 1\n")
    return root


def snakemake(root, *arguments, **options):
    return [SNAKEMAKE, "-s", str(folder("VR_WORKFLOW_DIR") / "Snakefile"), "--configfile", str(root / "cohort.yaml"),
            "--directory", str(root), *arguments]


def published(root):
    cases = root / "results" / "cases"
    return sorted(name for name in os.listdir(cases) if not name.startswith(".")) if cases.exists() else []


def jobs(text, finished_only=False):
    """The jobs a Snakemake log shows as (rule, wildcards), only those it reports finished if asked."""
    found = []
    for block in re.finditer(r"^rule (\w+):\n((?:    .*\n)*)", text, re.MULTILINE):
        job = re.search(r"jobid: (\d+)", block.group(2))
        wildcards = re.search(r"wildcards: (.*)", block.group(2))
        if finished_only and not (job and re.search(rf"^Finished job {job.group(1)}\.$", text, re.MULTILINE)):
            continue
        found.append((block.group(1), wildcards.group(1) if wildcards else ""))
    return found


def first_case_finished(log):
    """The case whose publish_case job Snakemake's log reports finished, or None."""
    for rule, wildcards in jobs(log.read_text(), finished_only=True):
        if rule == "publish_case":
            return wildcards[len("case="):]
    return None


def modification_times(path):
    return {str(p.relative_to(path)): p.stat().st_mtime_ns for p in sorted(path.rglob("*")) if p.is_file()}


def test_kill_resume_keep_going_table_and_dry_run(cohort):
    root = cohort
    # 1. Started, and killed hard (the whole process group, as a scheduler or a power cut would) as soon as
    #    Snakemake has finished the first case: its publication recorded, the other cases' jobs under way.
    with open(root / "first-run.log", "w") as log:
        run = subprocess.Popen(snakemake(root, "--cores", "2", "--keep-going"), stdout=log, stderr=subprocess.STDOUT,
                               start_new_session=True)
        deadline = time.monotonic() + 600
        while first_case_finished(root / "first-run.log") is None and run.poll() is None and \
                time.monotonic() < deadline:
            time.sleep(0.02)
        assert run.poll() is None, "the run ended before a case finished:\n" + (root / "first-run.log").read_text()
        os.killpg(run.pid, signal.SIGKILL)
        run.wait()
    first_log = (root / "first-run.log").read_text()
    first = first_case_finished(root / "first-run.log")
    finished_jobs = set(jobs(first_log, finished_only=True))
    assert first in published(root), f"{first} is not published:\n{first_log}"
    finished = {"case": modification_times(root / "results" / "cases" / first),
                "work": modification_times(root / "results" / "work" / first)}
    # Nothing half-published: the case folder holds every file of the case and its record.
    assert "case.json" in finished["case"] and "vessel-lumen.csv" in finished["case"]
    assert not (root / "results" / "cohort.csv").exists()

    # 2. Resumed as the workflow's notes say after a hard kill: unlock, then rerun with --rerun-incomplete.
    subprocess.run(snakemake(root, "--unlock"), check=True, capture_output=True)
    resumed = subprocess.run(snakemake(root, "--cores", "2", "--keep-going", "--rerun-incomplete"),
                             capture_output=True, text=True)
    log = resumed.stdout + resumed.stderr
    assert resumed.returncode != 0, "the corrupt case must fail the run"
    # The corrupt case is reported with the module's message; the others finished.
    assert "cohort: case corrupt failed in step" in log, log
    assert "corrupt.mha" in log
    assert published(root) == sorted(["runoff", "thorax", "aorta"]), log
    # Nothing finished was redone: the first case's files are untouched, and no job of it ran.
    assert modification_times(root / "results" / "cases" / first) == finished["case"]
    assert modification_times(root / "results" / "work" / first) == finished["work"]
    assert f"case={first}" not in log, log
    redone = finished_jobs & set(jobs(log))
    assert not redone, f"jobs finished before the kill ran again: {redone}"

    with open(root / "results" / "failed.csv", newline="") as file:
        failed = list(csv.DictReader(file))
    assert [row["case"] for row in failed] == ["corrupt"]
    assert "corrupt.mha" in failed[0]["message"]
    with open(root / "results" / "cohort.csv", newline="") as file:
        table = {row["case"]: row for row in csv.DictReader(file)}
    assert sorted(table) == ["aorta", "runoff", "thorax"]

    # 3. The table's MLD is the module's: VesselPathReformation run here on each case as a user would.
    modules = folder("VR_CLI_MODULES_DIR")
    aorta = folder("VR_TEST_DATA_DIR")
    direct = {"runoff": ["inputs/runoff.nrrd", "inputs/runoff-centerlines.vtp"],
              "thorax": ["inputs/thorax.nrrd", "inputs/thorax-centerlines.vtp"],
              "aorta": [str(aorta / "aorta.mha"), "--segmentation", str(aorta / "aorta-final-levelset.mha")]}
    for case, arguments in direct.items():
        returns = root / f"{case}-returns.txt"
        subprocess.run([str(modules / "VesselPathReformation"), *arguments, str(root / f"{case}-cpr.nrrd"),
                        "--width", "30", "--returnparameterfile", str(returns)], check=True, cwd=root,
                       capture_output=True)
        values = dict(line.split(" = ", 1) for line in returns.read_text().splitlines() if " = " in line)
        assert table[case]["mld_mm"] != ""
        assert float(table[case]["mld_mm"]) == float(values["minimalLumenDiameter"]), case
        assert table[case]["lumen_source"] == values["lumenSource"], case
    assert table["aorta"]["lumen_source"] == "segmentation"
    assert table["aorta"]["centerlines"] == "extracted"

    # 4. The corrupt case taken out of the manifest: the run completes, only the table is made again; then a dry
    #    run plans nothing.
    manifest = (root / "manifest.csv").read_text().splitlines()
    (root / "manifest.csv").write_text("\n".join(line for line in manifest if not line.startswith("corrupt")) + "\n")
    before = {case: modification_times(root / "results" / "cases" / case) for case in published(root)}
    completed = subprocess.run(snakemake(root, "--cores", "2"), capture_output=True, text=True)
    assert completed.returncode == 0, completed.stdout + completed.stderr
    assert {case: modification_times(root / "results" / "cases" / case) for case in published(root)} == before
    dry = subprocess.run(snakemake(root, "-n"), capture_output=True, text=True)
    assert dry.returncode == 0, dry.stdout + dry.stderr
    assert "Nothing to be done" in dry.stdout + dry.stderr, dry.stdout + dry.stderr
