#!/usr/bin/env python3
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
"""Prints the paper's Table 1 beside this machine's figures, from VesselReformationBenchmarks' JSON output.

    benchmark_table.py --run build/bin/VesselReformationBenchmarks [--json-out results.json] [-- ARGS...]
    benchmark_table.py --json results.json [--json more.json ...]

--run runs the benchmark executable (its console output goes to stderr; ARGS after -- are passed on, e.g.
--benchmark_filter=Relax) and reads the JSON it writes; --json reads a file written earlier with
--benchmark_out=FILE --benchmark_out_format=json (several: their benchmarks together, the first one's context).
Figures are medians of the repetitions, real time, in ms.
Python 3 standard library only.
"""

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

SIZES = [(256, 768), (512, 1024)]

# Kretschmer, Preim, Stamminger, EuroVis 2014, Table 1: Intel i5, 4 cores @ 3.1 GHz; GeForce GTX 760; 500 passes.
PAPER = {
    "mpCPR": {(256, 768): 40, (512, 1024): 113},
    "filter CPU": {(256, 768): 2486, (512, 1024): 6748},
    "filter GPU": {(256, 768): 33, (512, 1024): 75},
    "total GPU": {(256, 768): 74, (512, 1024): 189},
}

# docs/design.md "Numbers", at 512 x 1024 on the 2-core machine.
TARGETS = [
    ("CPU relax, 500 iterations", "Relax_CPU", 150.0),
    ("depth + resample for a new angle", "DepthResample", 30.0),
    ("whole pipeline on the CPU", "Pipeline_CPU", 250.0),
]
MINIMUM_SPEED_UP = 15.0
# Issue 40 on a GPU: the OpenCL relax, 500 passes at 512 x 1024, at most this long (ms).
OPENCL_RELAX_TARGET = 2.0
# Issue 40: the steady solve at 512 x 1024 at most this many times the 500 Jacobi passes (Relax_CPU/512/1024) of the
# same run, and each x 4 of pixels at most this many times the time, on every case.
STEADY_RATIO_TARGET = 2.0
STEADY_GROWTH_TARGET = 5.0
STEADY_PREFIX = "Relax_Steady"
# Issue 38: the Visibility depth map within this factor of the scanline one in the same run, and the occlusion
# profile of 180 angles within this many ms at 512 x 1024.
MAXIMUM_VISIBILITY_OVER_SCANLINE = 2.0
MAXIMUM_OCCLUSION_PROFILE_MS = 200.0
# Issue 22: on a machine with 16 cores, Relax_CPU/512/1024/threads:16 at least this much faster than threads:2.
MINIMUM_SCALING_16_OVER_2 = 5.0

# threads:N is kept: Relax_CPU/W/H/threads:N names the relax's team size (an argument, not Google's Threads()).
SUFFIX = re.compile(r"/(repeats|iterations|min_time):[^/]*|/real_time|/manual_time|/process_time")


def base_name(run_name):
    """'Relax_CPU/512/1024/repeats:10/real_time' -> 'Relax_CPU/512/1024'."""
    return SUFFIX.sub("", run_name)


def to_milliseconds(value, unit):
    return value * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[unit]


def read_medians(report):
    """Median real time (ms) per benchmark; a benchmark run without repetitions counts as its own median."""
    medians, singles = {}, {}
    for entry in report.get("benchmarks", []):
        if entry.get("error_occurred"):
            continue
        name = base_name(entry.get("run_name", entry["name"]))
        time = to_milliseconds(entry["real_time"], entry.get("time_unit", "ns"))
        if entry.get("run_type") == "aggregate":
            if entry.get("aggregate_name") == "median":
                medians[name] = time
        else:
            singles.setdefault(name, []).append(time)
    for name, times in singles.items():
        if name not in medians:
            times = sorted(times)
            middle = len(times) // 2
            medians[name] = times[middle] if len(times) % 2 else 0.5 * (times[middle - 1] + times[middle])
    return medians


def milliseconds(value):
    if value is None:
        return "–"
    if isinstance(value, int):
        return f"{value} ms"
    return f"{value:.0f} ms" if value >= 100 else f"{value:.1f} ms"


def ratio(numerator, denominator):
    if numerator is None or denominator is None or denominator <= 0:
        return "–"
    return f"{numerator / denominator:.0f}×" if numerator / denominator >= 10 else f"{numerator / denominator:.1f}×"


