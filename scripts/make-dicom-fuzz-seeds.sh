#!/usr/bin/env bash
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Makes the DICOM fuzz harness's seeds (Testing/Fuzz/corpus/dicom/aorta-crop-*): a 12 x 12 x 3 crop of VMTK's aorta
# around its brightest voxel of slice 17, written as a series by WriteDICOMSeries (ITK's GDCM IO, implicit VR) and
# converted to explicit VR little endian by gdcmconv, packed as vrFuzzDICOMSeries.cxx reads its input (each file a
# 4-byte little-endian length and its bytes). Small on purpose: a few KiB, so that libFuzzer mutates the header.
#
#   scripts/make-dicom-fuzz-seeds.sh [build folder=build]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath "${1:-build}")
data=${VR_SHARED_DATA_DIR:-$here/../Testing/Data}/vmtk-aorta-mra
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$data/aorta.mha" "$work/crop.nrrd" <<'PY'
import array, sys, zlib
raw = open(sys.argv[1], 'rb').read()
start = raw.index(b'ElementDataFile = LOCAL\n') + len(b'ElementDataFile = LOCAL\n')
voxels = array.array('f')
voxels.frombytes(zlib.decompress(raw[start:]))
nx, ny = 157, 393  # DimSize 157 393 34, spacing 0.878906 0.878906 1.50009, direction -1 -1 1, offset -156.445 -24.6094 0
brightest = max(range(nx * ny), key=lambda k: voxels[17 * nx * ny + k])
x0, y0 = brightest % nx - 6, brightest // nx - 6
crop = array.array('f', (voxels[z * nx * ny + y * nx + x] for z in range(16, 19) for y in range(y0, y0 + 12)
                         for x in range(x0, x0 + 12)))
header = (f"NRRD0004\ntype: float\ndimension: 3\nspace: left-posterior-superior\nsizes: 12 12 3\n"
          f"space directions: (-0.878906,0,0) (0,-0.878906,0) (0,0,1.50009)\n"
          f"space origin: ({-156.445 - x0 * 0.878906},{-24.6094 - y0 * 0.878906},{16 * 1.50009})\n"
          f"encoding: raw\nendian: little\n\n")
open(sys.argv[2], 'wb').write(header.encode() + crop.tobytes())
PY
"$build/bin/WriteDICOMSeries" "$work/crop.nrrd" "$work/implicit"
mkdir "$work/explicit"
for file in "$work"/implicit/*.dcm; do
  gdcmconv --explicit "$file" "$work/explicit/$(basename "$file")"
done
python3 - "$work" "$here/Testing/Fuzz/corpus/dicom" <<'PY'
import os, struct, sys
work, corpus = sys.argv[1], sys.argv[2]
def pack(folder, count):
    names = sorted(os.listdir(os.path.join(work, folder)))[:count]
    data = b''
    for name in names:
        content = open(os.path.join(work, folder, name), 'rb').read()
        data += struct.pack('<I', len(content)) + content
    return data
for name, folder, count in (('aorta-crop-explicit-3', 'explicit', 3), ('aorta-crop-implicit-3', 'implicit', 3),
                            ('aorta-crop-explicit-2', 'explicit', 2), ('aorta-crop-one-slice', 'explicit', 1)):
    open(os.path.join(corpus, name), 'wb').write(pack(folder, count))
PY
echo "wrote $here/Testing/Fuzz/corpus/dicom/aorta-crop-*"
