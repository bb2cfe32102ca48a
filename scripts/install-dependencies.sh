#!/usr/bin/env bash
# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Installs what VesselReformation needs to build and test on Debian 12 (bookworm), from Debian's packages.
set -euo pipefail

if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO=sudo; else
    echo "install-dependencies.sh: run as root (or install sudo): apt-get needs it" >&2; exit 1
  fi
else
  SUDO=
fi

packages=(
  build-essential cmake ninja-build pkg-config python3
  libinsighttoolkit5-dev libgdcm-tools            # ITK 5.2 (its CMake config wants the GDCM tools present)
  libvtk9-dev                                     # VTK 9.1: polydata IO, FreeType text in figures
  pocl-opencl-icd ocl-icd-opencl-dev opencl-clhpp-headers clinfo   # OpenCL 3.0 on the CPU through PoCL
  libgtest-dev libbenchmark-dev libcli11-dev nlohmann-json3-dev
  libxml2-utils                                   # xmllint: the modules' XML against CTK's schema (a test)
  qtbase5-dev libvtk9-qt-dev                      # the widgets and VesselReformationViewer: Qt 5 Widgets, VTK's Qt support
  xvfb xauth                                      # a virtual X server: the widgets' tests and headless screenshots
  clang libclang-rt-14-dev                        # scripts/test.sh --sanitize and scripts/fuzz.sh: ASan, UBSan, libFuzzer
  python3-dev python3-numpy pybind11-dev          # the Python package vesselreformation (Python/)
  python3-pytest python3-venv python3-setuptools python3-wheel python3-pip   # its tests: pytest, pip into a venv
  snakemake python3-yaml                          # the cohort workflow (workflows/cohort) and its test
)

export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${packages[@]}"
