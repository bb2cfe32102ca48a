#!/usr/bin/env bash
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# DICOM mutation campaign (issue 25): writes a real series (VMTK's aorta, 34 slices, with ITK's GDCM IO), makes N
# corrupted copies (1-3 files changed by a few bytes, mostly in the header, 10 % of the changed files also truncated),
# runs VesselReformation on each copy as the volume folder, and prints a table: exit codes, signals, and whether
# every failure's message names a file of the folder. Copies that end with a signal, or fail without naming a file,
# are kept under <work>/kept/ (add them to Testing/Data/Findings/ and a module test).
#
#   scripts/dicom-mutation-campaign.sh [N=1000] [build folder=build] [work folder=/tmp/vr-dicom-campaign] [seed=1]
set -euo pipefail
count=${1:-1000}
build=$(realpath "${2:-build}")
work=${3:-/tmp/vr-dicom-campaign}
seed=${4:-1}
here=$(cd "$(dirname "$0")/.." && pwd)
data=${VR_SHARED_DATA_DIR:-$here/../Testing/Data}/vmtk-aorta-mra
module=$build/cli-modules/VesselReformation
writer=$build/bin/WriteDICOMSeries
for tool in "$module" "$writer"; do
  [[ -x $tool ]] || { echo "missing $tool: cmake --build $build --target VesselReformation WriteDICOMSeries" >&2; exit 2; }
done
rm -rf "$work"
mkdir -p "$work/kept"
# A copy of the module, its library and the DICOM reader process, so that a rebuild of the build folder during a long
# campaign cannot fail runs (a half-linked library reads as "file too short").
frozen=$work/programs
mkdir -p "$frozen/cli-modules" "$frozen/libexec/VesselReformation"
cp "$module" "$build"/cli-modules/libVesselReformationLib.so "$frozen/cli-modules/"
cp "$build/libexec/VesselReformation/vrReadDICOMSeries" "$frozen/libexec/VesselReformation/"
module=$frozen/cli-modules/VesselReformation
export LD_LIBRARY_PATH=$frozen/cli-modules${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
"$writer" "$data/aorta.mha" "$work/series"
centerlines=$data/aorta-centerline.vtp

mutate() { # mutate <seed> <folder>: 1-3 files, a few bytes each (80 % within the first 2 KiB), some truncated
  python3 - "$1" "$2" <<'PY'
import os, random, sys
rng = random.Random(int(sys.argv[1]))
folder = sys.argv[2]
files = sorted(os.listdir(folder))
for name in rng.sample(files, rng.randint(1, 3)):
    path = os.path.join(folder, name)
    data = bytearray(open(path, 'rb').read())
    for _ in range(rng.randint(1, 4)):
        limit = min(len(data), 2048) if rng.random() < 0.8 else len(data)
        at = rng.randrange(limit)
        choice = rng.random()
        if choice < 0.5:
            data[at] = rng.randrange(256)
        elif choice < 0.75:
            data[at] ^= 1 << rng.randrange(8)
        else:
            data[at] = rng.choice([0x00, 0xff, 0x7f, 0x80])
    if rng.random() < 0.1:
        data = data[:rng.randrange(len(data))]
    open(path, 'wb').write(bytes(data))
    print(name)
PY
}

declare -A outcomes
unnamed=0
signals=0
start=$(date +%s)
for ((i = 1; i <= count; i++)); do
  copy=$work/copy
  rm -rf "$copy" && cp -r "$work/series" "$copy"
  changed=$(mutate $((seed * 1000003 + i)) "$copy" | tr '\n' ' ')
  set +e
  timeout 120 "$module" "$copy" "$centerlines" "$work/out.nrrd" > "$work/stdout" 2> "$work/stderr"
  status=$?
  set -e
  rm -f "$work/out.nrrd"
  if ((status > 128 && status != 124)); then
    outcome="signal $((status - 128))"
    signals=$((signals + 1))
    cp -r "$copy" "$work/kept/$i-signal"
  elif ((status == 0)); then
    outcome="read (exit 0)"
  else
    if grep -q "$copy/IM[0-9]*\.dcm" "$work/stderr"; then
      outcome="exit $status, a file named"
    else
      outcome="exit $status, no file named"
      unnamed=$((unnamed + 1))
      cp -r "$copy" "$work/kept/$i-unnamed"
      cp "$work/stderr" "$work/kept/$i-unnamed.stderr"
    fi
    if [[ $(wc -l < "$work/stderr") -ne 1 ]]; then
      outcome="$outcome, more than one stderr line"
      cp "$work/stderr" "$work/kept/$i-lines.stderr"
    fi
  fi
  outcomes[$outcome]=$((${outcomes[$outcome]:-0} + 1))
  echo "$i [$changed] $outcome: $(head -c 300 "$work/stderr" | tr '\n' ' ')" >> "$work/log.txt"
done
elapsed=$(($(date +%s) - start))
echo
echo "DICOM mutation campaign: $count corrupted copies of a $(ls "$work/series" | wc -l)-slice series of VMTK's aorta (seed $seed, ${elapsed} s)"
echo
echo "| outcome | copies |"
echo "| --- | --- |"
for outcome in "${!outcomes[@]}"; do
  echo "| $outcome | ${outcomes[$outcome]} |"
done | sort
echo
echo "signals: $signals; failures naming no file: $unnamed (kept in $work/kept); every run: $work/log.txt"
((signals == 0 && unnamed == 0))