def table(report):
    medians = read_medians(report)
    context = report.get("context", {})

    def ours(stage, size):
        return medians.get(f"{stage}/{size[0]}/{size[1]}")

    header = "| 500 filter passes | " + " | ".join(
        f"{w}×{h} paper | {w}×{h} ours" for w, h in SIZES) + " |"
    lines = [header, "|---|" + "---:|---:|" * len(SIZES)]

    def row(label, paper_key, stage, extra=None):
        cells = []
        for size in SIZES:
            paper = PAPER.get(paper_key, {}).get(size) if paper_key else None
            value = ours(stage, size) if stage else None
            text = milliseconds(value)
            if extra and value is not None:
                text += extra(size, value)
            cells += [milliseconds(paper) if paper else "–", text]
        lines.append(f"| {label} | " + " | ".join(cells) + " |")

    row("mpCPR depth (new angle)", "mpCPR", "Depth")
    row("filter, CPU", "filter CPU", "Relax_CPU",
        lambda size, value: f" ({ratio(ours('Relax_Plain', size), value)} plain, "
                            f"{ratio(PAPER['filter CPU'][size], value)} paper CPU)")
    row("filter, plain reference (scalar double, 1 thread)", None, "Relax_Plain")
    row("filter, GPU / OpenCL", "filter GPU", "Relax_OpenCL",
        lambda size, value: f" ({ratio(ours('Relax_Plain', size), value)} plain)")
    row("resample (linear)", None, "Resample")
    row("depth + resample (new angle)", None, "DepthResample")
    row("total: depth + CPU filter + resample", None, "Pipeline_CPU")
    row("total: depth + GPU/OpenCL filter + resample", "total GPU", "Pipeline_OpenCL")
    row("view on the CPU: depth + filter + 2 CPRs", None, "View_CPU")
    row("view on the device: depth + filter + 2 CPRs", None, "View_OpenCL",
        lambda size, value: f" ({ratio(ours('View_CPU', size), value)} the CPU's)")

    # Relax_CPU_<set>/W/H only; Relax_CPU_Passes/W/H/threads:N/passes:K has more fields.
    others = sorted(name for name in medians
                    if name.startswith("Relax_CPU_") and name.count("/") == 2 and not name.startswith("Relax_CPU_FullSize"))
    teams = {}
    for name in medians:
        parts = name.split("/")
        if len(parts) == 4 and parts[0] == "Relax_CPU" and parts[3].startswith("threads:"):
            teams[(int(parts[1]), int(parts[2]), int(parts[3][len("threads:"):]))] = medians[name]
    notes = []
    for name in sorted(name for name in medians if name.startswith("Relax_Generic/")):
        _, width, height = name.split("/")
        cpu = medians.get(f"Relax_CPU/{width}/{height}")
        notes.append(f"- the filter's previous CPU loop (now its generic path: double, all cores), {width}×{height}: "
                     f"{milliseconds(medians[name])}; the CPU relax is {ratio(medians[name], cpu)} faster")
    for name in others:
        stage, width, height = name.split("/")
        plain = medians.get(f"Relax_Plain/{width}/{height}")
        notes.append(f"- {stage[len('Relax_CPU_'):]} instead of {context.get('relax_instruction_set', '?')} "
                     f"(a build running elsewhere), {width}×{height}: {milliseconds(medians[name])}, "
                     f"{ratio(plain, medians[name])} the plain reference")

    for width, height, threads in sorted(teams):
        two = teams.get((width, height, 2))
        notes.append(f"- CPU relax with a team of {threads} threads, {width}×{height}: "
                     f"{milliseconds(teams[(width, height, threads)])}, "
                     f"{ratio(two, teams[(width, height, threads)])} the speed of 2 threads")

    passes = {}
    for name in medians:
        parts = name.split("/")
        if len(parts) == 4 and parts[0] == "Relax_OpenCL_Passes" and parts[3].startswith("passes:"):
            passes[int(parts[3][len("passes:"):])] = medians[name]
    for count in sorted(passes):
        notes.append(f"- OpenCL relax with {count} passes a launch ({-(-500 // count)} launches), 512×1024: "
                     f"{milliseconds(passes[count])}")

    checks = []
    big = SIZES[-1]
    for label, stage, limit in TARGETS:
        value = ours(stage, big)
        if value is None:
            checks.append(f"- {label} ≤ {limit:.0f} ms: not measured")
        else:
            verdict = "met" if value <= limit else f"MISSED by {value - limit:.1f} ms"
            checks.append(f"- {label} ≤ {limit:.0f} ms at {big[0]}×{big[1]}: {milliseconds(value)}, {verdict}")
    cpu, plain = ours("Relax_CPU", big), ours("Relax_Plain", big)
    if cpu and plain:
        speed_up = plain / cpu
        verdict = "met" if speed_up >= MINIMUM_SPEED_UP else "MISSED"
        checks.append(f"- CPU relax ≥ {MINIMUM_SPEED_UP:.0f}× the plain reference in the same run: "
                      f"{speed_up:.1f}×, {verdict}")

    for visible, scan, where in (("Depth_Visibility", "Depth", "30-40°"),
                                 ("Depth_Visibility_Overlap", "Depth_Overlap", "120-130°, legs overlapping")):
        value, reference = ours(visible, big), ours(scan, big)
        if value and reference:
            verdict = "met" if value / reference <= MAXIMUM_VISIBILITY_OVER_SCANLINE else "MISSED"
            checks.append(f"- visibility depth ≤ {MAXIMUM_VISIBILITY_OVER_SCANLINE:.0f}× scanline in the same run "
                          f"({where}): {milliseconds(value)} against {milliseconds(reference)}, "
                          f"{value / reference:.2f}×, {verdict}")
    profile, brute = ours("OcclusionProfile", big), ours("OcclusionProfile_DepthMaps", big)
    if profile:
        verdict = "met" if profile <= MAXIMUM_OCCLUSION_PROFILE_MS else "MISSED"
        checks.append(f"- occlusion profile, 180 angles ≤ {MAXIMUM_OCCLUSION_PROFILE_MS:.0f} ms: "
                      f"{milliseconds(profile)}, {verdict}"
                      + (f"; 180 visibility depth maps (its plain reference) {milliseconds(brute)}, "
                         f"{ratio(brute, profile)} slower" if brute else ""))

    two, sixteen = teams.get((big[0], big[1], 2)), teams.get((big[0], big[1], 16))
    cpus = int(context.get("num_cpus", 0) or 0)
    if two and sixteen and cpus >= 16:
        verdict = "met" if two / sixteen >= MINIMUM_SCALING_16_OVER_2 else "MISSED"
        checks.append(f"- CPU relax with 16 threads ≥ {MINIMUM_SCALING_16_OVER_2:.0f}× as fast as with 2 in the same "
                      f"run: {two / sixteen:.1f}×, {verdict}")
    elif two and sixteen:
        checks.append(f"- CPU relax with 16 threads against 2: {two / sixteen:.1f}×, not a check on {cpus} CPUs "
                      f"(16 threads need 16 cores)")

    opencl = ours("Relax_OpenCL", big)
    if opencl is not None:
        best = min(passes.values()) if passes else opencl
        verdict = "met" if min(opencl, best) <= OPENCL_RELAX_TARGET else "MISSED"
        checks.append(f"- OpenCL relax, 500 passes ≤ {OPENCL_RELAX_TARGET:.0f} ms at {big[0]}×{big[1]} (upload and "
                      f"download included): {milliseconds(opencl)} with the device's choice, "
                      f"{milliseconds(best)} at best, {verdict}")

    machine = (f"Ours: {context.get('cpu_model', 'unknown CPU')}, {context.get('num_cpus', '?')} CPUs "
               f"({context.get('itk_threads', '?')} ITK threads), relax kernel "
               f"{context.get('relax_instruction_set', '?')}, {context.get('build_type', '?')} build "
               f"({context.get('cxx_flags', '').strip() or 'default flags'}); "
               f"medians of repetitions, real time; {context.get('date', '')}.")
    paper = ("Paper: Kretschmer, Preim, Stamminger, EuroVis 2014, Table 1: Intel i5, 4 cores @ 3.1 GHz, "
             "GeForce GTX 760 (its mpCPR column is the depth map).")
    return "\n".join([machine, paper, ""] + lines + [""] + notes + ([""] if notes else []) + ["Targets:"] + checks)


