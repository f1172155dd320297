#!/usr/bin/env bash
# ctest install.DownstreamMatchesTheCommandLine: installs the build into a temporary prefix,
# builds examples/downstream against it (shared and static library), runs it on a generated mesh
# and checks its numbers against `curvbench estimate` byte for byte; runs `curvbench recommend`
# and the command it prints from outside the source tree; then imports the installed Python
# module (from PREFIX's site-packages, not the build tree) and checks the same numbers and table.
#   bash tests/install/downstream.sh BUILD_DIR SOURCE_DIR PYTHON
set -euo pipefail
build=$1 src=$2 python=$3
tmp=$(mktemp -d "${TMPDIR:-/tmp}/curvbench_install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix

cmake --install "$build" --prefix "$prefix" > "$tmp/install.log"
test -f "$prefix/include/curvbench/curvbench.h"
# Internal headers are not installed.
test ! -e "$prefix/include/curvbench/version.h" && test ! -e "$prefix/include/core"
ls "$prefix"/lib*/libcurvbench.so "$prefix"/lib*/libcurvbench.a > /dev/null

# The downstream recipe of docs/python.md (the installed C++ library).
cmake -S "$src/examples/downstream" -B "$tmp/ds" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$tmp/configure.log"
cmake --build "$tmp/ds" -j 2 > "$tmp/build.log"

"$prefix/bin/curvbench" mesh --family torus-structured --level 1 --output "$tmp/torus.off" 2> /dev/null
"$prefix/bin/curvbench" estimate "$tmp/torus.off" --method lhf --degree 2 \
  --output "$tmp/ref.csv" 2> /dev/null
cut -d, -f1,5-8 "$tmp/ref.csv" > "$tmp/expected.csv"
for demo in curvature_demo curvature_demo_static; do
  "$tmp/ds/$demo" "$tmp/torus.off" > "$tmp/$demo.csv" 2> /dev/null
  if ! cmp "$tmp/expected.csv" "$tmp/$demo.csv"; then
    echo "FAIL: $demo differs from curvbench estimate" >&2
    diff "$tmp/expected.csv" "$tmp/$demo.csv" | head -5 >&2
    exit 1
  fi
  echo "ok: $demo matches curvbench estimate ($(($(wc -l < "$tmp/$demo.csv") - 1)) vertices)"
done

# `recommend` from a folder outside the source tree reads the installed table
# (PREFIX/share/curvbench), and the command line it prints runs as printed; `--method auto` runs
# the same estimator.
(cd "$tmp" && "$prefix/bin/curvbench" recommend torus.off > recommend.txt)
grep -q "^table:      $prefix/share/curvbench/recommendations.csv, curvbench " "$tmp/recommend.txt"
command=$(sed -n 's/^run:        //p' "$tmp/recommend.txt")
test "${command#"$prefix/bin/curvbench estimate torus.off --method "}" != "$command"
(cd "$tmp" && eval "$command" 2> /dev/null)
test "$(wc -l < "$tmp/torus.curvatures.csv")" -eq "$(wc -l < "$tmp/ref.csv")"
(cd "$tmp" && "$prefix/bin/curvbench" estimate torus.off --method auto --output auto.csv 2> /dev/null)
cmp "$tmp/auto.csv" "$tmp/torus.curvatures.csv"
echo "ok: installed recommend's command runs as printed: $command"

# The installed Python module, run from PREFIX's site-packages with the build tree out of reach.
site=$(ls -d "$prefix"/lib/python3*/site-packages)
ls "$site"/curvbench*.so > /dev/null
(cd "$tmp" && env -u PYTHONPATH PYTHONPATH="$site" "$python" - "$tmp/torus.off" "$tmp/ref.csv" "$site" "$prefix" <<'PY'
import csv, sys
import numpy as np
import curvbench
mesh, ref, site, prefix = sys.argv[1:5]
assert curvbench.__file__.startswith(site), curvbench.__file__
V, F = curvbench.read_mesh(mesh)
r = curvbench.estimate(V, F, method="lhf", degree=2)
rows = list(csv.DictReader(open(ref)))
for q in ("k1", "k2", "H", "K"):
    want = np.array([float(row[q]) for row in rows])
    assert np.array_equal(getattr(r, q), want, equal_nan=True), q
table = prefix + "/share/curvbench/recommendations.csv"
assert curvbench.estimate(V, F, method="auto").recommendation["table"] == table
print("ok: installed Python module", curvbench.__version__, "matches curvbench estimate")
PY
)
