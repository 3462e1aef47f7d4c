#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs (run as root): compilers, OpenCASCADE 7.6,
# CGAL 5.5, pybind11, GoogleTest, pytest, numpy and Dask (cadmedial batch) for /usr/bin/python3,
# FreeCAD 0.20 and Xvfb.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends \
  build-essential cmake \
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-data-exchange-dev \
  libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev \
  pybind11-dev python3-dev python3-numpy python3-pytest \
  python3-dask python3-distributed \
  googletest libgtest-dev \
  freecad python3-pivy xvfb xauth
