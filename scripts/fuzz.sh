#!/usr/bin/env bash
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Fuzzes the readers with libFuzzer:
#
#   scripts/fuzz.sh READER SECONDS [libFuzzer flags...]   one harness for SECONDS
#   scripts/fuzz.sh all MINUTES [libFuzzer flags...]      every harness in turn, MINUTES in all (shared evenly), then
#                                                        a table and the grown corpora merged into the seeds
#   scripts/fuzz.sh R1,R2,... MINUTES [flags...]          as all, for the harnesses listed
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
# the working corpus (files), findings; then merges each working corpus into Testing/Fuzz/corpus/<READER>/:
# libFuzzer's -merge=1 (edge coverage, -use_counters=0) runs every input, and of those reaching edges the seeds do
# not, the ones reaching the most new edges are added, at most VR_FUZZ_MERGE_CAP (20) per harness and round, so that
# the committed corpus stays tens of files and CI replays it (Testing/Fuzz/CMakeLists.txt: a test per corpus file).
# They are named fuzz-<SHA-1>: mostly invalid files, unlike the named seeds. Review and commit them.
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
if [ "$what" = all ] || [[ "$what" == *,* ]]; then
  selected=("${readers[@]}")
  if [ "$what" != all ]; then
    IFS=, read -r -a selected <<< "$what"
    for reader in "${selected[@]}"; do
      if [ ! -d "Testing/Fuzz/corpus/$reader" ]; then
        echo "fuzz.sh: unknown reader $reader; use all or some of: ${readers[*]}" >&2
        exit 2
      fi
    done
    what=all # the table and the merge, for the harnesses listed
  fi
  seconds=$((amount * 60 / ${#selected[@]}))
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
# vrReadDICOMSeries: the child process the dicom harness reads through.
cmake --build "$build" --target "${selected[@]/#/vrFuzz_}" vrReadDICOMSeries
jobs=${VR_FUZZ_JOBS:-$(($(nproc) / 2))}
((jobs >= 1)) || jobs=1
cap=${VR_FUZZ_MERGE_CAP:-20}

# The flags one harness runs with. Each input is written to a file and read back by the real reader: 64 KiB covers
# every seed. An input that takes more than 10 s or 2 GiB is a finding (a hang, or an allocation a header asked
# for); a DICOM input starts a process, which the reader stops after 10 s itself (vrFuzzDICOMSeries.cxx), so there
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
  # libFuzzer's final statistics (summed over the processes) and its last status line with the largest coverage.
  executions=$(cat "${logs[@]}" | sed -n 's/^stat::number_of_executed_units: *//p' | awk '{s += $1} END {print s + 0}')
  coverage=$(cat "${logs[@]}" | grep -o 'cov: [0-9]* ft: [0-9]*' | awk '$2 >= c {c = $2; f = $4} END {print c + 0 " / " f + 0}')
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
echo "Merging each working corpus into Testing/Fuzz/corpus/<reader>/ (at most $cap inputs each, by new edges):"
for reader in "${selected[@]}"; do
  work="$build/fuzz/$reader"
  seeds="$root/Testing/Fuzz/corpus/$reader"
  scratch=$(mktemp -d)
  # libFuzzer's merge runs every input once and records the edges each reaches in its control file; the selection
  # below is ours, so that the committed corpus stays small.
  # shellcheck disable=SC2046
  (cd "$work" && "../../bin/vrFuzz_$reader" -merge=1 -use_counters=0 -merge_control_file="$scratch/control" \
    $(flags_of "$reader") "$scratch" "$seeds" corpus > merge.log 2>&1) || echo "  $reader: the merge failed, see $work/merge.log"
  python3 - "$scratch/control" "$seeds" "$work" "$cap" "$reader" <<'PY' || echo "  $reader: no merge (no control file?)"
import hashlib, os, shutil, sys
control, seeds, work, cap, reader = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
lines = open(control).read().split('\n')
count = int(lines[0])
files = lines[2:2 + count]
edges = {}
for line in lines[2 + count:]:
    words = line.split()
    if len(words) >= 2 and words[0] == 'COV':
        edges[int(words[1])] = set(words[2:])
def path(k):
    return files[k] if os.path.isabs(files[k]) else os.path.join(work, files[k])
is_seed = [os.path.dirname(os.path.abspath(path(k))) == os.path.abspath(seeds) for k in range(count)]
covered = set().union(*(edges.get(k, set()) for k in range(count) if is_seed[k]))
candidates = [k for k in range(count) if not is_seed[k] and k in edges]
total = len(set().union(covered, *(edges[k] for k in candidates)) - covered)
added = 0
gained = 0
while added < cap:
    best = max(candidates, default=None, key=lambda k: (len(edges[k] - covered), -os.path.getsize(path(k))))
    if best is None or not edges[best] - covered:
        break
    gained += len(edges[best] - covered)
    covered |= edges[best]
    candidates.remove(best)
    data = open(path(best), 'rb').read()
    shutil.copyfile(path(best), os.path.join(seeds, 'fuzz-' + hashlib.sha1(data).hexdigest()))
    added += 1
print(f"  {reader}: {sum(is_seed)} seed files; {added} added, reaching {gained} of the {total} edges the working "
      f"corpus reaches beyond the seeds")
PY
  rm -rf "$scratch"
done
exit $failed
