#!/usr/bin/env bash
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Installs the dependencies, builds everything, and runs the whole test suite.
#
#   scripts/test.sh                     GCC, Release, everything (build/)
#   scripts/test.sh --sanitize          Clang with AddressSanitizer + UndefinedBehaviorSanitizer (build-sanitize-clang/):
#                                       the whole suite, and the fuzz harnesses built as libFuzzer fuzzers whose
#                                       corpora are replayed as tests
#   scripts/test.sh --sanitize=gcc      the same with GCC (build-sanitize-gcc/); the harnesses get a replay main
#   scripts/test.sh --no-install ...    skip the apt-get step (the packages are there already)
#
# The sanitizer builds leave the benchmarks out (they time nothing under a sanitizer); the Clang one builds the Qt
# widgets and the viewer too, whose tests run without leak detection (Testing/Widgets/CMakeLists.txt says why), the
# GCC one leaves them out (not yet tried there). Both build in
# Release with line tables (-g1) so that reports name files and lines. A leak, an out-of-bounds access or undefined behaviour
# fails the test that caused it: LSan runs at every process exit, UBSan stops at its first finding. The only
# suppressed leaks are third-party ones listed, each with where it comes from, in Testing/Sanitizers/lsan.supp.
set -euo pipefail
cd "$(dirname "$0")/.."

sanitize=""
install=1
for argument in "$@"; do
  case "$argument" in
    --sanitize | --sanitize=clang) sanitize=clang ;;
    --sanitize=gcc) sanitize=gcc ;;
    --no-install) install=0 ;;
    *) echo "test.sh: unknown argument $argument (use --sanitize, --sanitize=gcc, --no-install)" >&2; exit 2 ;;
  esac
done

if [ "$install" = 1 ]; then
  bash scripts/install-dependencies.sh
fi

launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi

if [ -z "$sanitize" ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}"
  cmake --build build
  ctest --test-dir build --output-on-failure --timeout 900 -j "$(nproc)"
  exit 0
fi

build="build-sanitize-$sanitize"
if [ "$sanitize" = clang ]; then
  compilers=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DVR_BUILD_FUZZERS=ON -DVR_BUILD_WIDGETS=ON)
else
  compilers=(-DCMAKE_C_COMPILER=gcc -DCMAKE_CXX_COMPILER=g++ -DVR_BUILD_WIDGETS=OFF)
fi
# The options every sanitized process runs with, for the tests' discovery during the build as for ctest (which
# also sets them per test, see Testing/CMakeLists.txt).
source Testing/Sanitizers/sanitizer-environment.sh
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release "${compilers[@]}" "${launcher[@]}" \
  -DVR_SANITIZERS=address,undefined -DVR_BUILD_BENCHMARKS=OFF -DCMAKE_C_FLAGS=-g1 \
  -DCMAKE_CXX_FLAGS=-g1
start=$(date +%s)
cmake --build "$build"
built=$(date +%s)
ctest --test-dir "$build" --output-on-failure --timeout 1800 -j "$(nproc)"
echo "test.sh --sanitize=$sanitize: build $((built - start)) s, tests $(($(date +%s) - built)) s"
