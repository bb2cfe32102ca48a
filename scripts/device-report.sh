#!/usr/bin/env bash
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Measures a machine with a GPU or many cores: lists its OpenCL devices, runs the OpenCL tests, the relax, view and
# pipeline benchmarks (the OpenCL relax with each number of passes per launch; depth, relax and both CPR images for a
# new angle on the device against the CPU), the steady solver's families with their ratios to the 500 passes and
# their growth, and the whole job with each relax backend (cpu, opencl, auto), and writes report.md.
#
#   scripts/device-report.sh [FROM] [REPORT_DIR]
#     FROM        a build folder (default build/), or a bundle folder made by --pack (it holds unpack.sh): then the
#                 programs run from the build path recorded in the bundle, with the bundle's libraries, on a
#                 machine without Debian's packages (no cmake or ctest needed: the test programs run directly).
#     REPORT_DIR  default $OUT, else device-report/. Gets report.md, log.txt (every program's output),
#                 benchmarks.json (Google Benchmark's JSON, for Testing/Benchmarks/benchmark_table.py) and
#                 clinfo.txt: few files, all in one folder.
#   scripts/device-report.sh --pack [BUNDLE_DIR] [BUILD_DIR]
#     packs the programs the report runs, with their shared libraries, the kernel source the tests read and the
#     VMTK aorta, into BUNDLE_DIR (default device-bundle/, ignored by git) with ../shared/tools/device-bundle.sh,
#     for a machine that has none of Debian's ITK, VTK or OpenCL loader. Build them first:
#       cmake --build build --target itkOpenCLBilateralDepthRelaxFilterGTest itkOpenCLCPRDepthImageFilterGTest \
#         itkOpenCLCPRResampleImageFilterGTest VesselReformationLogicOpenCLGTest vrOpenCLDevicesGTest \
#         vrRelaxBackendOpenCLGTest VesselReformationBenchmarks VesselReformationDemo VesselReformation
#
# The default benchmark filter takes Relax_CPU/512/1024/threads:N (N = 1, 2, 4, 8, 16) too: the CPU relax's scaling
# with the cores in the same run (benchmark_table.py checks 16 threads against 2 where there are 16 cores).
#
# Settings (environment): VR_REPORT_MIN_TIME (seconds per benchmark repetition, default 0.2),
# VR_REPORT_BENCHMARKS (the filter of the 512 x 1024 benchmarks, 5 repetitions), VR_REPORT_STEADY (the filter of the
# steady families, 3 repetitions; "" skips them), VR_REPORT_STEP_TIMEOUT (seconds before a step is stopped, default
# 300).
# python3, where there is one, compares the backends' relaxed depth maps; without it the report says so.
set -uo pipefail

repository=$(cd "$(dirname "$0")/.." && pwd)
programs=(bin/itkOpenCLBilateralDepthRelaxFilterGTest bin/itkOpenCLCPRDepthImageFilterGTest
  bin/itkOpenCLCPRResampleImageFilterGTest bin/VesselReformationLogicOpenCLGTest bin/vrOpenCLDevicesGTest
  bin/vrRelaxBackendOpenCLGTest bin/VesselReformationBenchmarks bin/VesselReformationDemo cli-modules/VesselReformation)

fail() {
  echo "device-report: $*" >&2
  exit 1
}

# A variable of a build's CMakeCache.txt ("" when it is not there).
cache_value() {
  sed -n "s/^$2:[A-Z]*=//p" "$1/CMakeCache.txt" | head -n 1
}

