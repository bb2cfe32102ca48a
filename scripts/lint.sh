#!/usr/bin/env bash
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Runs clang-format (check only) and clang-tidy over the project's sources. Needs a configured build/ (for
# compile_commands.json) and the clang-format / clang-tidy packages.
#
# Debian's ITK 5.2 recognises only GCC in itk_compiler_detection.h; clang-tidy parses the headers as GCC 10 would
# (GCC 10 rather than 12 so that glibc does not use attributes clang lacks).
set -euo pipefail
cd "$(dirname "$0")/.."

# (A git pathspec's * also matches across folders.)
mapfile -t sources < <(git ls-files '*.h' '*.hxx' '*.cxx')

echo "clang-format: ${#sources[@]} files"
clang-format --dry-run --Werror "${sources[@]}"

# Testing/Package is a separate project built by its own test, outside compile_commands.json.
mapfile -t units < <(printf '%s\n' "${sources[@]}" | grep '\.cxx$' | grep -v '^Testing/Package/')
echo "clang-tidy: ${#units[@]} translation units"
status=0
for unit in "${units[@]}"; do
  clang-tidy -p build --quiet --warnings-as-errors='*' \
    --extra-arg=-U__clang__ --extra-arg=-U__GNUC__ --extra-arg=-D__GNUC__=10 \
    --extra-arg=-U__GNUC_MINOR__ --extra-arg=-D__GNUC_MINOR__=2 "$unit" 2>/dev/null || { echo "  in $unit"; status=1; }
done
exit $status
