#!/usr/bin/env bash
# Installs every Debian 12 package libvorocrust, its tools and its tests need. Idempotent: when
# everything is present it changes nothing and contacts no server; otherwise it runs
# `apt-get update` once and installs what is missing. Run as root.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git
  # the library
  libeigen3-dev libnanoflann-dev voro++-dev libopenmesh-dev libtbb-dev
  # the command-line program
  libcli11-dev nlohmann-json3-dev
  # the Exodus II output, and the PNG pictures of report.html (zlib's deflate and CRC)
  libexodusii-dev zlib1g-dev
  # report.html loaded in a real headless browser by its test
  chromium
  # ParaView's readers in the tests: pvpython comes with python3-paraview, whose VTK modules also
  # serve the tests' `import vtk` (Debian lets it replace python3-vtk9, which it conflicts with)
  paraview python3-paraview
  # tests and benchmarks (the CLI tests run under Debian's own python3)
  libgtest-dev libgmock-dev libbenchmark-dev python3
  # the cells' exports checked by the real readers: VTK's Python module (above) and OpenFOAM's
  # checkMesh
  openfoam
  # the tests' independent region volumes (a voxel flood fill)
  python3-scipy
  # a decimal-comma locale (de_DE, compiled by localedef) in which the files must not change
  locales
  # the Python module (pybind11 over Debian's Python 3 and NumPy)
  python3-dev python3-numpy pybind11-dev
  # the FreeCAD workbench and its tests (freecadcmd, and freecad under xvfb-run, below)
  freecad
  # the MeshLab plugin: MeshLab itself, what its headers need (Qt5, GLEW), dpkg-dev for the
  # `apt-get source` of scripts/fetch-meshlab-source.sh, and for meshlabserver's tests a virtual
  # X server with Mesa's software OpenGL
  meshlab qtbase5-dev libqt5opengl5-dev libglew-dev dpkg-dev xvfb xauth libgl1-mesa-dri
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]}; run this script as root" >&2
  exit 1
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"