pack() {
  local bundle=${1:-$repository/device-bundle} build=${2:-$repository/build}
  local tool=$repository/../shared/tools/device-bundle.sh
  [[ -f $tool ]] || fail "$tool is missing: packing needs the team's shared tools (CI does not)"
  [[ -f $build/CMakeCache.txt ]] || fail "$build is not a configured build folder"
  build=$(cd "$build" && pwd)
  for program in "${programs[@]}"; do
    [[ -x $build/$program ]] || fail "$build/$program is not built (see the command in this script's header)"
  done
  local source data
  source=$(cache_value "$build" CMAKE_HOME_DIRECTORY)
  data=$(cache_value "$build" VR_SHARED_DATA_DIR)
  data=$(cd "$data" 2>/dev/null && pwd -P) || data=""
  local extra="$source/OpenCL/BilateralDepthRelax.cl"
  if [[ -n $data && -f $data/vmtk-aorta-mra/aorta.mha ]]; then
    extra+=" $data/vmtk-aorta-mra/aorta.mha $data/vmtk-aorta-mra/aorta-centerline.vtp"
  else
    echo "device-report: no VMTK aorta under VR_SHARED_DATA_DIR ($data): the report will skip the module run on it"
  fi
  rm -rf "$bundle"
  EXTRA=$extra bash "$tool" "$build" "$bundle" "${programs[@]}" || fail "device-bundle.sh failed"
  # The commit the programs were built from: the device's copy of the tree may carry another git state.
  commit=$(git -C "$(dirname "$0")/.." describe --always --dirty 2>/dev/null || echo unknown)
  printf 'build=%q\ndata=%q\ncommit=%q\n' "$build" "$data" "$commit" >"$bundle/device-report.paths"
  echo "device-report: bundle $bundle: $(du -sh "$bundle" | cut -f1) in all (the device run's working tree may hold 64 MiB)"
}

if [[ ${1:-} == --pack ]]; then
  shift
  pack "$@"
  exit
fi

# --- Where the programs are, where the report goes ----------------------------------------------------------------
from=${1:-}
if [[ -z $from ]]; then
  from=$repository/build
  [[ ! -x $from/bin/VesselReformationBenchmarks && -f $repository/device-bundle/unpack.sh ]] &&
    from=$repository/device-bundle
fi
[[ -d $from ]] || fail "$from: no such folder"
from=$(cd "$from" && pwd)
report=${2:-${OUT:-$repository/device-report}}
mkdir -p "$report" || fail "cannot create $report"
report=$(cd "$report" && pwd)
log=$report/log.txt
: >"$log"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

if [[ -f $from/unpack.sh ]]; then
  [[ -f $from/device-report.paths ]] || fail "$from has no device-report.paths: pack it with $0 --pack"
  # shellcheck source=/dev/null
  source "$from/unpack.sh" >>"$log" 2>&1 || fail "unpacking the bundle $from failed (see $log)"
  build="" data="" commit=""
  # shellcheck source=/dev/null
  source "$from/device-report.paths"
  origin="bundle $from (built in $build)"
else
  build=$from
  data=$( [[ -f $build/CMakeCache.txt ]] && cache_value "$build" VR_SHARED_DATA_DIR)
  origin="build folder $build"
fi
for program in "${programs[@]}"; do
  [[ -x $build/$program ]] || fail "$build/$program is missing"
done
benchmarks=$build/bin/VesselReformationBenchmarks
aorta=${data:+$data/vmtk-aorta-mra}
step_timeout=${VR_REPORT_STEP_TIMEOUT:-300}
min_time=${VR_REPORT_MIN_TIME:-0.2}
filter=${VR_REPORT_BENCHMARKS:-'^(Relax_CPU|Relax_OpenCL|Relax_OpenCL_Passes|Relax_Plain|Depth|Depth_OpenCL|Resample|Resample_OpenCL|DepthResample|DepthResample_OpenCL|Pipeline_CPU|Pipeline_OpenCL|View_CPU|View_OpenCL)/512/1024/'}
# The steady families up to 1024 x 2048 (from 2048 x 4096 up the aorta where its iliacs cross takes tens of seconds a
# solve), the full-size views and the 500 passes on them.
steady_filter=${VR_REPORT_STEADY-'^(Relax_Steady[A-Za-z_]*/(256/512|512/1024|1024/2048)/|Relax_Steady_FullSize/|Relax_CPU_FullSize/)'}

md=$report/report.md
say() { printf '%s\n' "$*" >>"$md"; }
now() { date +%s.%N; }
seconds_since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }'; }

# Runs a step with a time limit, its output appended to the log under a heading; returns its exit status.
run_step() {
  local title=$1
  shift
  printf '\n===== %s: %s\n' "$title" "$*" >>"$log"
  timeout "$step_timeout" "$@" >>"$log" 2>&1
  local status=$?
  [[ $status == 124 ]] && echo "(stopped after $step_timeout s)" >>"$log"
  return $status
}

