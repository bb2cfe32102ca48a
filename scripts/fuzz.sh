#!/usr/bin/env bash
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Fuzzes the readers with libFuzzer:
#
#   scripts/fuzz.sh READER SECONDS [libFuzzer flags...]   one harness for SECONDS
#   scripts/fuzz.sh all MINUTES [libFuzzer flags...]      every harness in turn, MINUTES in all (shared evenly), then
#                                                        a table and the grown corpora merged into the seeds
#
# READER is one of volume, vtk, vtp, markups, tre, csv, arguments, nifti, nrrd, dicom (Testing/Fuzz/corpus/<READER>/
# holds its seeds, Testing/Fuzz/dictionaries/<READER>.dict its dictionary, passed with -dict=). Give -seed=N among
# the flags for a round that differs from the last. VR_FUZZ_JOBS=N runs N fuzzing processes per harness (-jobs and
# -workers; the default is half the machine's cores, at least 1).
#
# It builds the Clang + ASan + UBSan + libFuzzer build (build-sanitize-clang/, as scripts/test.sh --sanitize) if
# needed, fuzzes from the seed corpus into build-sanitize-clang/fuzz/<READER>/corpus (new inputs land there, the
# seeds stay as they are) and leaves findings as build-sanitize-clang/fuzz/<READER>/{crash,leak,timeout,oom}-*.
# A finding ends with a non-zero status; minimise it (./vrFuzz_<READER> -minimize_crash=1 -runs=10000 crash-...),
# fix the reader, and add the minimised input to Testing/Fuzz/corpus/<READER>/ as crash-<what> with a module test,
# so that every build replays it.
#
# "all" prints one row per harness: executions, coverage (libFuzzer's cov: edges and ft: features at the end),
# the working corpus (files), findings; then merges each working corpus into Testing/Fuzz/corpus/<READER>/ with
# -merge=1 on edge coverage only (-use_counters=0), so that only inputs reaching new code are added (tens, not
# thousands) and CI replays them (Testing/Fuzz/CMakeLists.txt: one test per corpus file). Review and commit them.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 2 ]; then
  echo "usage: scripts/fuzz.sh READER SECONDS [libFuzzer flags...] | scripts/fuzz.sh all MINUTES [flags...]" >&2
  exit 2
