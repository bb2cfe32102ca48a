#!/usr/bin/env bash
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Snakemake's cost per case (issue 41): a cohort of 20 phantom cases (the run-off and the thoracic phantom at 2 mm,
# alternately, with their exact centerlines), each with the tree CPR at two angles and the vessel reading, run
#   - by the cohort workflow (snakemake --cores 2), and
#   - by a plain shell loop running the same module commands (scripts/cohort.py's), two cases at a time,
# each from scratch, alternately, three times. Prints the wall times and Snakemake's overhead per case.
#
#   bash Testing/Tools/measure_cohort_overhead.sh build WORK_FOLDER
set -euo pipefail
build=$(cd "${1:?usage: measure_cohort_overhead.sh BUILD_DIR WORK_FOLDER}" && pwd)
work=${2:?usage: measure_cohort_overhead.sh BUILD_DIR WORK_FOLDER}
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$work/inputs"
work=$(cd "$work" && pwd)
for phantom in runoff thorax; do
  [ -f "$work/inputs/$phantom.nrrd" ] || "$build/bin/VesselReformationDemo" --phantom "$phantom" --phantomSpacing 2 \
    --writePhantom "$work/inputs" > /dev/null
done
{
  echo "case,volume,centerlines,segmentation,branch"
  for n in $(seq -w 1 20); do
    phantom=$([ $((10#$n % 2)) = 1 ] && echo runoff || echo thorax)
    echo "case$n,inputs/$phantom.nrrd,inputs/$phantom-centerlines.vtp,,"
  done
} > "$work/manifest.csv"
cat > "$work/cohort.yaml" <<YAML
manifest: manifest.csv
output: results
modules: $build/cli-modules
angles: [0, 90]
tree: {size: "256,512", iterations: 200}
vessel: {width: 30}
threads: 1
YAML

# The plain loop: each case's module commands in order, two cases at a time (the same two cores).
cat > "$work/loop.py" <<PY
import subprocess, sys
sys.path.insert(0, "$source_dir/workflows/cohort/scripts")
import cohort
cfg = cohort.load_config("$work/cohort.yaml")
for case in cohort.read_manifest(cfg["manifest"]):
    for step in cohort.step_files(cfg, case):
        print(" ".join(__import__("shlex").quote(part) for part in cohort.step_command(cfg, case, step)) + " &&", end=" ")
    print("true")
PY
python3 "$work/loop.py" > "$work/loop-commands.txt"

elapsed() { local start=$1; echo "$(($(date +%s%N) - start))" | awk '{printf "%.2f", $1 / 1e9}'; }
for round in 1 2 3; do
  rm -rf "$work/results" "$work/.snakemake"
  mkdir -p "$work/results/work"
  for n in $(seq -w 1 20); do mkdir -p "$work/results/work/case$n"; done
  start=$(date +%s%N)
  (cd "$work" && ITK_GLOBAL_DEFAULT_NUMBER_OF_THREADS=1 xargs -P 2 -I{} -d '\n' sh -c {} < loop-commands.txt > /dev/null 2>&1)
  loop=$(elapsed "$start")
  rm -rf "$work/results" "$work/.snakemake"
  start=$(date +%s%N)
  snakemake -s "$source_dir/workflows/cohort/Snakefile" --configfile "$work/cohort.yaml" --directory "$work" --cores 2 \
    --quiet > "$work/snakemake-$round.log" 2>&1
  snake=$(elapsed "$start")
  rows=$(($(wc -l < "$work/results/cohort.csv") - 1))
  echo "round $round: plain loop ${loop} s, snakemake ${snake} s (${rows} cases in the table); overhead per case" \
    "$(echo "$snake $loop" | awk '{printf "%.3f s, ratio %.3f", ($1 - $2) / 20, $1 / $2}')"
done