# The largest |a - b| over two float NRRD images (raw or gzip), in their unit; "n/a" without python3.
nrrd_difference() {
  command -v python3 >/dev/null || { echo "n/a (no python3)"; return; }
  python3 - "$1" "$2" <<'PYTHON' 2>&1 | tail -n 1
import array, gzip, math, sys
def read(path):
    with open(path, "rb") as f:
        data = f.read()
    header, _, body = data.partition(b"\n\n")
    fields = dict(line.split(": ", 1) for line in header.decode().splitlines()[1:] if ": " in line)
    if fields.get("type") != "float":
        raise SystemExit(f"{path}: type {fields.get('type')}, not float")
    if fields.get("encoding") == "gzip":
        body = gzip.decompress(body)
    values = array.array("f", body)
    if fields.get("endian", "little") != sys.byteorder:
        values.byteswap()
    return fields.get("sizes"), values
(size_a, a), (size_b, b) = read(sys.argv[1]), read(sys.argv[2])
if size_a != size_b:
    raise SystemExit(f"sizes differ: {size_a} and {size_b}")
worst = max((abs(x - y) if math.isfinite(x) and math.isfinite(y) else (0.0 if x == y else math.inf)
             for x, y in zip(a, b)), default=0.0)
print(f"{worst:.3g}")
PYTHON
}