fi
what="$1"
amount="$2"
shift 2
readers=(volume vtk vtp markups tre csv arguments nifti nrrd dicom)
if [ "$what" = all ]; then
  selected=("${readers[@]}")
  seconds=$((amount * 60 / ${#readers[@]}))
elif [ -d "Testing/Fuzz/corpus/$what" ]; then
  selected=("$what")
  seconds="$amount"
else
  echo "fuzz.sh: unknown reader $what; use all or one of: ${readers[*]}" >&2
  exit 2
fi
build=build-sanitize-clang
root=$(pwd)
source Testing/Sanitizers/sanitizer-environment.sh
if [ ! -f "$build/build.ninja" ]; then
  launcher=()
  if command -v ccache >/dev/null 2>&1; then
    launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  fi
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DVR_BUILD_FUZZERS=ON -DVR_SANITIZERS=address,undefined -DVR_BUILD_BENCHMARKS=OFF -DCMAKE_C_FLAGS=-g1 \
    -DCMAKE_CXX_FLAGS=-g1 "${launcher[@]}"
fi
# vrReadDicomSeries: the child process the dicom harness reads through.
cmake --build "$build" --target "${selected[@]/#/vrFuzz_}" vrReadDicomSeries
jobs=${VR_FUZZ_JOBS:-$(($(nproc) / 2))}
((jobs >= 1)) || jobs=1

# The flags one harness runs with. Each input is written to a file and read back by the real reader: 64 KiB covers
# every seed. An input that takes more than 10 s or 2 GiB is a finding (a hang, or an allocation a header asked
# for); a DICOM input starts a process, which the reader stops after 10 s itself (vrFuzzDicomSeries.cxx), so there
# libFuzzer's bound is 60 s.
flags_of() {
  local reader="$1" timeout=10
  [ "$reader" = dicom ] && timeout=60
  echo "-max_len=65536 -timeout=$timeout -rss_limit_mb=2048 -malloc_limit_mb=1024 -print_final_stats=1" \
    "-dict=$root/Testing/Fuzz/dictionaries/$reader.dict"
}

# run_one READER SECONDS [flags...]: fuzzes in build-sanitize-clang/fuzz/READER; its output in last-run.log there.
run_one() {
  local reader="$1" time="$2"
  shift 2
  local work="$build/fuzz/$reader"
  mkdir -p "$work/corpus"
  local parallel=()
  if ((jobs > 1)); then
    parallel=(-jobs="$jobs" -workers="$jobs")
  fi
  local show=(cat)
  [ "$what" = all ] || show=(tee /dev/stderr) # one harness: its output on the terminal too
  # shellcheck disable=SC2046 # flags_of's words are separate flags
  (cd "$work" && rm -f fuzz-*.log && "../../bin/vrFuzz_$reader" -max_total_time="$time" $(flags_of "$reader") \
    "${parallel[@]}" "$@" corpus "$root/Testing/Fuzz/corpus/$reader" 2>&1 | "${show[@]}" > last-run.log)
}

if [ "$what" != all ]; then
  work="$build/fuzz/$what"
  status=0
  run_one "$what" "$seconds" "$@" || status=$?
  exit $status
fi

echo "Fuzzing ${#selected[@]} harnesses for $seconds s each ($jobs process(es) each; flags: ${*:-none})"
rows=()
failed=0
for reader in "${selected[@]}"; do
  work="$build/fuzz/$reader"
  mkdir -p "$work"
  before=$(find "$work" -maxdepth 1 \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  start=$(date +%s)
  status=0
  run_one "$reader" "$seconds" "$@" || status=$?
  logs=("$work/last-run.log")
  if ((jobs > 1)); then
    logs=("$work"/fuzz-*.log)
  fi
  after=$(find "$work" -maxdepth 1 \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  findings=$((after - before))
  # libFuzzer's final statistics (summed over the processes) and its last status line (the largest coverage seen).
  executions=$(cat "${logs[@]}" | sed -n 's/^stat::number_of_executed_units: *//p' | awk '{s += $1} END {print s + 0}')
  coverage=$(cat "${logs[@]}" | grep -o 'cov: [0-9]* ft: [0-9]*' | awk '$2 > c {c = $2; f = $4} END {print c + 0 " / " f + 0}')
  corpus=$(find "$work/corpus" -type f | wc -l)
  if ((findings > 0 || status != 0)); then
    failed=1
    echo "$reader: status $status, $findings finding(s) in $work; the end of its log:"
    tail -n 30 "${logs[@]}" | sed 's/^/    /'
  fi
  rows+=("| $reader | $(($(date +%s) - start)) | $executions | $coverage | $corpus | $findings |")
done

echo
echo "| harness | seconds | executions | coverage (cov / ft) | working corpus | findings |"
echo "| --- | ---: | ---: | ---: | ---: | ---: |"
printf '%s\n' "${rows[@]}"

echo
echo "Merging each working corpus into Testing/Fuzz/corpus/<reader>/ (edge coverage only):"
for reader in "${selected[@]}"; do
  work="$build/fuzz/$reader"
  seeds="$root/Testing/Fuzz/corpus/$reader"
  count=$(find "$seeds" -type f | wc -l)
  # shellcheck disable=SC2046
  (cd "$work" && "../../bin/vrFuzz_$reader" -merge=1 -use_counters=0 $(flags_of "$reader") "$seeds" corpus \
    > merge.log 2>&1) || echo "  $reader: the merge failed, see $work/merge.log"
  echo "  $reader: $count seed files, $(($(find "$seeds" -type f | wc -l) - count)) added"
done
exit $failed
