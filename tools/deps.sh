#!/usr/bin/env bash
# Checks that every Debian package curvbench builds with is installed. As root, installs the
# missing ones with apt-get; otherwise prints the exact apt-get line and fails.
#
#   bash tools/deps.sh          what make build/test/experiments/bench/test-sanitize need
#   bash tools/deps.sh fuzz     the same plus clang and libFuzzer (make fuzz)
#   bash tools/deps.sh slurm    the same plus Slurm and MUNGE (make test-slurm)
#   bash tools/deps.sh pcl      the same plus PCL (the optional PCL adapter, build/pcl_curvatures)
set -euo pipefail
mode="${1:-build}"
packages=(
  g++ cmake make           # toolchain (g++ brings libgomp for OpenMP, libasan/libubsan)
  libeigen3-dev            # Eigen 3.4: dense linear algebra
  libcgal-dev              # CGAL 5.5 (header-only): mesh I/O, LSCM, Jet_fitting_3, 2-D Delaunay
  libgmp-dev libmpfr-dev libboost-dev  # CGAL's own dependencies
  libgtest-dev libgmock-dev  # GoogleTest
  libbenchmark-dev         # Google Benchmark
  libcli11-dev             # command line
  libhwy-dev               # Google Highway: SIMD with run-time dispatch (batched fitting kernels)
  libnanoflann-dev         # nanoflann, header-only: k-d tree neighbour search of point sets (points/)
  libfmt-dev               # {fmt} 9, header-only: shortest round-trip digits for the estimate CSV
  pybind11-dev python3-dev python3-numpy python3-pytest  # Python module (for /usr/bin/python3);
                           # numpy also runs the outside-estimator examples (experiments/examples/)
  python3-vtk9             # VTK for /usr/bin/python3: the vtk-curvatures method of the field
                           # study (experiments/examples/vtk_curvatures.py; skipped without it)
  gnuplot-nox              # convergence plots (PNG and SVG)
  libjs-chart.js           # the results site's charts (copied into results/site/, no CDN)
  chromium chromium-driver python3-selenium  # the results site's browser test (ctest site.*)
  time                     # /usr/bin/time -v: peak memory in make bench
)
case "$mode" in
  build) ;;
  fuzz)
    # clang (clang-14 on Debian 12) only recommends its runtime libraries; libFuzzer
    # (libclang_rt.fuzzer) and the clang sanitizer runtimes are in libclang-rt-dev.
    packages+=(clang libclang-rt-dev)
    ;;
  slurm)
    # slurm-wlm: slurmctld, slurmd and the client commands (sbatch, sinfo, squeue, scontrol);
    # it depends on munge, the authentication daemon.
    packages+=(slurm-wlm munge)
    ;;
  pcl)
    # libpcl-dev: PCL 1.13, the outside estimator experiments/examples/pcl_curvatures.cpp
    # (optional: it pulls in about 338 packages, VTK and Qt among them)
    packages+=(libpcl-dev)
    ;;
  *)
    echo "usage: bash tools/deps.sh [build|fuzz|slurm|pcl]" >&2
    exit 2
    ;;
esac
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
