#!/usr/bin/env bash
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Fuzzes one reader with libFuzzer for a while:
#
#   scripts/fuzz.sh READER SECONDS [libFuzzer flags...]
#
# READER is one of volume, vtk, vtp, markups, tre, csv, arguments (Testing/Fuzz/corpus/<READER>/ holds its seeds).
# It builds the Clang + ASan + UBSan + libFuzzer build (build-sanitize-clang/, as scripts/test.sh --sanitize) if
# needed, fuzzes from the seed corpus into build-sanitize-clang/fuzz/<READER>/corpus (new inputs land there, the seeds
# stay as they are) and leaves crashes as build-sanitize-clang/fuzz/<READER>/crash-*. A finding ends the run with a
# non-zero status; minimise it (./vrFuzz_<READER> -minimize_crash=1 -runs=10000 crash-...), fix the reader, and add
# the minimised input to Testing/Fuzz/corpus/<READER>/ as crash-<what>, so that every build replays it.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 2 ]; then
  echo "usage: scripts/fuzz.sh READER SECONDS [libFuzzer flags...]" >&2
  exit 2
fi
reader="$1"
seconds="$2"
shift 2
if [ ! -d "Testing/Fuzz/corpus/$reader" ]; then
  echo "fuzz.sh: unknown reader $reader; use one of: $(ls Testing/Fuzz/corpus | tr '\n' ' ')" >&2
  exit 2
fi
build=build-sanitize-clang
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
cmake --build "$build" --target "vrFuzz_$reader"
work="$build/fuzz/$reader"
mkdir -p "$work/corpus"
# Each input is written to a file and read back by the real reader: 64 KiB covers every seed. An input that takes
# more than 10 s or 2 GiB is a finding (a hang or an allocation a header asked for).
cd "$work"
exec "../../bin/vrFuzz_$reader" -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
  -malloc_limit_mb=1024 -print_final_stats=1 "$@" corpus "../../../Testing/Fuzz/corpus/$reader"
