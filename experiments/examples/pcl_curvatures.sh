#!/bin/sh
# Runs build/pcl_curvatures (experiments/examples/pcl_curvatures.cpp) for an `external` method:
#   sh experiments/examples/pcl_curvatures.sh MESH OUT [K]
# from the repository root. Where it is not built (no libpcl-dev when CMake ran), exits 77 with
# one line, and the runner skips the method.
bin="${CURVBENCH_PCL_ADAPTER:-build/pcl_curvatures}"
if [ ! -x "$bin" ]; then
  echo "PCL adapter not built ($bin missing): install libpcl-dev (bash tools/deps.sh pcl), re-run cmake" >&2
  exit 77
fi
exec "$bin" "$@"
