#!/usr/bin/env bash
# Checks that every Debian package curvbench builds with is installed. As root, installs the
# missing ones with apt-get; otherwise prints the exact apt-get line and fails.
set -euo pipefail
packages=(
  g++ cmake make           # toolchain (OpenMP comes with g++ as libgomp)
  libeigen3-dev            # Eigen 3.4: dense linear algebra
  libcgal-dev              # CGAL 5.5 (header-only): mesh I/O, LSCM, Jet_fitting_3, 2-D Delaunay
  libgmp-dev libmpfr-dev libboost-dev  # CGAL's own dependencies
  libgtest-dev libgmock-dev  # GoogleTest
  libbenchmark-dev         # Google Benchmark
  libcli11-dev             # command line
  gnuplot-nox              # convergence plots (PNG and SVG)
)
missing=()
for p in "${packages[@]}"; do
  if [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" != "install ok installed" ]]; then
    missing+=("$p")
  fi
done
if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi
if [[ "$(id -u)" -eq 0 ]]; then
  echo "deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "deps: missing Debian packages. Run:" >&2
  echo "  sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
