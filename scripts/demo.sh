#!/usr/bin/env bash
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Installs the dependencies, builds the demo and the viewer, and runs the main job on the built-in phantom. Pictures land
# in ./vessel-reformation-demo/ (or the folder given as the first argument). Then build/bin/VesselReformationViewer opens
# the phantom in a window (see the README).
set -euo pipefail
cd "$(dirname "$0")/.."
output="${1:-vessel-reformation-demo}"

bash scripts/install-dependencies.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --target VesselReformationDemo VesselReformationViewer
./build/bin/VesselReformationDemo --output "$output"