# --- Machine --------------------------------------------------------------------------------------------------------
started=$(now)
cpu_model=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
memory=$(awk '/^MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo)
gpus=$(command -v nvidia-smi >/dev/null && nvidia-smi -L 2>/dev/null | sed 's/ (UUID.*//' | paste -sd ';' -)
devices=$(timeout 120 "$benchmarks" --opencl_devices 2>&1)
printf '\n===== OpenCL devices (VesselReformationBenchmarks --opencl_devices)\n%s\n' "$devices" >>"$log"
if command -v clinfo >/dev/null; then
  timeout 120 clinfo >"$report/clinfo.txt" 2>&1
  clinfo_list=$(timeout 60 clinfo -l 2>&1)
else
  echo "clinfo is not installed here" >"$report/clinfo.txt"
  clinfo_list="(no clinfo)"
fi

: >"$md"
say "# Device report: $(hostname), $(date -u '+%Y-%m-%d %H:%M UTC')"
say ""
say "Programs: $origin, commit ${commit:-$(git -C "$repository" rev-parse --short HEAD 2>/dev/null || echo unknown)}."
say ""
say "| | |"
say "| --- | --- |"
say "| Processor | ${cpu_model:-unknown} |"
say "| Cores (nproc) | $(nproc) |"
say "| Memory | $memory |"
say "| GPU (nvidia-smi) | ${gpus:-none found} |"
say "| OpenCL devices | $(printf '%s' "$devices" | paste -sd ';' - | sed 's/;/<br>/g') |"
say "| OCL_ICD_VENDORS | ${OCL_ICD_VENDORS:-(system default)} |"
say ""
say "clinfo -l:"
say ""
say '```'
say "$clinfo_list"
say '```'

# --- OpenCL tests ---------------------------------------------------------------------------------------------------
say ""
say "## OpenCL tests"
say ""
say "| Program | Result | Time (s) |"
say "| --- | --- | --- |"
gtest_failures=0
gtest() {
  local name=$1
  shift
  local begin output status
  begin=$(now)
  run_step "$name" "$@"
  status=$?
  output=$(sed -n '/^===== '"$name"':/,$p' "$log")
  local passed failed skipped
  passed=$(grep -m1 -o '\[  PASSED  \] [0-9]*' <<<"$output" | grep -o '[0-9]*$')
  failed=$(grep -m1 -o '\[  FAILED  \] [0-9]* test' <<<"$output" | grep -o '[0-9]*' | head -n 1)
  skipped=$(grep -m1 -o '\[  SKIPPED \] [0-9]* test' <<<"$output" | grep -o '[0-9]*' | head -n 1)
  local result="${passed:-0} passed, ${failed:-0} failed, ${skipped:-0} skipped"
  if [[ $status != 0 ]]; then
    result+=" (exit $status)"
    gtest_failures=$((gtest_failures + 1))
    local names
    names=$(grep -o '^\[  FAILED  \] [A-Za-z0-9_/.]*' <<<"$output" | sed 's/^\[  FAILED  \] //' | sort -u |
      paste -sd ',' - | sed 's/,/, /g')
    [[ -n $names ]] && result+=": $names"
  fi
  say "| $name | $result | $(seconds_since "$begin") |"
}
gtest itkOpenCLBilateralDepthRelaxFilterGTest "$build/bin/itkOpenCLBilateralDepthRelaxFilterGTest"
gtest itkOpenCLCPRDepthImageFilterGTest "$build/bin/itkOpenCLCPRDepthImageFilterGTest"
gtest itkOpenCLCPRResampleImageFilterGTest "$build/bin/itkOpenCLCPRResampleImageFilterGTest"
gtest VesselReformationLogicOpenCLGTest "$build/bin/VesselReformationLogicOpenCLGTest"
gtest vrOpenCLDevicesGTest "$build/bin/vrOpenCLDevicesGTest"
gtest vrRelaxBackendOpenCLGTest "$build/bin/vrRelaxBackendOpenCLGTest" --gtest_filter=-RelaxBackendWithoutOpenCL.*
# What ctest runs as RelaxBackendWithoutAnyOpenCLPlatform: the ICD loader pointed at an empty vendors folder.
mkdir -p "$scratch/no-opencl-vendors"
gtest "vrRelaxBackendOpenCLGTest (no platform)" env OCL_ICD_VENDORS="$scratch/no-opencl-vendors" OCL_ICD_FILENAMES= \
  "$build/bin/vrRelaxBackendOpenCLGTest" --gtest_filter=RelaxBackendWithoutOpenCL.*

# --- Benchmarks -----------------------------------------------------------------------------------------------------
say ""
say "## Benchmarks"
say ""
say "\`VesselReformationBenchmarks --benchmark_filter='$filter' --benchmark_min_time=$min_time\`, 5 repetitions,"
say "then the steady families \`--benchmark_filter='$steady_filter'\`, 3 repetitions (the largest once). Medians"
say "of real time; the label names the device or the CPU path. All figures in benchmarks.json and"
say "benchmarks-steady.json."
say ""
begin=$(now)
run_step benchmarks "$benchmarks" --benchmark_filter="$filter" --benchmark_min_time="$min_time" \
  --benchmark_repetitions=5 --benchmark_report_aggregates_only=true --benchmark_out="$report/benchmarks.json" \
  --benchmark_out_format=json --benchmark_format=console --benchmark_color=false
status=$?
say '```'
sed -n '/^===== benchmarks:/,$p' "$log" | grep -E '^(Benchmark|-{20})|_median ' | sed 's/repeats:[0-9]*\///' >>"$md"
say '```'
say ""
say "Benchmarks: exit $status, $(seconds_since "$begin") s."
jsons=("$report/benchmarks.json")
if [[ -n $steady_filter ]]; then
  begin=$(now)
  # The steady families' own repetitions (3, once from 2048 x 4096 up) as registered, with Relax_CPU/512/1024 for
  # the ratio in the same run.
  run_step benchmarks-steady "$benchmarks" --benchmark_filter="$steady_filter|^Relax_CPU/(256/512|512/1024|1024/2048)/(repeats|iterations)" \
    --benchmark_min_time="$min_time" --benchmark_out="$report/benchmarks-steady.json" \
    --benchmark_out_format=json --benchmark_format=console --benchmark_color=false
  status=$?
  say ""
  say '```'
  sed -n '/^===== benchmarks-steady:/,$p' "$log" | grep -E '^(Benchmark|-{20})|_median |/iterations:1 ' |
    sed 's/repeats:[0-9]*\///' >>"$md"
  say '```'
  say ""
  say "Steady benchmarks: exit $status, $(seconds_since "$begin") s."
  [[ -s $report/benchmarks-steady.json ]] && jsons+=("$report/benchmarks-steady.json")
fi
table=$repository/Testing/Benchmarks/benchmark_table.py
if command -v python3 >/dev/null && [[ -f $table && -s $report/benchmarks.json ]]; then
  say ""
  say "The paper's Table 1 beside these figures, the OpenCL relax and the steady families"
  say "(Testing/Benchmarks/benchmark_table.py):"
  say ""
  python3 "$table" $(printf -- '--json %q ' "${jsons[@]}") >>"$md" 2>>"$log"
fi

# --- The whole job with each backend --------------------------------------------------------------------------------
say ""
say "## The whole job with each relax backend"
say ""
say "VesselReformationDemo on the run-off phantom (512 x 1024, 500 iterations, two relaxations: isotropic, then"
say "J = 3 mm). Wall time includes building the phantom; relax times are the logic's stage times."
say ""
say "| Backend | Exit | Wall (s) | Relax (ms) | Backend used | max \\|depth - CPU's\\| (mm) |"
say "| --- | --- | --- | --- | --- | --- |"
for backend in cpu opencl auto; do
  begin=$(now)
  run_step "demo --backend $backend" "$build/bin/VesselReformationDemo" --phantom runoff --backend "$backend" \
    --output "$scratch/demo-$backend"
  status=$?
  wall=$(seconds_since "$begin")
  output=$(sed -n '/^===== demo --backend '"$backend"':/,$p' "$log")
  relax=$(grep -o '^    relax  *[0-9]* ms' <<<"$output" | grep -o '[0-9]*' | paste -sd '+' - | sed 's/+/ + /g')
  used=$(grep -m1 '^    backend ' <<<"$output" | sed 's/^    backend *//')
  used+=$(grep -m1 '^    view ' <<<"$output" | sed 's/^    view */; /')
  difference="-"
  if [[ $backend != cpu && -f $scratch/demo-$backend/depth-relaxed.nrrd && -f $scratch/demo-cpu/depth-relaxed.nrrd ]]
  then
    difference=$(nrrd_difference "$scratch/demo-cpu/depth-relaxed.nrrd" "$scratch/demo-$backend/depth-relaxed.nrrd")
  fi
  say "| $backend | $status | $wall | ${relax:--} | ${used:--} | $difference |"
done

say ""
if [[ -n $aorta && -f $aorta/aorta.mha ]]; then
  say "The VesselReformation command-line module on the VMTK aorta (MRA, --up auto, 512 x 1024, 500 iterations; the module's"
  say "returned stage times; with opencl the whole view runs on the device, and the log's summary line says where each"
  say "stage ran):"
  say ""
  say "| Backend | Exit | Wall (s) | depth, relax, resample (ms) | backendUsed | Image | max \\|depth - CPU's\\| (mm) | max \\|CPR - CPU's\\| |"
  say "| --- | --- | --- | --- | --- | --- | --- | --- |"
  for backend in cpu opencl auto; do
    begin=$(now)
    run_step "module --backend $backend" "$build/cli-modules/VesselReformation" --up auto --size 512,1024 \
      --backend "$backend" \
      --outputRelaxedDepth "$scratch/aorta-$backend-relaxed.nrrd" --returnparameterfile "$scratch/aorta-$backend.txt" \
      "$aorta/aorta.mha" "$aorta/aorta-centerline.vtp" "$scratch/aorta-$backend-cpr.nrrd"
    status=$?
    wall=$(seconds_since "$begin")
    value() { sed -n "s/^$1 = //p" "$scratch/aorta-$backend.txt" 2>/dev/null; }
    difference="-"
    cpr="-"
    if [[ $backend != cpu && -f $scratch/aorta-$backend-relaxed.nrrd && -f $scratch/aorta-cpu-relaxed.nrrd ]]; then
      difference=$(nrrd_difference "$scratch/aorta-cpu-relaxed.nrrd" "$scratch/aorta-$backend-relaxed.nrrd")
      cpr=$(nrrd_difference "$scratch/aorta-cpu-cpr.nrrd" "$scratch/aorta-$backend-cpr.nrrd")
    fi
    times="$(value depthTime), $(value relaxTime), $(value resampleTime)"
    say "| $backend | $status | $wall | $times | $(value backendUsed) | $(value imageSize) | $difference | $cpr |"
  done
else
  say "The module run on the VMTK aorta was skipped: no data at '${aorta:-(VR_SHARED_DATA_DIR unset)}'."
fi

say ""
say "Whole report: $(seconds_since "$started") s. Every program's output: log.txt."
echo "device-report: $md ($(seconds_since "$started") s; $gtest_failures test program(s) failed)"
