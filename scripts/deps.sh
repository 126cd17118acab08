#!/usr/bin/env bash
# Installs the Debian 12 packages radx needs, only those missing (safe to run again).
# Build: cmake, ninja, g++, Eigen, SuiteSparse (CHOLMOD), HDF5, METIS, Catch2, and Open MPI for radx-engine-mpi and
# mpirun (docs/parallel.md; the other executables do not link it). Tests: hdf5-tools, h5py, and
# ParaView's pvpython (python3-paraview), which the tests use to open the files as a user would. Runs:
# python3-matplotlib, with which the engine draws NAME_energy.png (io/listing/energy_plot.hpp). Fuzzing and the clang
# UBSan build: clang, its sanitizer and libFuzzer runtimes (libclang-rt-dev) and its OpenMP (libomp-dev). The
# time-history kill test: strace, which kills the engine at a chosen write. ParaView screenshots in the tests: xvfb
# and xauth, for xvfb-run (Debian's pvpython crashes with --force-offscreen-rendering, so it renders on a virtual
# X display). The packaging test (cpack -G DEB): dpkg-dev (dpkg-shlibdeps computes the package's dependencies).
# `deps.sh run` installs only what building the executables and running them needs (the README's first
# command): no test, fuzzing or packaging tools. Catch2 stays in that set: the configuration, the same for
# both commands, looks for it.
# Usage: scripts/deps.sh [run]
set -euo pipefail
packages=(cmake ninja-build g++ libeigen3-dev libsuitesparse-dev libhdf5-dev libmetis-dev catch2 python3-matplotlib git
          libopenmpi-dev openmpi-bin)
if [[ "${1:-}" != run ]]; then
  packages+=(hdf5-tools python3-h5py python3-numpy python3-paraview clang-format clang libclang-rt-dev libomp-dev
             strace dpkg-dev xvfb xauth)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "radx: installing Debian packages: ${missing[*]}"
  if [[ $(id -u) -ne 0 ]]; then
    echo "radx: installing packages needs root (run as root, or: sudo apt-get install ${missing[*]})" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