def steady_table(report):
    """The steady solver's families (Relax_Steady*/W/H): time, the ratio to the 500 Jacobi passes of the same run
    (Relax_CPU/W/H, or Relax_CPU_<case>/W/H on the case's own maps where the run has it), and the growth per x 4 of
    pixels, with the targets checked: at 512 x 1024, or for a family without that size at its middle size."""
    medians = read_medians(report)
    families = {}
    for name, time in medians.items():
        parts = name.split("/")
        if len(parts) == 3 and parts[0].startswith(STEADY_PREFIX):
            families.setdefault(parts[0], {})[(int(parts[1]), int(parts[2]))] = time
    if not families:
        return ""
    lines = ["| case | " + " | ".join(["W×H", "ms", "× passes", "growth"]) + " |", "|---|---|---:|---:|---:|"]
    checks = []
    for family in sorted(families):
        sizes = sorted(families[family], key=lambda size: size[0] * size[1])
        target = (512, 1024) if (512, 1024) in sizes else sizes[len(sizes) // 2]
        suffix = family[len(STEADY_PREFIX):]

        def passes(size):
            return medians.get(f"Relax_CPU{suffix}/{size[0]}/{size[1]}") or medians.get(f"Relax_CPU/{size[0]}/{size[1]}")

        previous = None
        for size in sizes:
            time = families[family][size]
            jacobi = passes(size)
            times_passes = f"{time / jacobi:.2f}" if jacobi else "–"
            growth = "–"
            if previous and size[0] * size[1] == 4 * previous[0][0] * previous[0][1]:
                growth = f"×{time / previous[1]:.2f}"
                if time / previous[1] > STEADY_GROWTH_TARGET:
                    checks.append(f"- {family}: {previous[0][0]}×{previous[0][1]} → {size[0]}×{size[1]} costs "
                                  f"×{time / previous[1]:.2f}, above ×{STEADY_GROWTH_TARGET:.0f}: MISSED")
            lines.append(f"| {family} | {size[0]}×{size[1]} | {milliseconds(time)} | {times_passes} | {growth} |")
            previous = (size, time)
        at, jacobi = families[family].get(target), passes(target)
        if jacobi and at:
            verdict = "met" if at / jacobi <= STEADY_RATIO_TARGET else "MISSED"
            checks.append(f"- {family} at {target[0]}×{target[1]} ≤ {STEADY_RATIO_TARGET:.0f}× the 500 passes "
                          f"({milliseconds(jacobi)}): {at / jacobi:.2f}×, {verdict}")
    growths = [line for line in checks if "costs ×" in line]
    if not growths:
        checks.append(f"- every ×4 of pixels ≤ ×{STEADY_GROWTH_TARGET:.0f} on every case: met")
    return "\n".join(lines + ["", "Steady targets:"] + checks)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument("--run", metavar="EXE", help="run this benchmark executable")
    source.add_argument("--json", metavar="FILE", action="append", help="read this JSON output (repeatable)")
    parser.add_argument("--json-out", metavar="FILE", help="with --run: keep the JSON here")
    parser.add_argument("extra", nargs="*", help="with --run: arguments for the executable (after --)")
    arguments = parser.parse_args()

    if arguments.json:
        if arguments.extra or arguments.json_out:
            parser.error("--json takes no executable arguments or --json-out")
        report = None
        for path in arguments.json:
            try:
                with open(path, encoding="utf-8") as file:
                    part = json.load(file)
            except (OSError, ValueError) as error:
                sys.exit(f"benchmark_table.py: cannot read --json {path}: {error}")
            if report is None:
                report = part
            else:
                report.setdefault("benchmarks", []).extend(part.get("benchmarks", []))
    else:
        if not (os.path.isfile(arguments.run) and os.access(arguments.run, os.X_OK)):
            sys.exit(f"benchmark_table.py: --run {arguments.run} is not an executable file")
        out = arguments.json_out or tempfile.NamedTemporaryFile(suffix=".json", delete=False).name
        command = [arguments.run, f"--benchmark_out={out}", "--benchmark_out_format=json"] + arguments.extra
        status = subprocess.run(command, stdout=sys.stderr).returncode
        if status != 0:
            sys.exit(f"benchmark_table.py: {' '.join(command)} failed with exit status {status}")
        with open(out, encoding="utf-8") as file:
            report = json.load(file)
        if not arguments.json_out:
            os.unlink(out)
    print(table(report))
    steady = steady_table(report)
    if steady:
        print()
        print(steady)


if __name__ == "__main__":
    main()
